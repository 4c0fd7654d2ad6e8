// analyses::CarryCouplingForces: before a stage of stiffer couplings, every coupling and support is
// closed to the strain that carries, at the new stiffness, the force it carried at the old. Measured
// on a string that builds and turns in a hole (bit, stabilizer, collars, drill pipe with tool
// joints) laid on the wall by the resting start, whose couplings carry the soft-string tension:
//   * each coupling's force and moment at c = 100 after the change equal those at c = 10 before
//     (the plain restart would multiply them by 10);
//   * the hook carries the same load;
//   * no node goes deeper into the wall (nothing adds up along the string);
//   * the residual the stiffer couplings add is a hundredth of what the plain restart adds.
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "field_parts.hpp"
#include "analyses/coupling_regap.hpp"
#include "analyses/resting_start.hpp"
#include "core/error.hpp"
#include "model/builder.hpp"
#include "model/spring_elements.hpp"
#include "model/wall_contact.hpp"

namespace drillflex::analyses {
namespace {

using testing::kFt;
using testing::kIn;
using testing::kLbf;
using testing::Part;

model::ModelInput BuildAndTurn(double coupling_factor) {
  model::ModelInput input;
  model::Component stabilizer = Part(model::ComponentType::Stabilizer, 6.75, 2.8125, 5.0);
  stabilizer.blade_diameter = 8.375 * kIn;
  model::Component pipe = Part(model::ComponentType::Pipe, 5.0, 4.276, 30.0, 20);
  pipe.joint_diameter = 6.625 * kIn;
  pipe.joint_inner_diameter = 3.25 * kIn;
  input.string.components = {Part(model::ComponentType::Bit, 8.5, 2.0, 1.0), stabilizer,
                             Part(model::ComponentType::Collar, 6.75, 2.8125, 30.0, 2), pipe};
  input.materials["steel"] = fe::Material{"steel", 2.1e11, 0.3, 7850.0};
  input.gravity = 9.81;
  // Vertical to 1000 ft, then 5°/100 ft to 25° while turning from north to east.
  input.trajectory.emplace(std::vector<well::SurveyStation>{{0.0, 0.0, 0.0},
                                                            {1000.0 * kFt, 0.0, 0.0},
                                                            {1500.0 * kFt, 25.0 * kDegree, 90.0 * kDegree},
                                                            {2500.0 * kFt, 25.0 * kDegree, 90.0 * kDegree}});
  input.hole = {well::HoleSection{{}, 8.5 * kIn, {}}};
  input.bit_md = 1900.0 * kFt;
  input.operation.weight_on_bit = 10000.0 * kLbf;
  input.settings.coupling_factor = coupling_factor;
  return input;
}

// Every coupling's and support's force (K e, their own frames) at q, in element order.
std::vector<Vec6> SpringForces(const model::SystemModel& system, const VecX& q) {
  const auto poses = system.Poses(q);
  const VecX rest = VecX::Zero(system.num_velocities());
  std::vector<Vec6> forces;
  for (const auto& element : system.elements()) {
    const model::ElementState state = system.StateOf(*element, poses, rest, 0.0, 1.0);
    if (const auto* coupling = dynamic_cast<const model::CouplingElement*>(element.get())) {
      forces.push_back(coupling->Force(state));
    } else if (const auto* support = dynamic_cast<const model::SupportElement*>(element.get())) {
      forces.push_back(-support->Reaction(state));
    }
  }
  return forces;
}

double DeepestPenetration(const model::BuiltModel& built, const VecX& q) {
  const auto poses = built.system.Poses(q);
  const VecX rest = VecX::Zero(built.system.num_velocities());
  double deepest = -1.0;
  for (const int index : built.contact_elements) {
    const auto& contact = static_cast<const model::WallContactElement&>(*built.system.elements()[index]);
    deepest = std::max(deepest, contact.Result(built.system.StateOf(contact, poses, rest, 0.0, 1.0)).penetration);
  }
  return deepest;
}

TEST(CarryCouplingForces, KeepsEveryJointForceWhenTheCouplingsStiffenTenfold) {
  cms::ReductionCache cache;
  const model::ModelInput soft_input = BuildAndTurn(10.0);
  const model::BuiltModel soft = model::BuildSystemModel(soft_input, cache);
  const model::BuiltModel stiff = model::BuildSystemModel(BuildAndTurn(100.0), cache);
  const VecX start = RestingStart(soft_input, soft);
  VecX moved = start;
  CarryCouplingForces(soft, stiff, moved);

  const std::vector<Vec6> before = SpringForces(soft.system, start);
  const std::vector<Vec6> restarted = SpringForces(stiff.system, start);  // the plain restart
  const std::vector<Vec6> after = SpringForces(stiff.system, moved);
  ASSERT_EQ(before.size(), after.size());
  double largest_force = 0.0, largest_miss = 0.0, largest_restart_miss = 0.0;
  for (std::size_t i = 0; i < before.size(); ++i) {
    largest_force = std::max(largest_force, before[i].head<3>().norm());
    largest_miss = std::max(largest_miss, (after[i] - before[i]).head<3>().norm());
    largest_restart_miss = std::max(largest_restart_miss, (restarted[i] - before[i]).head<3>().norm());
  }
  // The strains are ~1e-5 m; what the linear end-motion fit leaves is of second order in them and
  // in the joints' angles (~1e-3 rad): 1e-3 of the forces is a generous bound, against the factor
  // 10 of the restart.
  EXPECT_GT(largest_force, 1e4);  // the tension at the top, N
  EXPECT_GT(largest_restart_miss, 5.0 * largest_force);
  EXPECT_LT(largest_miss, 1e-3 * largest_force);

  // The hook (the last support) carries the same load.
  const int hook = static_cast<int>(before.size()) - 1;
  EXPECT_NEAR(after[hook][0], before[hook][0], 1e-3 * std::abs(before[hook][0]));

  // Nothing is pushed into the wall: the motions are micrometres and do not add up along the string.
  EXPECT_LT(DeepestPenetration(stiff, moved), DeepestPenetration(soft, start) + 1e-6);

  // The resting start is not an equilibrium (its own residual is the sag between the joints, the
  // contacts): what the stiffer couplings add to it, against what the plain restart adds.
  const VecX zero = VecX::Zero(stiff.system.num_velocities());
  const VecX soft_residual = soft.system.Residual(0.0, start, zero, zero, 1.0);
  const double restart_added = (stiff.system.Residual(0.0, start, zero, zero, 1.0) - soft_residual).norm();
  const double moved_added = (stiff.system.Residual(0.0, moved, zero, zero, 1.0) - soft_residual).norm();
  EXPECT_GT(restart_added, largest_force);
  EXPECT_LT(moved_added, 1e-2 * restart_added);
}

TEST(CarryCouplingForces, RefusesModelsThatDoNotMatch) {
  cms::ReductionCache cache;
  model::ModelInput shorter = BuildAndTurn(100.0);
  shorter.string.components.back().count = 10;
  const model::ModelInput soft_input = BuildAndTurn(10.0);
  const model::BuiltModel soft = model::BuildSystemModel(soft_input, cache);
  const model::BuiltModel other = model::BuildSystemModel(shorter, cache);
  VecX q = RestingStart(soft_input, soft);
  EXPECT_THROW(CarryCouplingForces(soft, other, q), LogicError);
}

}  // namespace
}  // namespace drillflex::analyses
