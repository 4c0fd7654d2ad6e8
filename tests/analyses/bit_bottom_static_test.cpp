// The bottom contact of the bit (model/bit_bottom.hpp) in statics and at a transient's start.
//  * A string in a 30° well held at its top by a hook load H (the block's dead force) with its bit on
//    the bottom: the contact carries the WOB the axial balance leaves, the string's buoyed weight
//    along the hole less H (frictionless at rest, so exact: the soft-string balance that
//    model::WeightOnBitFromHookLoad gives the applied WOB of today's cases).
//  * The bottom placed for a transient's start (analyses/transient_start_places.hpp): at the equilibrium
//    under the applied WOB the contact carries that WOB, and the moving model is in balance there
//    (nothing jumps at t = 0).
#include <gtest/gtest.h>

#include <cstdio>

#include "analyses/transient_start_places.hpp"
#include "analyses/static_analysis.hpp"
#include "analyses/transient_analysis.hpp"
#include "cms/reduction_cache.hpp"
#include "well_cases.hpp"

namespace drillflex::analyses {
namespace bit_bottom_static_test {

model::BitRockParameters BottomOnly() {
  model::BitRockParameters p;
  p.law = model::BitRockLaw::None;
  p.stick_speed = model::kDefaultStickSpeed;
  p.bottom = model::BitBottomParameters{};
  return p;
}

double ContactForce(const model::BuiltModel& built, const VecX& q) {
  const model::SystemModel& system = built.system;
  const auto& bottom = built.Get(*built.bit_bottom);
  const auto poses = system.Poses(q);
  return bottom.ContactForce(system.StateOf(bottom, poses, VecX::Zero(bottom.local_size()), 0.0, 1.0));
}

TEST(BitBottomStatic, HookLoadLessContactForceIsTheBuoyedWeight) {
  model::ModelInput input = testing::KickOffToTheSouth(10);
  const double weight = model::WeightOnBitFromHookLoad(input, 0.0);  // along the hole, to the surface
  const double wob = input.operation.weight_on_bit;                  // 20 klbf
  const double hook_load = weight - wob;                               // at the surface
  input.operation.weight_on_bit = 0.0;  // not applied: the contact carries it
  input.bit_rock = BottomOnly();
  model::BlockDrive block;
  block.mode = model::BlockMode::HookLoad;
  block.setting.target = hook_load - model::StringAboveWeight(input);  // at the model's top
  input.block = block;
  cms::ReductionCache cache;
  const model::BuiltModel built = model::BuildSystemModel(input, cache);
  const StaticResult result = RunStaticInWell(input, built, StaticSettings{});
  ASSERT_TRUE(result.converged);
  const double contact = ContactForce(built, result.q);
  std::printf("buoyed weight %.6g N, hook load %.6g N, contact force %.6g N (WOB from the hook load %.6g N)\n", weight,
              hook_load, contact, model::WeightOnBitFromHookLoad(input, hook_load));
  // The equilibrium's residual (tens of newtons on a string: bit_tendency.hpp) bounds the balance.
  EXPECT_NEAR(contact, weight - hook_load, 1e-3 * wob + result.residual_norm);
}

TEST(BitBottomStatic, TransientStartsOnBottomInBalance) {
  model::ModelInput input = testing::KickOffToTheSouth(5);
  const double wob = input.operation.weight_on_bit;
  cms::ReductionCache cache;
  const model::BuiltModel start = model::BuildSystemModel(input, cache);
  TransientSettings settings;
  settings.bit_rock = BottomOnly();
  const VecX q0 = TransientStartPositions(input, start, settings, StaticSettings{});
  const double fluid_frequency = TransientFluidFrequency(input, start, q0, settings);
  const model::ModelInput moving_input =
      PlaceBottomAtStart(TransientModelInput(input, settings, fluid_frequency), start, q0);
  const model::BuiltModel moving = model::BuildSystemModel(moving_input, cache);
  // The contact carries the start's WOB, pressed in by W/k.
  EXPECT_NEAR(ContactForce(moving, q0), wob, 1e-9 * wob);
  const auto& bottom = moving.Get(*moving.bit_bottom);
  const auto poses = moving.system.Poses(q0);
  EXPECT_NEAR(bottom.Penetration(moving.system.StateOf(bottom, poses, VecX::Zero(bottom.local_size()), 0.0, 1.0)),
              wob / bottom.stiffness(), 1e-12);
  // Both models are in balance at q0 (the applied WOB of the one is the contact of the other).
  const VecX zero = VecX::Zero(moving.system.num_velocities());
  const double start_residual = start.system.Residual(0.0, q0, zero, zero, 1.0).norm();
  const double moving_residual = moving.system.Residual(0.0, q0, zero, zero, 1.0).norm();
  std::printf("residual at the start: %.3g N (applied WOB), %.3g N (bottom contact)\n", start_residual, moving_residual);
  EXPECT_LT(moving_residual, start_residual + 1e-6 * wob);
  // Without a bottom the input is left as it was.
  EXPECT_FALSE(PlaceBottomAtStart(input, start, q0).bit_rock.has_value());
}

}  // namespace bit_bottom_static_test
}  // namespace drillflex::analyses
