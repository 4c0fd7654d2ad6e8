// The fluid's lateral mass and damping (model/lateral_fluid.hpp) against hand sums: a rigid
// lateral motion of the whole string carries ρ_i A_i L (bore) plus C_m ρ π a² L (annulus), an
// axial motion or a twist none; the annulus groups reproduce the per-node matrices.
#include "model/lateral_fluid.hpp"

#include <gtest/gtest.h>

#include "fe/annulus_fluid.hpp"
#include "model_test_support.hpp"

namespace drillflex::model {
namespace lateral_fluid_test {

// A hollow rod (OD 3 in, ID 1 in) of 4 bodies in a straight vertical 6 in hole (a well), fluid
// 1200 kg/m³ inside and out, gravity off.
ModelInput HollowRodInHole(double viscosity) {
  ModelInput input = testing::RodInput(4, 10, 6);
  input.string.components[0].inner_diameter = 0.0254;
  input.well =
      model::MakeWellbore(well::Trajectory(std::vector<well::SurveyStation>{{0.0, 0.0, 0.0}, {100.0, 0.0, 0.0}}),
                          std::vector<well::HoleSection>{well::HoleSection{std::nullopt, 0.1524, std::nullopt}});
  input.bit_md = 50.0;
  input.fluid = FluidConfig{1200.0, viscosity, std::nullopt, -1.0};
  return input;
}

// The velocity of a rigid translation `t` (global) of every body.
VecX RigidTranslation(const SystemModel& model, const Vec3& t) {
  VecX v = VecX::Zero(model.num_velocities());
  for (const Body& body : model.bodies()) v.segment<3>(body.v_offset) = t;
  return v;
}

TEST(LateralFluid, RigidLateralMotionCarriesBoreAndAnnulusFluid) {
  cms::ReductionCache cache;
  const ModelInput input = HollowRodInHole(0.0);
  const BuiltModel built = BuildSystemModel(input, cache);
  const LateralFluid fluid = MakeLateralFluid(input, built.system);
  const VecX q = built.system.ReferencePositions();
  const LateralFluidMatrices m = ComputeLateralFluidMatrices(built.system, fluid, q, 10.0);
  const double a = 0.0381, b = 0.0762, length = 5.08;
  const double bore = 1200.0 * kPi * 0.0127 * 0.0127 * length;
  const double cm = (b * b + a * a) / (b * b - a * a);  // inviscid, method.md §7
  const double annulus = cm * 1200.0 * kPi * a * a * length;
  // The string runs along the hole axis (global z, vertical): lateral is x and y.
  for (const Vec3& direction : {Vec3(Vec3::UnitX()), Vec3(Vec3::UnitY())}) {
    const VecX v = RigidTranslation(built.system, direction);
    EXPECT_NEAR(v.dot(m.mass * v), bore + annulus, 1e-9 * (bore + annulus));
    EXPECT_NEAR(v.dot(m.damping * v), 0.0, 1e-12);
  }
  const VecX axial = RigidTranslation(built.system, Vec3::UnitZ());
  EXPECT_NEAR(axial.dot(m.mass * axial), 0.0, 1e-9 * annulus);
  // Internal only: the bore's share; annulus groups (one group here) equal the annulus part.
  const VecX v = RigidTranslation(built.system, Vec3::UnitX());
  const SparseMat internal = ComputeLateralFluidMatrices(built.system, fluid, q, 10.0, FluidPart::Internal).mass;
  EXPECT_NEAR(v.dot(internal * v), bore, 1e-9 * bore);
  const auto groups = ComputeAnnulusGroups(built.system, fluid, q);
  ASSERT_EQ(groups.size(), 1u);
  const LateralFluidMatrices grouped = ComputeAnnulusMatrices(groups, fluid, 10.0);
  EXPECT_NEAR(v.dot(grouped.mass * v), annulus, 1e-9 * annulus);
}

TEST(LateralFluid, ViscousAnnulusFollowsChenWambsganssAtTheFrequency) {
  cms::ReductionCache cache;
  const ModelInput input = HollowRodInHole(0.02);
  const BuiltModel built = BuildSystemModel(input, cache);
  const LateralFluid fluid = MakeLateralFluid(input, built.system);
  ASSERT_TRUE(fluid.frequency_dependent());
  const VecX q = built.system.ReferencePositions();
  const double omega = 30.0, a = 0.0381, length = 5.08;
  const fe::AnnulusFluidCoefficients c = fe::ComputeAnnulusFluidCoefficients(a, 0.0762, omega, 0.02 / 1200.0);
  const LateralFluidMatrices m = ComputeLateralFluidMatrices(built.system, fluid, q, omega, FluidPart::Annulus);
  const VecX v = RigidTranslation(built.system, Vec3::UnitY());
  const double unit = 1200.0 * kPi * a * a * length;
  EXPECT_NEAR(v.dot(m.mass * v), c.added_mass * unit, 1e-9 * unit);
  EXPECT_NEAR(v.dot(m.damping * v), c.damping * omega * unit, 1e-9 * unit * omega);
  EXPECT_GT(c.damping, 0.0);
  // Without a well only the bore fluid is left.
  ModelInput dry_hole = input;
  dry_hole.well.reset();
  const BuiltModel straight = BuildSystemModel(dry_hole, cache);
  const LateralFluid no_annulus = MakeLateralFluid(dry_hole, straight.system);
  const LateralFluidMatrices bore =
      ComputeLateralFluidMatrices(straight.system, no_annulus, straight.system.ReferencePositions(), omega);
  const VecX w = RigidTranslation(straight.system, Vec3::UnitZ());
  EXPECT_NEAR(w.dot(bore.mass * w), 1200.0 * kPi * 0.0127 * 0.0127 * length, 1e-9);
}

}  // namespace lateral_fluid_test
}  // namespace drillflex::model
