// The static residual of a string in a well is the gradient of its total potential energy
// (model::SystemModel::PotentialEnergyChange, solvers::StaticProblem::EnergyChange): what the
// energy trust region (solvers/energy_trust_region.hpp) relies on. Checked by central differences
// of the energy along random increments, R(q)·dv = dΠ(q ⊕ h dv)/dh at h = 0, at a state with wall
// contacts pressed in, bent and twisted bodies, the WOB and the torque on bit (a dead moment, whose
// work enters the energy change), on a string that kicks off, builds and turns.
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "analyses/resting_start.hpp"
#include "field_parts.hpp"
#include "well_cases.hpp"
#include "model/builder.hpp"
#include "model/static_problem.hpp"
#include "model/wall_contact.hpp"

namespace drillflex::analyses {
namespace static_energy_test {

using testing::kFt;
using testing::kLbf;

// The kick-off of tests/analyses/well_cases.hpp with four joints of pipe, 5000 ft·lbf on the bit and
// couplings at c = 100.
model::ModelInput BuildAndTurn() {
  model::ModelInput input = testing::KickOffToTheSouth(4);
  input.operation.torque_on_bit = 5000.0 * kLbf * kFt;
  input.settings.coupling_factor = 100.0;
  return input;
}

TEST(StaticEnergy, TheResidualIsTheGradientOfTheEnergyChange) {
  const model::ModelInput input = BuildAndTurn();
  cms::ReductionCache cache;
  const model::BuiltModel built = model::BuildSystemModel(input, cache);
  const model::SystemModel& system = built.system;
  VecX q = RestingStart(input, built);
  TwistUnderTorque(input, built, q);
  // Off the start a little, so that no term is at a stationary point of its own.
  std::mt19937 random(7);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  VecX nudge(system.num_velocities());
  for (int i = 0; i < nudge.size(); ++i) nudge[i] = 1e-5 * uniform(random);
  for (const model::Body& body : system.bodies()) nudge.segment(body.v_offset + 6, body.flexible_count) *= 1e-2;
  q = system.IncrementKeepingShape(q, nudge);
  model::StaticModelProblem problem(system);
  const VecX zero = VecX::Zero(system.num_velocities());
  const VecX residual = problem.Residual(0.0, q, zero, zero);
  // The state is a real one: contacts pressed in and the dead moment at work.
  int pressed = 0;
  const auto poses = system.Poses(q);
  for (const auto handle : built.contacts) {
    const auto& contact = system.Get(handle);
    pressed += contact.Result(system.StateOf(contact, poses, zero, 0.0, 1.0)).in_contact ? 1 : 0;
  }
  EXPECT_GT(pressed, 10);
  EXPECT_NEAR(problem.EnergyChange(q, q), 0.0, 1e-9);  // round-off of log(A Aᵀ) only
  // Element by element (each force element's own residual against its own energy change), so
  // that a small term is not hidden by a large one; then the bodies' elasticity with the whole.
  const auto poses_at = [&](const VecX& state) { return system.Poses(state); };
  for (int trial = 0; trial < 4; ++trial) {
    VecX direction(system.num_velocities());
    for (int i = 0; i < direction.size(); ++i) direction[i] = uniform(random);
    // Lateral and axial motions of ~0.1 mm, turns of ~1e-5, modal coordinates of their size.
    for (const model::Body& body : system.bodies()) {
      direction.segment<3>(body.v_offset) *= 1e-4;
      direction.segment<3>(body.v_offset + 3) *= 1e-5;
      direction.segment(body.v_offset + 6, body.flexible_count) *= 1e-6;
    }
    constexpr double h = 1e-3;
    const VecX ahead = problem.Increment(q, h * direction), behind = problem.Increment(q, -h * direction);
    const auto here = poses_at(q), forward = poses_at(ahead), backward = poses_at(behind);
    int checked = 0;
    for (const auto& element : system.elements()) {
      const model::ElementState state = system.StateOf(*element, here, zero, 0.0, 1.0);
      model::ElementContribution contribution;
      element->Evaluate(state, false, contribution);
      VecX local(element->local_size());
      int offset = 0;
      for (const model::Body* body : element->bodies()) {
        local.segment(offset, body->velocity_count()) = direction.segment(body->v_offset, body->velocity_count());
        offset += body->velocity_count();
      }
      const double slope = contribution.force.dot(local);
      const double difference =
          (element->PotentialEnergyChange(state, system.StateOf(*element, forward, zero, 0.0, 1.0)) -
           element->PotentialEnergyChange(state, system.StateOf(*element, backward, zero, 0.0, 1.0))) /
          (2.0 * h);
      const double scale = contribution.force.cwiseAbs().dot(local.cwiseAbs());
      if (scale == 0.0) continue;
      // A contact within 1e-6 m of its onset: the differences (moves of ~1e-7 m) straddle the kink of
      // ½ k δ², whose derivative is continuous but not differentiable there; its check is the whole sum's.
      // Its penetration is formed from positions ~1 km from the origin (a rounding unit ~1e-13 m):
      // over the differences' 2h that is |f|·1e-10 besides the relative round-off.
      double absolute = 0.0;
      if (const auto* contact = dynamic_cast<const model::WallContactElement*>(element.get()); contact != nullptr) {
        if (std::abs(contact->Result(state).penetration) < 1e-6) continue;
        absolute = 1e-10 * contribution.force.norm();
      }
      ++checked;
      EXPECT_NEAR(difference, slope, 1e-6 * scale + absolute) << element->Describe() << ", trial " << trial;
    }
    EXPECT_GT(checked, 50);  // the couplings, the loads, the supports and the contacts pressed in
    const double slope = residual.dot(direction);
    const double difference = (problem.EnergyChange(q, ahead) - problem.EnergyChange(q, behind)) / (2.0 * h);
    EXPECT_NEAR(difference, slope, 1e-6 * residual.cwiseAbs().dot(direction.cwiseAbs())) << "trial " << trial;
  }
}

// The dead moment alone: the torque on bit's work over a twist of the string about its axis is
// −T φ, exactly, however large the turn (the energy change takes the frame's turn by its log).
TEST(StaticEnergy, TheTorqueOnBitWorksOverATwistOfTheBit) {
  model::ModelInput input = BuildAndTurn();
  input.gravity = 0.0;
  input.operation.weight_on_bit = 0.0;
  cms::ReductionCache cache;
  const model::BuiltModel built = model::BuildSystemModel(input, cache);
  const model::SystemModel& system = built.system;
  const VecX q = system.ReferencePositions();
  const model::Body& bit = system.bodies().front();
  for (const double angle : {0.3, 1.5, 2.9}) {
    VecX turn = VecX::Zero(system.num_velocities());
    turn[bit.v_offset + 3] = angle;  // about the bit body's own axis (body frame x)
    const VecX turned = system.IncrementKeepingShape(q, turn);
    // The bit body alone turns: its couplings strain; the load's share of the change is −T φ.
    const double loads = [&] {
      double sum = 0.0;
      const auto before = system.Poses(q);
      const auto after = system.Poses(turned);
      const VecX rest = VecX::Zero(system.num_velocities());
      for (const auto& element : system.elements()) {
        if (element->bodies().size() != 1 || element->bodies()[0] != &bit) continue;
        if (element->Describe().find("loads") == std::string::npos) continue;
        sum += element->PotentialEnergyChange(system.StateOf(*element, before, rest, 0.0, 1.0),
                                              system.StateOf(*element, after, rest, 0.0, 1.0));
      }
      return sum;
    }();
    // The torque on bit is a moment T about the string frame's +x at the bit: over a turn φ about
    // that axis it does the work T φ, and the energy changes by −T φ.
    EXPECT_NEAR(loads, -input.operation.torque_on_bit * angle, 1e-9 * input.operation.torque_on_bit) << angle;
  }
}

}  // namespace static_energy_test
}  // namespace drillflex::analyses
