// The parameter block a built model is evaluated under (model/load_parameters.hpp): every element's
// Jacobian under a block that changes everything it can (central differences of the model's own
// residual), the block standing for a model rebuilt with the same values (a WOB and torque on bit as
// values, friction coefficients, a prescribed sliding), and what each factor scales (the couplings'
// stiffness and energy, the bit's support, the weight group).
#include <gtest/gtest.h>

#include <random>

#include "cms/reduction_cache.hpp"
#include "analyses/resting_start.hpp"
#include "model/builder.hpp"
#include "model/static_problem.hpp"
#include "model/spring_elements.hpp"
#include "model/wall_contact.hpp"
#include "solvers/problem.hpp"
#include "well_cases.hpp"

namespace drillflex::analyses {
namespace load_parameters_test {

// The string resting on the wall (its contacts touching) with every coordinate moved a little.
VecX Perturbed(const model::ModelInput& input, const model::BuiltModel& built, double size, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  VecX dv(built.system.num_velocities());
  for (Eigen::Index i = 0; i < dv.size(); ++i) dv[i] = size * uniform(rng);
  return built.system.Increment(RestingStart(input, built), dv);
}

// How many wall contacts press on the wall at q.
int Touching(const model::BuiltModel& built, const VecX& q) {
  const auto poses = built.system.Poses(q);
  const VecX rest = VecX::Zero(built.system.num_velocities());
  int touching = 0;
  for (const auto handle : built.contacts) {
    const auto& contact = built.system.Get(handle);
    touching += contact.Result(built.system.StateOf(contact, poses, rest, 0.0, 1.0)).in_contact ? 1 : 0;
  }
  return touching;
}

model::LoadParameters EverythingChanged() {
  model::LoadParameters block(0.8);
  block.weight_factor = 1.3;
  block.case_load_factor = 0.5;
  block.weight_on_bit = 30e3;
  block.torque_on_bit = 4e3;
  block.SetWallFriction({0.35, 0.2});
  block.friction_factor = 0.7;
  block.sliding_mode = model::SlidingMode::kPrescribed;
  block.sliding = {0.2, 6.0};
  block.coupling_factor = 0.3;
  block.bit_support_factor = 0.5;
  return block;
}

TEST(LoadParameters, EveryJacobianMatchesCentralDifferencesUnderAChangedBlock) {
  model::ModelInput input = testing::KickOffToTheSouth(2);
  cms::ReductionCache cache;
  const model::BuiltModel built = model::BuildSystemModel(input, cache);
  const model::StaticModelProblem problem(built.system, EverythingChanged());
  const VecX zero = VecX::Zero(built.system.num_velocities());
  for (unsigned seed : {3u, 11u}) {
    const VecX q = Perturbed(input, built, 1e-6, seed);
    ASSERT_GT(Touching(built, q), 10) << "seed " << seed;
    const SparseMat analytic = problem.IterationMatrix(0.0, q, zero, zero, 1.0, 0.0, 0.0);
    const SparseMat numeric = solvers::FiniteDifferenceIterationMatrix(problem, 0.0, q, zero, zero, 1.0, 0.0, 0.0, 1e-7);
    EXPECT_LT(solvers::RelativeMatrixError(MatX(analytic), MatX(numeric)), 1e-6) << "seed " << seed;
  }
}

// The block's values are the rebuilt model's: a WOB and torque on bit, friction coefficients and a
// prescribed sliding set through the block give the residual of a model built with them.
TEST(LoadParameters, TheBlockIsTheModelRebuiltWithItsValues) {
  model::ModelInput input = testing::KickOffToTheSouth(2);
  cms::ReductionCache cache;
  const model::BuiltModel built = model::BuildSystemModel(input, cache);
  model::ModelInput changed = input;
  changed.operation.weight_on_bit = 12e3;
  changed.operation.torque_on_bit = 3e3;
  changed.settings.contact.friction = 0.4;
  changed.settings.contact.axial_friction = 0.15;
  changed.static_sliding = model::PrescribedSliding{-0.3, 2.0};
  const model::BuiltModel rebuilt = model::BuildSystemModel(changed, cache);
  model::LoadParameters block;
  block.weight_on_bit = 12e3;
  block.torque_on_bit = 3e3;
  block.SetWallFriction({0.15, 0.4});
  block.sliding_mode = model::SlidingMode::kPrescribed;
  block.sliding = {-0.3, 2.0};
  const VecX q = Perturbed(input, built, 1e-6, 5);
  ASSERT_GT(Touching(built, q), 10);
  const VecX zero = VecX::Zero(built.system.num_velocities());
  const VecX by_block = built.system.Residual(0.0, q, zero, zero, block);
  const VecX by_rebuild = rebuilt.system.Residual(0.0, q, zero, zero, 1.0);
  EXPECT_LT((by_block - by_rebuild).norm(), 1e-9 * by_rebuild.norm());
  // And a case's zero WOB given a value through the block (its element is per unit WOB).
  model::ModelInput none = input;
  none.operation.weight_on_bit = 0.0;
  const model::BuiltModel unloaded = model::BuildSystemModel(none, cache);
  model::LoadParameters wob;
  wob.weight_on_bit = input.operation.weight_on_bit;
  EXPECT_LT((unloaded.system.Residual(0.0, q, zero, zero, wob) - built.system.Residual(0.0, q, zero, zero, 1.0)).norm(),
            1e-9 * by_rebuild.norm());
}

// The couplings' factor s scales their force and energy by s; the bit's support factor its
// reaction; the weight factor the weight group alone (with the top free: the pipe above the model,
// model/string_above.hpp, stiffens with its own weight and the top's tension, not linearly).
TEST(LoadParameters, FactorsScaleWhatTheyName) {
  model::ModelInput input = testing::KickOffToTheSouth(2);
  input.settings.top = model::TopCondition::Free;
  cms::ReductionCache cache;
  const model::BuiltModel built = model::BuildSystemModel(input, cache);
  const model::SystemModel& system = built.system;
  const VecX q = Perturbed(input, built, 1e-6, 9);
  const auto poses = system.Poses(q);
  const VecX zero = VecX::Zero(system.num_velocities());
  model::LoadParameters soft;
  soft.coupling_factor = 0.25;
  int couplings = 0;
  for (const auto& element : system.elements()) {
    const auto* coupling = dynamic_cast<const model::CouplingElement*>(element.get());
    if (coupling == nullptr) continue;
    ++couplings;
    const Vec6 full = coupling->Force(system.StateOf(*coupling, poses, zero, 0.0, 1.0));
    const Vec6 scaled = coupling->Force(system.StateOf(*coupling, poses, zero, 0.0, soft));
    EXPECT_LT((scaled - 0.25 * full).norm(), 1e-12 * full.norm());
    const double energy = coupling->PotentialEnergy(system.StateOf(*coupling, poses, zero, 0.0, 1.0));
    EXPECT_NEAR(coupling->PotentialEnergy(system.StateOf(*coupling, poses, zero, 0.0, soft)), 0.25 * energy,
                1e-12 * energy);
  }
  EXPECT_GT(couplings, 0);
  model::LoadParameters free_bit;
  free_bit.bit_support_factor = 0.0;
  int bit_supports = 0;
  for (const auto handle : built.supports) {
    const auto& support = system.Get(handle);
    const Vec6 held = support.Reaction(system.StateOf(support, poses, zero, 0.0, 1.0));
    const Vec6 freed = support.Reaction(system.StateOf(support, poses, zero, 0.0, free_bit));
    if (support.holds_bit()) {
      ++bit_supports;
      EXPECT_GT(held.norm(), 0.0);
      EXPECT_EQ(freed.norm(), 0.0);
    } else {
      EXPECT_EQ(freed, held);  // the hook is not the bit's
    }
  }
  EXPECT_EQ(bit_supports, 1);
  // The weight group is linear in its factor and nothing else moves with it: R(2) − R(1) = R(1) − R(0)
  // (the couplings' placement kink, the same in the three, drops out), and it is the weight.
  model::LoadParameters none_weight, heavy;
  none_weight.weight_factor = 0.0;
  heavy.weight_factor = 2.0;
  const VecX light = system.Residual(0.0, q, zero, zero, none_weight);
  const VecX once = system.Residual(0.0, q, zero, zero, 1.0);
  const VecX twice = system.Residual(0.0, q, zero, zero, heavy);
  EXPECT_LT(((twice - once) - (once - light)).norm(), 1e-9 * (once - light).norm());
  // The frame-translation rows of the difference sum to the string's buoyed weight, along +z (down).
  Vec3 weight = Vec3::Zero();
  for (const model::Body& body : system.bodies()) weight -= (once - light).segment<3>(body.v_offset);
  double expected = 0.0;
  for (const model::Body& body : system.bodies()) expected += model::BuoyedWeightPerLength(body, input) * body.length();
  EXPECT_NEAR(weight.z(), expected, 1e-9 * expected);
  EXPECT_LT(weight.head<2>().norm(), 1e-9 * expected);
}

}  // namespace load_parameters_test
}  // namespace drillflex::analyses
