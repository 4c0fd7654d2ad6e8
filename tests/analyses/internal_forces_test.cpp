// Internal forces along the string (model/internal_forces.hpp) through the static analysis, on
// the V1 rod (4 bodies × 10 elements × (6 + 6)): statically determinate cases whose stress
// resultants follow from equilibrium alone, and the agreement of the bodies' end forces with the
// coupling forces at the joints.
#include <gtest/gtest.h>

#include <cmath>

#include "analyses/static_analysis.hpp"
#include "analyses_test_support.hpp"
#include "model/internal_forces.hpp"

namespace drillflex::analyses {
namespace {

using testing::kRodLength;

struct Solved {
  model::BuiltModel built;
  StaticResult result;
};

Solved SolveCantilever(std::vector<model::Load> loads, cms::ReductionCache& cache) {
  model::ModelInput input = testing::V1Rod();
  input.supports = {testing::ClampAt(0.0)};
  input.loads = std::move(loads);
  model::BuiltModel built = model::BuildSystemModel(input, cache);
  StaticResult result = RunStatic(built, StaticSettings{});
  return {std::move(built), std::move(result)};
}

// Cantilever with a tip force P (y): M(s) = P (L − s) about z, shear P (the part above pulls the
// part below with +P ŷ, whose moment about the section is (L − s) x̂ × P ŷ = P (L − s) ẑ).
TEST(InternalForces, CantileverTipForceMomentAndShear) {
  cms::ReductionCache cache;
  const double force = 100.0;
  const Solved solved = SolveCantilever({testing::PointLoad(kRodLength, Vec3(0, force, 0))}, cache);
  double worst_moment = 0.0, worst_shear = 0.0;
  for (const StaticNodeResult& node : solved.result.nodes) {
    const double exact = force * (kRodLength - node.s);
    worst_moment = std::max(worst_moment, std::abs(node.moment.z() - exact) / (force * kRodLength));
    if (kRodLength - node.s > 0.1 * kRodLength) {
      EXPECT_NEAR(node.bending_moment, exact, 5e-3 * exact) << "s = " << node.s;
    }
    EXPECT_NEAR(node.force.y(), force, 5e-3 * force) << "s = " << node.s;
    worst_shear = std::max(worst_shear, std::abs(node.shear_force / force - 1.0));
    EXPECT_NEAR(node.axial_force, 0.0, 1e-3 * force);
    EXPECT_NEAR(node.torque, 0.0, 1e-3 * force * kRodLength);
  }
  std::printf("tip force: max moment error %.2e P L, max shear error %.2e P\n", worst_moment, worst_shear);
  EXPECT_LT(worst_moment, 5e-3);
}

TEST(InternalForces, AxialBarUnderTipTensionCarriesItEverywhere) {
  cms::ReductionCache cache;
  const double tension = 5e4;
  const Solved solved = SolveCantilever({testing::PointLoad(kRodLength, Vec3(tension, 0, 0))}, cache);
  double worst = 0.0;
  for (const StaticNodeResult& node : solved.result.nodes) {
    worst = std::max(worst, std::abs(node.axial_force / tension - 1.0));
    EXPECT_NEAR(node.bending_moment, 0.0, 1e-6 * tension * kRodLength);
  }
  std::printf("tip tension: max axial force error %.2e\n", worst);
  EXPECT_LT(worst, 1e-6);
}

TEST(InternalForces, ShaftUnderTipTorqueCarriesItEverywhere) {
  cms::ReductionCache cache;
  const double torque = 500.0;
  const Solved solved = SolveCantilever({testing::PointLoad(kRodLength, Vec3::Zero(), Vec3(torque, 0, 0))}, cache);
  double worst = 0.0;
  for (const StaticNodeResult& node : solved.result.nodes) worst = std::max(worst, std::abs(node.torque / torque - 1.0));
  std::printf("tip torque: max torque error %.2e\n", worst);
  // The couplings measure relative rotation by vee(skew(R)) ≈ θ (1 − θ²/6): the frames of
  // consecutive bodies turn by ~2.4e-3 rad here, a 1e-6 relative effect.
  EXPECT_LT(worst, 1e-5);
}

// A distributed axial load w toward the top (tension) on a bar clamped at the bit:
// N(s) = w (L − s). Interior nodes average two elements (exact for a linear N); a body's end node
// carries its one element, off by at most w h/2 (h the element length); joints give the coupling
// force, exact.
TEST(InternalForces, DistributedAxialLoadGivesALinearAxialForce) {
  cms::ReductionCache cache;
  const double w = 1000.0;  // N/m
  const Solved solved = SolveCantilever({testing::DistributedLoad(0.0, kRodLength, Vec3(w, 0, 0))}, cache);
  const double h = kRodLength / 40.0;
  for (const StaticNodeResult& node : solved.result.nodes) {
    const double exact = w * (kRodLength - node.s);
    const bool end = node.s < 1e-9 || node.s > kRodLength - 1e-9;
    EXPECT_NEAR(node.axial_force, exact, end ? 0.5 * w * h * (1 + 1e-6) : 1e-6 * w * kRodLength) << "s = " << node.s;
  }
}

// The end forces of each body's FE model agree with the coupling force at the joint (the
// coupling force is the internal force there). Axial force and torque agree to round-off. The
// lateral parts agree to O(c × slope), c = (EA/L) ½ ηᵀ K_G,ff η: the model's bending terms use
// N(η) = N̄ − c (model/internal_forces.hpp), measured 0.7 N of a 106 N shear here; 1 % of the
// lateral force is allowed (without the geometric term N̄ K_G d the mismatch would be N̄ × slope
// ≈ 80 N).
TEST(InternalForces, BodyEndForcesAgreeWithTheCouplingForces) {
  cms::ReductionCache cache;
  const Solved solved = SolveCantilever(
      {testing::PointLoad(kRodLength, Vec3(2e4, 100, -60), Vec3(300, 40, -20))}, cache);
  const model::SystemModel& system = solved.built.system;
  const VecX& q = solved.result.q;
  const auto forces = model::ComputeInternalForces(system, q);
  const auto joints = model::JointInternalForces(system, q, VecX::Zero(system.num_velocities()));
  ASSERT_EQ(joints.size(), 3u);
  const auto poses = system.Poses(q);
  for (std::size_t j = 0; j < joints.size(); ++j) {
    const model::SectionForces& joint = joints[j];  // lower body's frame
    const Mat3 upper_to_lower = poses[j].A.transpose() * poses[j + 1].A;
    const model::SectionForces& lower_end = forces[j].back();
    model::SectionForces upper_start;
    upper_start.force = upper_to_lower * forces[j + 1].front().force;
    upper_start.moment = upper_to_lower * forces[j + 1].front().moment;
    for (const model::SectionForces* end : {&lower_end, static_cast<const model::SectionForces*>(&upper_start)}) {
      EXPECT_NEAR(end->axial_force(), joint.axial_force(), 1e-6 * joint.axial_force()) << "joint " << j;
      EXPECT_NEAR(end->torque(), joint.torque(), 1e-5 * joint.torque()) << "joint " << j;
      EXPECT_LT((end->force - joint.force).tail<2>().norm(), 1e-2 * joint.shear_force()) << "joint " << j;
      EXPECT_LT((end->moment - joint.moment).tail<2>().norm(), 1e-2 * joint.bending_moment()) << "joint " << j;
    }
  }
}

// The P-delta part: a compressed column (half its Euler load) with a lateral tip force. The
// body-end forces (with the geometric term N̄ K_G d) still match the coupling forces, which hold
// the exact equilibrium of the deformed string, to 0.5 % (measured 0.24 %; the O(c × slope) of
// the test above); without that term they would miss N̄ × slope ≈ 100 N of the 250–410 N shear.
TEST(InternalForces, GeometricTermKeepsTheBodyEndsInBalanceUnderCompression) {
  cms::ReductionCache cache;
  const double pcr = kPi * kPi * 2.1e11 * testing::RodSecondMoment() / (4 * kRodLength * kRodLength);
  const Solved solved = SolveCantilever({testing::PointLoad(kRodLength, Vec3(-0.5 * pcr, 200, 0))}, cache);
  const model::SystemModel& system = solved.built.system;
  const VecX& q = solved.result.q;
  const auto forces = model::ComputeInternalForces(system, q);
  const auto joints = model::JointInternalForces(system, q, VecX::Zero(system.num_velocities()));
  for (std::size_t j = 0; j < joints.size(); ++j) {
    const model::SectionForces& lower_end = forces[j].back();
    EXPECT_NEAR(lower_end.force.y(), joints[j].force.y(), 5e-3 * std::abs(joints[j].force.y())) << "joint " << j;
    EXPECT_NEAR(lower_end.moment.z(), joints[j].moment.z(), 5e-3 * std::abs(joints[j].moment.z())) << "joint " << j;
  }
  // Equilibrium of the deformed column: M(0) = H L + P δ_tip (P compression, δ the tip deflection).
  const StaticNodeResult& tip = solved.result.nodes.back();
  const double expected = 200 * (kRodLength + tip.displacement.x()) + 0.5 * pcr * tip.displacement.y();
  EXPECT_NEAR(solved.result.nodes.front().moment.z(), expected, 2e-3 * expected);
}

}  // namespace
}  // namespace drillflex::analyses
