// The stationary-frame gyroscopic moments (model/gyroscopic_element.hpp): the element's stiffness
// and damping against central differences of its own residual at bent, moving states; the
// assembled gyroscopic matrix G against the elements' forces and its skew symmetry (no work); and
// the moment of a rigid spinning rod whose axis tilts, Ω J_p (e_x × w), against the rod's polar
// moment of inertia ρ (π D⁴/32) L.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>

#include "element_problem.hpp"
#include "model/gyroscopic_element.hpp"
#include "model_test_support.hpp"

namespace drillflex::model {
namespace gyroscopic_element_test {

using testing::RodInput;

// The rod's bodies with one GyroscopicElement each at the spin rate (rad/s).
SystemModel SpinningRod(const SystemModel& rod, double spin) {
  std::vector<Body> bodies = rod.bodies();
  std::vector<std::unique_ptr<ForceElement>> elements;
  for (const Body& body : bodies) elements.push_back(std::make_unique<GyroscopicElement>(&body, spin));
  return SystemModel(std::move(bodies), std::move(elements), rod.length());
}

TEST(GyroscopicElement, MatricesMatchCentralDifferencesOfItsResidual) {
  cms::ReductionCache cache;
  const BuiltModel built = BuildSystemModel(RodInput(3, 4, 5), cache);
  const SystemModel model = SpinningRod(built.system, 150.0);
  std::mt19937 rng(11);
  for (int trial = 0; trial < 3; ++trial) {
    const VecX q = testing::SpunPositions(model, 0.7 * trial, 0.05, rng);
    const VecX v = testing::SpinningVelocities(model, 3.0, 2.0, rng);
    for (int e = 0; e < static_cast<int>(model.elements().size()); ++e) {
      const testing::ElementProblem problem(model, e);
      const testing::Errors errors = testing::JacobianErrors(problem, 0.0, q, v);
      EXPECT_LT(errors.stiffness, 1e-6) << "trial " << trial << ", body " << e;
      EXPECT_LT(errors.damping, 1e-6) << "trial " << trial << ", body " << e;
    }
  }
}

TEST(GyroscopicElement, AssembledMatrixIsTheElementsForcePerSpinAndDoesNoWork) {
  cms::ReductionCache cache;
  const BuiltModel built = BuildSystemModel(RodInput(3, 4, 5), cache);
  constexpr double kSpin = 40.0;
  const SystemModel model = SpinningRod(built.system, kSpin);
  std::mt19937 rng(5);
  const VecX q = testing::SpunPositions(model, 0.4, 0.05, rng);
  const VecX v = testing::SpinningVelocities(model, 0.0, 1.0, rng);
  const SparseMat gyroscopic = ComputeGyroscopicMatrix(model, q);
  VecX element_forces = VecX::Zero(v.size());
  const auto poses = model.Poses(q);
  for (const auto& element : model.elements()) {
    ElementContribution c;
    element->Evaluate(model.StateOf(*element, poses, v, 0.0, 1.0), false, c);
    const Body& body = *element->bodies()[0];
    element_forces.segment(body.v_offset, body.velocity_count()) += c.force;
  }
  EXPECT_LT((kSpin * (gyroscopic * v) - element_forces).norm(), 1e-12 * element_forces.norm());
  EXPECT_GT(element_forces.norm(), 0.0);
  EXPECT_LT(SparseMat(gyroscopic + SparseMat(gyroscopic.transpose())).norm(), 1e-14 * gyroscopic.norm());
  EXPECT_NEAR(v.dot(gyroscopic * v), 0.0, 1e-12 * v.squaredNorm() * gyroscopic.norm());
}

TEST(GyroscopicElement, RigidRodTiltingCarriesThePolarMomentOfInertia) {
  cms::ReductionCache cache;
  const BuiltModel built = BuildSystemModel(RodInput(1, 10, 4), cache);
  constexpr double kSpin = 100.0;  // rad/s, about −x (clockwise looking down-hole)
  const SystemModel model = SpinningRod(built.system, kSpin);
  const VecX q = model.ReferencePositions();
  VecX v = VecX::Zero(model.num_velocities());
  const Vec3 tilt(0.0, 0.3, -0.2);  // the axis tilts at w (body frame), rad/s
  v.segment<3>(3) = tilt;
  ElementContribution c;
  const auto poses = model.Poses(q);
  model.elements()[0]->Evaluate(model.StateOf(*model.elements()[0], poses, v, 0.0, 1.0), false, c);
  // d/dt (J_p Ω a) with a = −e_x turning at w: J_p Ω (w × a) = J_p Ω (e_x × w).
  const double diameter = 0.0762, length = 5.08, density = 7800.0;
  const double polar = density * kPi * std::pow(diameter, 4) / 32.0 * length;
  const Vec3 expected = polar * kSpin * Vec3::UnitX().cross(tilt);
  EXPECT_LT((c.force.segment<3>(3) - expected).norm(), 1e-9 * expected.norm());
  EXPECT_EQ(c.force.head<3>().norm(), 0.0);
}

}  // namespace gyroscopic_element_test
}  // namespace drillflex::model
