// Modes of the spinning string and its Campbell diagram (method.md §9.2, "Gyroscopic modes").
//
// About the static equilibrium q (the same linearization as modes_analysis.hpp: K, M with the
// fluid, D), the string's material spins at Ω about its own axis while the frames stay: the
// gyroscopic matrix G of model/gyroscopic_element.hpp enters the velocity term,
//   M ẍ + (D + Ω G) ẋ + K x = 0,   x = Re(φ e^{st}),
// a quadratic eigenproblem whose state-space matrix is not symmetric. It is solved on the lowest
// undamped modes Φ of (K, M_ref) (solvers::SolveModes: dense or shift-invert Lanczos, M_ref with
// the annulus at its inviscid C_m): the r × r projected problem (ΦᵀKΦ, Φᵀ(D + ΩG)Φ, ΦᵀMΦ) in the
// dense state-space form of solvers::SolveDampedModes. G couples the two bending planes of each
// lateral mode (the forward and backward whirl of one shape), so a basis of the 2·count + 10 lowest
// modes (plus as many again as are near zero or of negative stiffness) holds the couplings that
// matter; the validation compares it with the full state-space solve.
//
// Each mode: frequency_hz = Im s / 2π (the whirl frequency), damping_ratio = ζ_s − Re s/|s| (the
// structural loss factor added as in modes_analysis.hpp), its kind by the kinetic-energy split of
// its real and imaginary parts, and its whirl (ModeResult::whirl) against the spin. A viscous
// fluid's C_m(ω), C_v(ω) are taken at each mode's own frequency by a fixed point (the projected
// problem re-solved at the mode's ω, keeping the mode whose shape is most like the previous one). Modes below
// kNearZeroFrequencyHz and real eigenvalues (negative stiffness, overdamped) are left out.
//
// The equilibrium, and with it the contact and friction tangent, is the one at operation.rpm: a
// Campbell diagram varies only Ω in Ω G.
#pragma once

#include <memory>
#include <vector>

#include "analyses/analysis_settings.hpp"
#include "analyses/modes_analysis.hpp"
#include "core/types.hpp"
#include "model/lateral_fluid.hpp"
#include "model/system_model.hpp"

namespace drillflex::analyses {

// A crossing of a Campbell branch with the 1× line f = Ω/2π: a rotary speed at which an imbalance
// (1×, forward) meets that mode.
struct CampbellCrossing {
  double rotary_speed = 0.0;  // rad/s
  double frequency_hz = 0.0;
  Index branch = 0;             // the mode's rank by frequency (0: the lowest)
  Whirl whirl = Whirl::None;  // of the branch at the nearer sweep point
};

struct CampbellPoint {
  double rotary_speed = 0.0;     // rad/s
  std::vector<ModeResult> modes;  // without vectors and shapes
};

struct CampbellResult {
  std::vector<CampbellPoint> points;
  std::vector<CampbellCrossing> synchronous;  // crossings with 1×, ascending in speed
  Index basis_size = 0;
};

// The projected problem, built once for many spin rates.
class GyroscopicModeSolver {
 public:
  // Throws SolverError when the undamped basis cannot be found, LogicError when count < 1.
  GyroscopicModeSolver(const model::SystemModel& model, const VecX& q, int count, const model::LateralFluid* fluid);
  ~GyroscopicModeSolver();
  GyroscopicModeSolver(GyroscopicModeSolver&&) noexcept;
  GyroscopicModeSolver& operator=(GyroscopicModeSolver&&) noexcept;

  // The `count` lowest modes (of `kind`: All or Lateral) at the spin rate Ω (rad/s, clockwise
  // looking down-hole); with shapes (ModeResult::displacement, rotation, vector: the real part
  // of the complex mode with its largest coordinate real) when `shapes`.
  ModesResult Solve(double spin, ModeKind kind, bool shapes) const;
  Index basis_size() const;

 private:
  struct Data;
  std::unique_ptr<Data> data_;
};

// The modes at settings.rotary_speed. Throws InputError for a kind other than all or lateral.
ModesResult ComputeGyroscopicModes(const model::SystemModel& model, const VecX& q, const ModesSettings& settings,
                                   const model::LateralFluid* fluid);

// The modes at every speed of settings.campbell (which must be set) and the 1× crossings.
CampbellResult ComputeCampbell(const model::SystemModel& model, const VecX& q, const ModesSettings& settings,
                               const model::LateralFluid* fluid);

// The crossings of the branches of `points` with 1× (linear interpolation between sweep points).
std::vector<CampbellCrossing> FindSynchronousCrossings(const std::vector<CampbellPoint>& points);

}  // namespace drillflex::analyses
