// Couplings far from the origin (model/coupling_kinematics.cpp, BodyPose): q holds each frame's
// displacement from its reference position, and a coupling's gap is formed from the reference and
// displacement differences. The same string at the same state near the origin and 4.7 km from it
// then has the same coupling strains; formed from the absolute origins r = reference +
// displacement, each rounded to its own unit of 4.5e-13 m, they would differ by up to that (~1 N in
// a c = 1000 drill-pipe coupling of 2e12 N/m).
#include <gtest/gtest.h>

#include <cstdio>
#include <random>

#include "model/coupling_kinematics.hpp"
#include "model_test_support.hpp"

namespace drillflex::model {
namespace far_origin_test {

TEST(FarOrigin, CouplingStrainsDoNotDependOnWhereTheStringIs) {
  cms::ReductionCache cache;
  const BuiltModel built = BuildSystemModel(testing::RodInput(6, 4, 4), cache);
  const std::vector<Body>& near = built.system.bodies();
  // The same string 4.7 km from the origin: every component of every frame origin large.
  const Vec3 far_away(3600.123456789, -2500.987654321, 1800.555555557);  // m
  std::vector<Body> far = near;
  for (Body& body : far) body.reference_position += far_away;
  auto strains = [](const std::vector<Body>& bodies, const VecX& state) {
    std::vector<Vec6> out;
    for (std::size_t b = 0; b + 1 < bodies.size(); ++b) {
      const CouplingEnd lower{&bodies[b], bodies[b].node_count() - 1, PoseOf(bodies[b], state)};
      const CouplingEnd upper{&bodies[b + 1], 0, PoseOf(bodies[b + 1], state)};
      out.push_back(ComputeCouplingKinematics(lower, upper).strain);
    }
    return out;
  };
  // Deformed states (each frame displaced and turned its own way): the strains are a matter of the
  // string's shape alone. Formed from the absolute origins, each rounded to its own unit of
  // 4.5e-13 m far away, the gaps would differ by up to that.
  // Each string's strains are taken from its own rest state: the far references carry their own
  // rounding (their gaps differ from the near ones by up to 4.5e-13 m, a constant of the model).
  const VecX rest = built.system.ReferencePositions();
  const std::vector<Vec6> near_rest = strains(near, rest), far_rest = strains(far, rest);
  std::mt19937 rng(5);
  double largest = 0.0, largest_strain = 0.0;
  for (int trial = 0; trial < 20; ++trial) {
    const VecX q = testing::PerturbedPositions(built.system, rng, 1e-2);
    const std::vector<Vec6> a = strains(near, q), b = strains(far, q);
    for (std::size_t c = 0; c < a.size(); ++c) {
      largest = std::max(largest, ((a[c] - near_rest[c]) - (b[c] - far_rest[c])).cwiseAbs().maxCoeff());
      largest_strain = std::max(largest_strain, a[c].cwiseAbs().maxCoeff());
    }
  }
  std::printf("20 deformed states: largest strain %.3e, largest change when 4.7 km away %.3e m\n", largest_strain,
              largest);
  ASSERT_GT(largest_strain, 1e-4);  // the states do strain the couplings
  // Only the round-off of the metre-sized offsets (ε × 2.5 m) and the constant reference error
  // turned by the frames' rotations (4.5e-13 m × 1e-2 rad).
  EXPECT_LT(largest, 2e-14);
}

}  // namespace far_origin_test
}  // namespace drillflex::model
