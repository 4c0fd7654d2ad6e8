// One wall-contact evaluation (model/wall_contact.hpp) as the assembly calls it: a contact circle
// at every node of a 30 m string (10 bodies × 11 nodes, default settings: 10 elements, 6 modes,
// 18 velocities per body) in a build-and-turn hole, every contact loaded and sliding with
// friction. The element states are prepared once (their construction belongs to the assembly).
// Run: build/bench/wall_contact_bench   (items_per_second = contact evaluations per second)
#include <benchmark/benchmark.h>

#include <memory>
#include <random>
#include <vector>

#include "cms/reduction_cache.hpp"
#include "model/builder.hpp"
#include "model/wall_contact.hpp"

namespace {

using namespace drillflex;
using namespace drillflex::model;

struct Setup {
  std::unique_ptr<BuiltModel> built;
  std::vector<std::unique_ptr<WallContactElement>> contacts;
  std::vector<BodyPose> poses;
  std::vector<ElementState> states;
};

const Setup& TheSetup(bool prescribed) {
  static Setup setups[2];
  Setup& s = setups[prescribed ? 1 : 0];
  if (s.built) return s;
  std::vector<well::SurveyStation> stations{{0.0, 0.0, 0.0}, {100.0, 20.0 * kDegree, 10.0 * kDegree},
                                            {160.0, 50.0 * kDegree, 40.0 * kDegree}, {400.0, 50.0 * kDegree, 40.0 * kDegree}};
  auto wellbore = std::make_shared<const Wellbore>(Wellbore{well::Trajectory(stations), well::HoleProfile({{{}, 0.2, {}}})});
  ModelInput input;
  Component pipe;
  pipe.outer_diameter = 0.127;
  pipe.inner_diameter = 0.1086;
  pipe.length = 30.0;
  input.string.components.push_back(pipe);
  input.materials["steel"] = fe::Material{"steel", 2.1e11, 0.3, 7850.0};
  input.well = MakeWellbore(wellbore->trajectory);  // the path alone: no hole, no contact
  input.bit_md = 150.0;
  cms::ReductionCache cache;
  s.built = std::make_unique<BuiltModel>(BuildSystemModel(input, cache));
  const SystemModel& model = s.built->system;
  WallContactParameters p;
  p.contact_radius = 0.0635;
  p.normal_stiffness = 1e8;
  p.normal_damping = 1e3;
  p.axial_friction = 0.3;
  p.tangential_friction = 0.25;
  p.regularization_velocity = 1e-3;
  if (prescribed) p.prescribed_sliding = PrescribedSliding{0.5, 10.0};
  // Every body pushed 0.055 m toward the low side (clearance 0.0365 m, chord sagitta 0.01 m) and moving.
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  VecX dv = VecX::Zero(model.num_velocities());
  VecX v = VecX::Zero(model.num_velocities());
  for (const Body& body : model.bodies()) {
    dv.segment<3>(body.v_offset) = body.reference_orientation.toRotationMatrix() * Vec3(0.0, 0.0, -0.055);
    for (int j = 0; j < body.velocity_count(); ++j) v[body.v_offset + j] = 0.3 * u(rng);
  }
  s.poses = model.Poses(model.Increment(model.ReferencePositions(), dv));
  for (const Body& body : model.bodies()) {
    for (int k = 0; k < body.node_count(); ++k) {
      const double md = input.bit_md - body.s_start - body.reduced->node_positions[k].x();
      s.contacts.push_back(std::make_unique<WallContactElement>(&body, k, wellbore, p, md));
      s.states.push_back(model.StateOf(*s.contacts.back(), s.poses, v, 0.0, 1.0));
    }
  }
  return s;
}

void Evaluate(benchmark::State& state, bool with_matrices, bool prescribed) {
  const Setup& s = TheSetup(prescribed);
  ElementContribution out;
  std::size_t i = 0;
  for (auto _ : state) {
    s.contacts[i]->Evaluate(s.states[i], with_matrices, out);
    benchmark::DoNotOptimize(out.force.data());
    if (++i == s.contacts.size()) i = 0;
  }
  state.SetItemsProcessed(state.iterations());
  int active = 0;
  for (std::size_t c = 0; c < s.contacts.size(); ++c) active += s.contacts[c]->Result(s.states[c]).in_contact ? 1 : 0;
  state.counters["active_fraction"] = static_cast<double>(active) / static_cast<double>(s.contacts.size());
}

void BM_ContactWithMatrices(benchmark::State& state) { Evaluate(state, true, false); }
void BM_ContactForceOnly(benchmark::State& state) { Evaluate(state, false, false); }
void BM_ContactPrescribedSlidingWithMatrices(benchmark::State& state) { Evaluate(state, true, true); }

void BM_ContactResult(benchmark::State& state) {
  const Setup& s = TheSetup(false);
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(s.contacts[i]->Result(s.states[i]).normal_force);
    if (++i == s.contacts.size()) i = 0;
  }
  state.SetItemsProcessed(state.iterations());
}

// The node-force mapping alone (model/node_force.hpp) for a force at a point off the node, with
// random derivatives: the share of the matrices in a contact evaluation.
void BM_AddPointForce(benchmark::State& state) {
  const Setup& s = TheSetup(false);
  const Body& body = *s.contacts[5]->bodies()[0];
  const NodeMotion motion = ComputeNodeMotion(body, *s.states[5].poses[0], 5, s.states[5].velocity);
  PointForceJacobian J;
  J.force_position = Mat3::Random();
  J.force_velocity = Mat3::Random();
  J.force_angular_velocity = Mat3::Random();
  J.lever_position = Mat3::Random();
  ElementContribution out;
  const int n = body.velocity_count();
  out.force = VecX::Zero(n);
  out.stiffness = MatX::Zero(n, n);
  out.damping = MatX::Zero(n, n);
  for (auto _ : state) {
    AddPointForce(body, *s.states[5].poses[0], 5, motion, Vec3(1.0, 2.0, 3.0), Vec3(0.01, 0.02, 0.03), &J, true, out);
    benchmark::DoNotOptimize(out.stiffness.data());
  }
  state.SetItemsProcessed(state.iterations());
}

BENCHMARK(BM_ContactWithMatrices);
BENCHMARK(BM_AddPointForce);
BENCHMARK(BM_ContactForceOnly);
BENCHMARK(BM_ContactPrescribedSlidingWithMatrices);
BENCHMARK(BM_ContactResult);

}  // namespace

BENCHMARK_MAIN();
