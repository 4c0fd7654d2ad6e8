// Model-layer cost (never a timed test): build in Release and run by hand,
//   build/bench/model_bench [--benchmark_filter=String1000]
// Goals: the V1 cantilever (4 bodies × 10 elements, 6 modes a body) builds, solves statically and
// gives 10 modes in under 10 ms each; a 3 km string of 5 in drill pipe (1000 bodies) solves
// statically and gives its 20 lowest modes in under 2 s each, in under 1 GB.
// peak_MB is the process's peak resident size so far (getrusage): run one filter at a time to
// attribute it to one case.
// Reference values in the counters: V1 tip 1000 N: FL³/3EI = 0.1257 m; string: taut-string
// frequencies f_n = (n / 2L) √(T/μ) = 0.01442 n Hz (each twice: y and z), stretch TL/EA = 0.839 m.
// Measured (2 shared cores, CPU time): V1 build 0.16 ms, static 0.55 ms, 10 modes 0.65 ms; string
// build 26 ms, static 0.47 s (8 Newton iterations), 110 MB; 20 modes 16.5 s, all of it in the
// Lanczos solver: its pole σ = shift − 1e-9 max K_ii/M_ii (solvers/eigen_lanczos.cpp) is −980 here,
// far below the wanted ω² = 0.008…0.8, so ν = 1/(ω² − σ) are clustered (2034 operator
// applications; 53 with σ = 0).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <optional>

#include "bench_support.hpp"
#include "fe/material.hpp"
#include "model/body_inertia_jacobian.hpp"
#include "model/builder.hpp"
#include "model/static_problem.hpp"
#include "solvers/eigen.hpp"
#include "solvers/newton.hpp"

