// Internal forces along the string (model/internal_forces.hpp) through the static analysis, on
// the V1 rod (4 bodies × 10 elements × (6 + 6)): statically determinate cases whose stress
// resultants follow from equilibrium alone, and the agreement of the bodies' end forces with the
// coupling forces at the joints.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "analyses/static_analysis.hpp"
#include "analyses_test_support.hpp"
#include "fe/beam_element.hpp"
#include "fe/body_fe_model.hpp"
#include "model/internal_forces.hpp"

namespace drillflex::analyses {
namespace internal_forces_test {

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
// lateral force carries the one-sided element error N̄ κ h (see the P-delta test below; measured
// 0.2–0.8 N against bounds of 1–2 N here); the bending moment agrees to 1 %.
TEST(InternalForces, BodyEndForcesAgreeWithTheCouplingForces) {
  cms::ReductionCache cache;
  const Solved solved = SolveCantilever(
      {testing::PointLoad(kRodLength, Vec3(2e4, 100, -60), Vec3(300, 40, -20))}, cache);
  const model::SystemModel& system = solved.built.system;
  const VecX& q = solved.result.q;
  const auto forces = model::ComputeInternalForces(solved.built, q);
  const auto joints = model::JointInternalForces(solved.built, q, VecX::Zero(system.num_velocities()));
  ASSERT_EQ(joints.size(), 3u);
  const auto poses = system.Poses(q);
  const double ei = 2.1e11 * testing::RodSecondMoment();
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
      const double element_error = joint.axial_force() * joint.bending_moment() / ei * (kRodLength / 40.0);
      EXPECT_LT((end->force - joint.force).tail<2>().norm(), element_error) << "joint " << j;
      EXPECT_LT((end->moment - joint.moment).tail<2>().norm(), 1e-2 * joint.bending_moment()) << "joint " << j;
    }
  }
}

// Why the section torque of a twisted string reads above the torque it carries (docs/validation.md V11b):
// a coupling measures the relative rotation of two bodies' frames by vee(skew(R)), sin φ about the axis
// for a twist φ, not φ. Its moment λ is conjugate to sin φ, so the rigid rotation of the body above
// balances the torque T it carries with λ cos φ = T: the coupling, and the bodies' elastic twist on its
// side, read T / cos φ, φ the relative twist of the two frames, which itself carries that torque:
// φ = (T / cos φ) L_b/(G J) for bodies L_b long (solved here by fixed point). The rod (3 in solid,
// G = E/2.6) under a tip torque of 5 kN·m in bodies of 2.54 m: φ = 0.047559 rad, the joint reads
// 1/cos φ − 1 = 1.1320e-3 above T; in bodies of 1.27 m (φ/2) a quarter of that; under 10 kN·m four times
// as much; and the same with 200 kN of tension (no geometric stiffness of the tension enters a straight
// shaft's torque). Asserted within 1 % of the predicted excess (measured 0.1 % at most).
TEST(InternalForces, TheCouplingsSmallRotationStrainRaisesATwistedShaftsTorqueByOneOverCosPhi) {
  const double polar = kPi / 32.0 * std::pow(testing::kRodDiameter, 4);
  const double shear_modulus = 2.1e11 / 2.6;
  struct Case {
    int bodies;
    double tension, torque;
  };
  for (const Case& each : {Case{2, 0.0, 5e3}, Case{2, 2e5, 5e3}, Case{4, 0.0, 5e3}, Case{2, 0.0, 1e4}}) {
    cms::ReductionCache cache;
    model::ModelInput input = testing::RodInput(each.bodies, 2.1e11, 7800.0);
    input.supports = {testing::ClampAt(0.0)};
    input.loads = {testing::PointLoad(kRodLength, Vec3(each.tension, 0, 0), Vec3(each.torque, 0, 0))};
    const model::BuiltModel built = model::BuildSystemModel(input, cache);
    const StaticResult result = RunStatic(built, StaticSettings{});
    const double linear = each.torque * (kRodLength / each.bodies) / (shear_modulus * polar);
    double phi = linear;
    for (int i = 0; i < 50; ++i) phi = linear / std::cos(phi);
    const double predicted = 1.0 / std::cos(phi) - 1.0;
    const auto joints = model::JointInternalForces(built, result.q, VecX::Zero(built.system.num_velocities()));
    ASSERT_EQ(joints.size(), static_cast<std::size_t>(each.bodies - 1));
    for (std::size_t j = 0; j < joints.size(); ++j) {
      const double excess = joints[j].torque() / each.torque - 1.0;
      EXPECT_NEAR(excess, predicted, 0.01 * predicted) << each.bodies << " bodies, joint " << j;
      std::printf("%d bodies, %.0f kN, %.0f kN*m, joint %zu: phi %.6f rad, torque excess %.4e, 1/cos(phi) - 1 = %.4e\n",
                  each.bodies, each.tension / 1e3, each.torque / 1e3, j, phi, excess, predicted);
    }
  }
}

