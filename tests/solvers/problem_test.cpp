// FiniteDifferenceIterationMatrix against analytic Jacobians of toy problems, and
// RelativeMatrixError.
#include "solvers/problem.hpp"

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "core/so3.hpp"
#include "toy_problems.hpp"

namespace drillflex::solvers {
namespace problem_test {

using testing::SpringChain;
using testing::SpringHeldRigidBody;

// A spinning, tilted body away from its equilibrium: every block of K, D, M is non-zero and K is
// unsymmetric.
struct RigidBodyCase {
  SpringHeldRigidBody body{2.5,
                           Vec3(0.3, 0.5, 0.7).asDiagonal().toDenseMatrix() +
                               0.05 * (Mat3() << 0, 1, 0, 1, 0, 1, 0, 1, 0).finished(),
                           400.0,
                           Vec3(0.2, -0.1, 0.3),
                           Vec3(0.5, 0.4, -0.2),
                           Vec3(0.0, 0.0, -9.81)};
  VecX q = VecX(7);
  VecX v = VecX(6);
  VecX a = VecX(6);
  RigidBodyCase() {
    const Quat r = so3::QuatFromRotationVector(Vec3(0.7, -1.2, 2.1));
    q << 0.1, -0.3, 0.25, r.w(), r.x(), r.y(), r.z();
    v << 0.3, -0.2, 0.1, 4.0, -7.0, 11.0;
    a << 1.0, 2.0, -3.0, 5.0, -2.0, 0.5;
  }
};

TEST(FiniteDifferenceIterationMatrix, MatchesRotatingRigidBodyJacobianBlockByBlock) {
  const RigidBodyCase c;
  // K alone, D alone, M alone, then a time-integrator-like combination.
  const double coefficients[4][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1.0, 2.0e2, 4.0e4}};
  for (const auto& coefficient : coefficients) {
    const SparseMat analytic = c.body.IterationMatrix(0.0, c.q, c.v, c.a, coefficient[0],
                                                      coefficient[1], coefficient[2]);
    const SparseMat numeric = FiniteDifferenceIterationMatrix(
        c.body, 0.0, c.q, c.v, c.a, coefficient[0], coefficient[1], coefficient[2]);
    // Central differences with h = 1e-6: truncation ~h² and round-off ~1e-16 |R| / h ~ 1e-9.
    EXPECT_LT(RelativeMatrixError(analytic, numeric), 1e-7)
        << "cK, cD, cM = " << coefficient[0] << ", " << coefficient[1] << ", " << coefficient[2];
  }
}

TEST(FiniteDifferenceIterationMatrix, DetectsAWrongRotationalStiffness) {
  // The same body with the K_θθ block expressed in the wrong frame (right-multiplied by Rᵀ): a
  // frame mix-up the check must catch.
  const RigidBodyCase c;
  MatX k_wrong = MatX(c.body.IterationMatrix(0.0, c.q, c.v, c.a, 1, 0, 0));
  const Mat3 rotation = SpringHeldRigidBody::Orientation(c.q).toRotationMatrix();
  k_wrong.block<3, 3>(3, 3) = k_wrong.block<3, 3>(3, 3) * rotation.transpose();
  const SparseMat numeric = FiniteDifferenceIterationMatrix(c.body, 0.0, c.q, c.v, c.a, 1, 0, 0);
  EXPECT_GT(RelativeMatrixError(MatX(numeric), k_wrong), 1e-3);
}

TEST(FiniteDifferenceIterationMatrix, MatchesSpringChainStiffness) {
  SpringChain chain(6, 1.0e3, 5.0e4, 10.0);
  VecX q(6);
  q << 0.01, 0.05, 0.02, 0.11, 0.2, 0.16;
  const VecX zero = VecX::Zero(6);
  const SparseMat analytic = chain.IterationMatrix(0.0, q, zero, zero, 1.0, 0.0, 0.0);
  const SparseMat numeric = FiniteDifferenceIterationMatrix(chain, 0.0, q, zero, zero, 1, 0, 0);
  EXPECT_LT(RelativeMatrixError(analytic, numeric), 1e-8);
  // Entries off the tridiagonal band stay (exactly) zero: a perturbation of q_j only changes
  // the forces of the springs next to node j.
  EXPECT_EQ(MatX(numeric).cwiseAbs().topRightCorner(2, 2).maxCoeff(), 0.0);
}

TEST(FiniteDifferenceIterationMatrix, RejectsWrongSizes) {
  SpringChain chain(3, 1.0, 1.0, 1.0);
  EXPECT_THROW(FiniteDifferenceIterationMatrix(chain, 0.0, VecX::Zero(2), VecX::Zero(3),
                                               VecX::Zero(3), 1, 0, 0),
               LogicError);
}

TEST(RelativeMatrixError, IsFrobeniusDifferenceOverLargerNorm) {
  MatX a(2, 2), b(2, 2);
  a << 3, 0, 0, 4;  // ‖a‖_F = 5
  b << 3, 0, 0, 4.5;
  EXPECT_NEAR(RelativeMatrixError(a, b), 0.5 / b.norm(), 1e-15);
  EXPECT_NEAR(RelativeMatrixError(SparseMat(a.sparseView()), SparseMat(b.sparseView())),
              0.5 / b.norm(), 1e-15);
  EXPECT_EQ(RelativeMatrixError(MatX::Zero(2, 2), MatX::Zero(2, 2)), 0.0);
  EXPECT_THROW(RelativeMatrixError(MatX::Zero(2, 2), MatX::Zero(3, 3)), LogicError);
}

}  // namespace problem_test
}  // namespace drillflex::solvers
