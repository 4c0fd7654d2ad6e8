// The linear system behind the vibration sweep (analyses/vibration_analysis.hpp) and the two ways
// of solving it at a frequency ω (rad/s):
//   (K (1 + 2iζ_s) − ω² M(ω) + iω D(ω)) X = F,
// K, M (steel and bore fluid) and D = ∂R/∂v of analyses/linearization.hpp Linearize; the annulus added mass
// and damping of each group of nodes with one rod and hole radius, C_m(ω) U_g and C_v(ω) ω U_g
// (model/lateral_fluid.hpp); the structural damping ratio ζ_s as a loss factor 2ζ_s on K
// (hysteretic: iω (2ζ_s/ω) K, so every mode gets ζ_s at its resonance; the modal damping of the
// bodies' fixed-interface modes alone reaches the string's low modes only weakly, e.g. ζ ≈ 2e-4
// for ζ_s = 0.01 in V5's collar).
//  * direct: solvers::HarmonicSolver, a sparse LU of the full matrix per frequency;
//  * modal: solvers::ProjectedHarmonicSolver on the modes of K φ = ω² M_ref φ up to a cutoff and
//    one static correction per load pattern. M_ref holds the annulus at C_m of a reference
//    frequency (the geometric mean of the sweep's lowest and highest excitation frequencies);
//    the projected system takes every frequency's own C_m(ω), C_v(ω), so the basis only has to
//    span the response, not diagonalize it.
#pragma once

#include <memory>
#include <utility>
#include <vector>

#include "core/types.hpp"
#include "model/lateral_fluid.hpp"
#include "model/system_model.hpp"
#include "solvers/harmonic.hpp"
#include "solvers/projected_harmonic.hpp"

namespace drillflex::analyses {

struct SweepSystem {
  solvers::LinearSystem system;   // K, M (steel and bore fluid), D
  std::vector<SparseMat> terms;   // U_g of each annulus group, then K (the hysteretic term) last
  std::vector<std::pair<double, double>> annulus_radii;  // (rod, hole) radius of each group, m
  const model::LateralFluid* fluid = nullptr;             // null without annulus groups
  double loss_factor = 0.0;       // 2ζ_s
  solvers::HarmonicOptions options;  // the bodies' blocks (the direct solve's block LU)
};

SweepSystem AssembleSweepSystem(const model::SystemModel& model, const model::LateralFluid& fluid, const VecX& q);

// The coefficient pair of each term at ω: (C_m, C_v ω) of each group, (0, 2ζ_s/ω) of K.
std::vector<solvers::FrequencyTermCoefficients> SweepTermCoefficients(const SweepSystem& sweep, double frequency);

// The mass of the modal basis: M + Σ_g C_m,g(ω_ref) U_g.
SparseMat ReferenceMass(const SweepSystem& sweep, double reference_frequency);

// Solves at one frequency; one object per thread (the direct solver holds its factorization, the
// modal one shares the projected matrices).
class ResponseSolver {
 public:
  // Direct: a HarmonicSolver of its own.
  explicit ResponseSolver(std::shared_ptr<const SweepSystem> sweep);
  // Modal: the shared projection.
  ResponseSolver(std::shared_ptr<const SweepSystem> sweep, std::shared_ptr<const solvers::ProjectedHarmonicSolver> modal);

  solvers::ComplexMat Solve(double frequency, const solvers::ComplexMat& loads);

 private:
  std::shared_ptr<const SweepSystem> sweep_;
  std::unique_ptr<solvers::HarmonicSolver> direct_;
  std::shared_ptr<const solvers::ProjectedHarmonicSolver> modal_;
};

}  // namespace drillflex::analyses