namespace {

using namespace drillflex;
using bench::PeakMemoryMb;

void ReportMemory(benchmark::State& state) { state.counters["peak_MB"] = PeakMemoryMb(); }

// The V1 rod (validation.md): solid, D = 3 in, L = 200 in, steel-like E = 2.1e11 Pa, ρ = 7800 kg/m³,
// clamped at s = 0, the paper's model (4 bodies × 10 elements, 6 modes a body), a lateral tip load.
model::ModelInput CantileverInput() {
  model::ModelInput input;
  model::Component rod;
  rod.outer_diameter = 0.0762;
  rod.length = 5.08;
  rod.material = "rod";
  input.string.components.push_back(rod);
  input.materials["rod"] = fe::Material{"rod", 2.1e11, 0.3, 7800.0};
  input.settings.body_length = 5.08 / 4 + 1e-9;
  input.settings.elements_per_body = 10;
  input.settings.modes_per_body = 6;
  model::Support root;
  root.fixed.fill(true);
  input.supports = {root};
  model::Load tip;
  tip.at = 5.08;
  tip.force = Vec3(0.0, 1000.0, 0.0);
  input.loads = {tip};
  return input;
}

// 3 km of 5 in drill pipe (OD 0.127 m, ID 0.1086 m, steel) in 3 m bodies of 10 elements and 6 modes:
// pinned at s = 0 (x, y, z, torsion), held laterally at the top, 200 kN tension at the top and a
// lateral line load of 1 N/m along the whole string.
model::ModelInput StringInput() {
  model::ModelInput input;
  model::Component pipe;
  pipe.type = model::ComponentType::Pipe;
  pipe.outer_diameter = 0.127;
  pipe.inner_diameter = 0.1086;
  pipe.length = 3000.0;
  pipe.material = "steel";
  input.string.components.push_back(pipe);
  input.materials["steel"] = fe::Steel();
  input.settings.body_length = 3.0;
  input.settings.elements_per_body = 10;
  input.settings.modes_per_body = 6;
  model::Support bottom;
  bottom.fixed = {true, true, true, true, false, false};
  model::Support top;
  top.at = 3000.0;
  top.fixed = {false, true, true, false, false, false};
  input.supports = {bottom, top};
  model::Load tension;
  tension.at = 3000.0;
  tension.force = Vec3(200e3, 0.0, 0.0);
  model::Load lateral;
  lateral.distributed = true;
  lateral.from = 0.0;
  lateral.to = 3000.0;
  lateral.force_per_length = Vec3(0.0, 1.0, 0.0);
  input.loads = {tension, lateral};
  return input;
}

// The Newton settings recommended for this model (notes/model-orientation.md).
solvers::NewtonOptions ModelNewtonOptions() {
  solvers::NewtonOptions options;
  options.increment_tolerance = 1e-10;
  options.line_search.enabled = false;
  return options;
}

model::BuiltModel Build(const model::ModelInput& input) {
  cms::ReductionCache cache;
  return model::BuildSystemModel(input, cache);
}

solvers::NewtonResult SolveStatic(const model::SystemModel& system) {
  model::StaticModelProblem problem(system);
  return solvers::SolveStatic(problem, system.ReferencePositions(), ModelNewtonOptions());
}

// The lowest modes about q: symmetric part of the tangent stiffness (dead loads make it slightly
// unsymmetric) with the mass matrix.
solvers::ModalResult Modes(const model::SystemModel& system, const VecX& q, int count) {
  const VecX zero = VecX::Zero(system.num_velocities());
  const SparseMat tangent = system.IterationMatrix(0.0, q, zero, zero, 1.0, 1.0, 0.0, 0.0);
  const SparseMat stiffness = 0.5 * (tangent + SparseMat(tangent.transpose()));
  return solvers::SolveModes(stiffness, system.MassMatrix(q), count);
}

void BuildBenchmark(benchmark::State& state, const model::ModelInput& input) {
  int velocities = 0;
  for (auto _ : state) {
    const model::BuiltModel built = Build(input);  // a fresh cache: the reduction runs every time
    velocities = built.system.num_velocities();
    benchmark::DoNotOptimize(velocities);
  }
  state.counters["dofs"] = velocities;
  ReportMemory(state);
}

// The static solve. A single load factor scales every load, and at the straight, unstressed start
// the long string has next to no lateral stiffness (bending only: 1 N/m would deflect it ~1e6 m),
// so the lateral load cannot go on together with the tension that stiffens it. Where `prestress`
// is given (the same string with its axial loads only) it is solved first, and the full model
// then by Newton at full load from that stretched state.
solvers::NewtonResult SolveStaged(const model::SystemModel& system, const model::SystemModel* prestress) {
  if (prestress == nullptr) return SolveStatic(system);
  const solvers::NewtonResult stretched = SolveStatic(*prestress);
  model::StaticModelProblem problem(system);
  solvers::NewtonOptions options = ModelNewtonOptions();
  options.load_stepping.enabled = false;
  solvers::NewtonResult result = solvers::SolveStatic(problem, stretched.q, options);
  result.iterations += stretched.iterations;
  return result;
}

// Sanity counters of a static result: the top node's axial displacement and the largest lateral
// (y) node displacement. References: V1 tip 1000 N: y = FL³/3EI = 0.126 m (linear); string:
// stretch TL/EA = 0.839 m, mid-span sag of a taut string qL²/8T = 5.63 m.
void ReportDeflection(benchmark::State& state, const model::SystemModel& system, const VecX& q) {
  const auto poses = system.Poses(q);
  double largest_y = 0.0;
  for (std::size_t b = 0; b < poses.size(); ++b) {
    const model::Body& body = system.bodies()[b];
    for (int k = 0; k < body.node_count(); ++k) {
      largest_y = std::max(largest_y, std::abs(poses[b].NodePosition(body, k).y()));
    }
  }
  const model::Body& top = system.bodies().back();
  state.counters["top_dx_m"] = poses.back().NodePosition(top, top.node_count() - 1).x() - system.length();
  state.counters["max_dy_m"] = largest_y;
}

void StaticBenchmark(benchmark::State& state, const model::ModelInput& input,
                     const std::optional<model::ModelInput>& prestress_input = std::nullopt) {
  const model::BuiltModel built = Build(input);
  std::optional<model::BuiltModel> prestress;
  if (prestress_input) prestress.emplace(Build(*prestress_input));
  solvers::NewtonResult result;
  for (auto _ : state) {
    result = SolveStaged(built.system, prestress ? &prestress->system : nullptr);
    benchmark::DoNotOptimize(result.q.data());
  }
  state.counters["newton_iterations"] = result.iterations;
  state.counters["residual_N"] = result.residual_norm;
  ReportDeflection(state, built.system, result.q);
  ReportMemory(state);
}

void ModesBenchmark(benchmark::State& state, const model::ModelInput& input, int count,
                    const std::optional<model::ModelInput>& prestress_input = std::nullopt) {
  const model::BuiltModel built = Build(input);
  std::optional<model::BuiltModel> prestress;
  if (prestress_input) prestress.emplace(Build(*prestress_input));
  // Modes about the loaded equilibrium.
  const VecX q = SolveStaged(built.system, prestress ? &prestress->system : nullptr).q;
  solvers::ModalResult modes;
  for (auto _ : state) {
    modes = Modes(built.system, q, count);
    benchmark::DoNotOptimize(modes.eigenvalues.data());
  }
  const VecX hz = solvers::FrequenciesHz(modes.eigenvalues);
  state.counters["f1_Hz"] = hz[0];
  state.counters["f_last_Hz"] = hz[hz.size() - 1];
  ReportMemory(state);
}

void BM_V1_Build(benchmark::State& state) { BuildBenchmark(state, CantileverInput()); }
void BM_V1_Static(benchmark::State& state) { StaticBenchmark(state, CantileverInput()); }
void BM_V1_Modes10(benchmark::State& state) { ModesBenchmark(state, CantileverInput(), 10); }
BENCHMARK(BM_V1_Build)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_V1_Static)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_V1_Modes10)->Unit(benchmark::kMillisecond);