// The P-delta part: a compressed cantilever (half its Euler load P) with a lateral tip force H.
// Above any section the only load is the tip's, so in the string (= global) frame the internal
// force is exactly (−P, H) everywhere, and the moment at the root is H (L + u_x) + P δ_tip.
// In a body frame turned by α the shear reads H + P α, mostly the geometric term N̄ K_G d.
// The element end forces carry the cubic element's own error where only one element side
// exists: its shear is constant while the true one changes by N̄ κ h across it (κ = M/EI the
// curvature, h the element length); that bound is the tolerance at the body ends. Without the
// geometric term the body-end shear misses N̄ × slope (≈ 41 N of 253 N at the first joint).
TEST(InternalForces, GeometricTermCarriesTheCompressionIntoTheShear) {
  cms::ReductionCache cache;
  const double ei = 2.1e11 * testing::RodSecondMoment();
  const double compression = 0.5 * kPi * kPi * ei / (4 * kRodLength * kRodLength), lateral = 200.0;
  const Solved solved = SolveCantilever({testing::PointLoad(kRodLength, Vec3(-compression, lateral, 0))}, cache);
  const double h = kRodLength / 40.0;
  const auto& nodes = solved.result.nodes;
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    const StaticNodeResult& node = nodes[i];
    double moment = 0.0;  // the largest bending moment on the elements next to the node
    for (std::size_t k = (i > 0 ? i - 1 : 0); k <= std::min(i + 1, nodes.size() - 1); ++k) {
      moment = std::max(moment, std::abs(nodes[k].moment.z()));
    }
    const double tolerance = compression * (moment / ei) * h;
    EXPECT_NEAR(node.force.y(), lateral, tolerance) << "s = " << node.s;
    EXPECT_NEAR(node.force.x(), -compression, 1e-4 * compression) << "s = " << node.s;
  }
  const StaticNodeResult& tip = solved.result.nodes.back();
  const double root_moment = lateral * (kRodLength + tip.displacement.x()) + compression * tip.displacement.y();
  std::printf("P-delta: root moment %.3f N·m, equilibrium %.3f N·m (linear theory %.3f)\n",
              solved.result.nodes.front().moment.z(), root_moment, lateral * kRodLength);
  EXPECT_NEAR(solved.result.nodes.front().moment.z(), root_moment, 2e-3 * root_moment);

  const model::SystemModel& system = solved.built.system;
  const VecX& q = solved.result.q;
  const auto forces = model::ComputeInternalForces(solved.built, q);
  const auto joints = model::JointInternalForces(solved.built, q, VecX::Zero(system.num_velocities()));
  const auto poses = system.Poses(q);
  const fe::Mat12 stiffness =
      fe::ElementStiffness(fe::BodyElementProperties(system.bodies()[0].reduced->spec), fe::BeamTheory::kEulerBernoulli);
  for (std::size_t j = 0; j < joints.size(); ++j) {
    const model::Body& body = system.bodies()[j];
    const double tolerance = compression * (std::abs(joints[j].moment.z()) / ei) * h;
    EXPECT_NEAR(forces[j].back().force.y(), joints[j].force.y(), tolerance) << "joint " << j;
    EXPECT_NEAR(forces[j].back().moment.z(), joints[j].moment.z(), 5e-3 * std::abs(joints[j].moment.z())) << "joint " << j;
    // The elastic part alone (K_e d of the body's last element) misses the geometric term.
    const VecX d = body.reduced->mode_shapes * poses[j].eta;
    const Eigen::Matrix<double, 12, 1> elastic = stiffness * d.segment<12>(d.size() - 12);
    EXPECT_GT(std::abs(elastic[7] - joints[j].force.y()), 2 * tolerance) << "joint " << j;
  }
}

}  // namespace internal_forces_test
}  // namespace drillflex::analyses
