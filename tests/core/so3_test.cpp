#include "core/so3.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace drillflex::so3 {
namespace so3_test {

Vec3 RandomVector(std::mt19937& rng, double scale) {
  std::uniform_real_distribution<double> u(-scale, scale);
  return Vec3(u(rng), u(rng), u(rng));
}

TEST(So3, SkewIsCrossProduct) {
  const Vec3 a(1.0, -2.0, 3.0), b(-0.5, 4.0, 2.0);
  EXPECT_LT((Skew(a) * b - a.cross(b)).norm(), 1e-15);
  EXPECT_LT((Vee(Skew(a)) - a).norm(), 1e-15);
}

TEST(So3, ExpMatchesAngleAxis) {
  std::mt19937 rng(7);
  for (int i = 0; i < 100; ++i) {
    const Vec3 theta = RandomVector(rng, 3.0);
    const Mat3 expected = Eigen::AngleAxisd(theta.norm(), theta.normalized()).toRotationMatrix();
    EXPECT_LT((ExpMap(theta) - expected).norm(), 1e-13);
    EXPECT_LT((QuatFromRotationVector(theta).toRotationMatrix() - expected).norm(), 1e-13);
  }
  EXPECT_LT((ExpMap(Vec3(1e-9, 0, 0)) - Mat3::Identity()).norm(), 1e-8);
}

TEST(So3, LogInvertsExp) {
  std::mt19937 rng(11);
  for (int i = 0; i < 100; ++i) {
    Vec3 theta = RandomVector(rng, 1.0);
    theta *= (kPi * 0.999) / std::max(theta.norm(), 1.0) ;
    EXPECT_LT((LogMap(ExpMap(theta)) - theta).norm(), 1e-12);
    EXPECT_LT((RotationVectorFromQuat(QuatFromRotationVector(theta)) - theta).norm(), 1e-12);
  }
}

TEST(So3, TangentOperatorMatchesFiniteDifference) {
  // ω_body = T(θ) θ̇ where skew(ω_body) = Rᵀ Ṙ.
  std::mt19937 rng(3);
  for (int i = 0; i < 20; ++i) {
    const Vec3 theta = RandomVector(rng, 2.0);
    const Vec3 rate = RandomVector(rng, 1.0);
    const double h = 1e-6;
    const Mat3 r_dot = (ExpMap(theta + h * rate) - ExpMap(theta - h * rate)) / (2.0 * h);
    const Vec3 omega = Vee(ExpMap(theta).transpose() * r_dot);
    EXPECT_LT((TangentOperator(theta) * rate - omega).norm(), 1e-8);
  }
}

TEST(So3, ThousandRevolutionsAndBackReturnToStart) {
  // A body spun through 1000 revolutions in small increments, then back, returns to its start.
  const Quat start = QuatFromRotationVector(Vec3(0.3, -0.2, 0.5));
  const Vec3 axis = Vec3(0.2, 0.9, -0.4).normalized();
  const int steps = 100000;
  const Vec3 increment = axis * (1000.0 * 2.0 * kPi / steps);
  Quat q = start;
  for (int i = 0; i < steps; ++i) q = Compose(q, increment);
  EXPECT_LT((q.toRotationMatrix() - start.toRotationMatrix()).norm(), 1e-9);
  for (int i = 0; i < steps; ++i) q = Compose(q, -increment);
  EXPECT_LT((q.toRotationMatrix() - start.toRotationMatrix()).norm(), 1e-10);
}

}  // namespace so3_test
}  // namespace drillflex::so3