void BM_String1000_Build(benchmark::State& state) { BuildBenchmark(state, StringInput()); }
// The string with its tension only (the prestress stage of the static solve).
model::ModelInput StringTensionOnly() {
  model::ModelInput input = StringInput();
  input.loads.resize(1);
  return input;
}

void BM_String1000_Static(benchmark::State& state) { StaticBenchmark(state, StringInput(), StringTensionOnly()); }
void BM_String1000_Modes20(benchmark::State& state) {
  ModesBenchmark(state, StringInput(), 20, StringTensionOnly());
}
BENCHMARK(BM_String1000_Build)->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(BM_String1000_Static)->Unit(benchmark::kMillisecond)->Iterations(2);
BENCHMARK(BM_String1000_Modes20)->Unit(benchmark::kMillisecond)->Iterations(1);

// The model's share of the modal analysis: K (symmetrized) and M at the loaded equilibrium.
void BM_String1000_ModalMatrices(benchmark::State& state) {
  const model::BuiltModel built = Build(StringInput());
  const model::BuiltModel prestress = Build(StringTensionOnly());
  const VecX q = SolveStaged(built.system, &prestress.system).q;
  const VecX zero = VecX::Zero(built.system.num_velocities());
  for (auto _ : state) {
    const SparseMat tangent = built.system.IterationMatrix(0.0, q, zero, zero, 1.0, 1.0, 0.0, 0.0);
    const SparseMat stiffness = 0.5 * (tangent + SparseMat(tangent.transpose()));
    const SparseMat mass = built.system.MassMatrix(q);
    benchmark::DoNotOptimize(stiffness.valuePtr());
    benchmark::DoNotOptimize(mass.valuePtr());
  }
  ReportMemory(state);
}
BENCHMARK(BM_String1000_ModalMatrices)->Unit(benchmark::kMillisecond);

// A moving state of the string: small deformation, spin, whirl, modal rates and accelerations.
struct MovingState {
  VecX q, v, a;
};

MovingState MakeMovingState(const model::SystemModel& system) {
  MovingState s;
  s.v = VecX::Random(system.num_velocities());
  s.a = 10.0 * VecX::Random(system.num_velocities());
  s.q = system.Increment(system.ReferencePositions(), 1e-3 * VecX::Random(system.num_velocities()));
  return s;
}

// K_in + D_in of every body (the inertia terms alone), body blocks into one dense buffer per body.
void BM_String1000_InertiaMatrices(benchmark::State& state) {
  const model::BuiltModel built = Build(StringInput());
  const model::SystemModel& system = built.system;
  const MovingState s = MakeMovingState(system);
  const auto poses = system.Poses(s.q);
  for (auto _ : state) {
    for (std::size_t b = 0; b < system.bodies().size(); ++b) {
      const model::Body& body = system.bodies()[b];
      const int n = body.velocity_count();
      MatX local = MatX::Zero(n, n);
      model::AddInertiaMatrices(body, poses[b], s.v.segment(body.v_offset, n), s.a.segment(body.v_offset, n), 1.0,
                                1.0, 0.0, local);
      benchmark::DoNotOptimize(local.data());
    }
  }
  ReportMemory(state);
}
BENCHMARK(BM_String1000_InertiaMatrices)->Unit(benchmark::kMillisecond);

// The whole sparse iteration matrix cK K + cD D + cM M at a moving state (a dynamic step) and at
// rest (a Newton iteration), and the residual.
void BM_String1000_IterationMatrix(benchmark::State& state) {
  const model::BuiltModel built = Build(StringInput());
  const model::SystemModel& system = built.system;
  MovingState s = MakeMovingState(system);
  if (state.range(0) == 0) {
    s.v.setZero();
    s.a.setZero();
  }
  for (auto _ : state) {
    const SparseMat matrix = system.IterationMatrix(0.0, s.q, s.v, s.a, 1.0, 1.0, 0.5, 0.25);
    benchmark::DoNotOptimize(matrix.valuePtr());
  }
  ReportMemory(state);
}
BENCHMARK(BM_String1000_IterationMatrix)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

void BM_String1000_Residual(benchmark::State& state) {
  const model::BuiltModel built = Build(StringInput());
  const model::SystemModel& system = built.system;
  const MovingState s = MakeMovingState(system);
  for (auto _ : state) {
    const VecX residual = system.Residual(0.0, s.q, s.v, s.a, 1.0);
    benchmark::DoNotOptimize(residual.data());
  }
  ReportMemory(state);
}
BENCHMARK(BM_String1000_Residual)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
