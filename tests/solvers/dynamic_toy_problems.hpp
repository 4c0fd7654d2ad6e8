// Toy problems for the time-integrator tests: no drill string, analytic residuals and matrices.
#pragma once

#include <cmath>
#include <functional>
#include <limits>
#include <vector>

#include "core/so3.hpp"
#include "core/types.hpp"
#include "solvers/problem.hpp"

namespace drillflex::solvers::testing {

// M a + D v + K q = 0 with constant matrices (kg, N·s/m, N/m): a linear oscillator of any size.
class LinearOscillator final : public Problem {
 public:
  LinearOscillator(MatX mass, MatX damping, MatX stiffness)
      : mass_(std::move(mass)), damping_(std::move(damping)), stiffness_(std::move(stiffness)) {}

  Index num_positions() const override { return mass_.rows(); }
  Index num_velocities() const override { return mass_.rows(); }
  VecX Increment(const VecX& q, const VecX& dv) const override { return q + dv; }
  VecX Residual(double, const VecX& q, const VecX& v, const VecX& a) const override {
    return mass_ * a + damping_ * v + stiffness_ * q;
  }
  SparseMat IterationMatrix(double, const VecX&, const VecX&, const VecX&, double cK, double cD,
                            double cM) const override {
    return MatX(cK * stiffness_ + cD * damping_ + cM * mass_).sparseView();
  }
  bool CanReuseIterationMatrix() const override { return true; }
  std::vector<Eigen::Index> CoordinateBlocks() const override { return blocks; }

  // The coordinate blocks CoordinateBlocks() reports (none unless set).
  std::vector<Eigen::Index> blocks;

  // ½ vᵀ M v + ½ qᵀ K q (J).
  double Energy(const VecX& q, const VecX& v) const {
    return 0.5 * v.dot(mass_ * v) + 0.5 * q.dot(stiffness_ * q);
  }
  const MatX& mass() const { return mass_; }
  const MatX& stiffness() const { return stiffness_; }

 private:
  MatX mass_, damping_, stiffness_;
};

// m ẍ + k x + k3 x³ = 0 (a hardening Duffing oscillator, N with x in m), with an optional
// `broken_above`: the residual turns NaN once |x| exceeds it (for the failure tests).
class DuffingOscillator final : public Problem {
 public:
  DuffingOscillator(double mass, double stiffness, double cubic_stiffness,
                    double broken_above = std::numeric_limits<double>::infinity())
      : mass_(mass), k_(stiffness), k3_(cubic_stiffness), broken_above_(broken_above) {}

  Index num_positions() const override { return 1; }
  Index num_velocities() const override { return 1; }
  VecX Increment(const VecX& q, const VecX& dv) const override { return q + dv; }
  VecX Residual(double, const VecX& q, const VecX&, const VecX& a) const override {
    const double x = q[0];
    if (std::abs(x) > broken_above_) return VecX::Constant(1, std::numeric_limits<double>::quiet_NaN());
    return VecX::Constant(1, mass_ * a[0] + k_ * x + k3_ * x * x * x);
  }
  SparseMat IterationMatrix(double, const VecX& q, const VecX&, const VecX&, double cK, double,
                            double cM) const override {
    SparseMat matrix(1, 1);
    matrix.insert(0, 0) = cK * (k_ + 3.0 * k3_ * q[0] * q[0]) + cM * mass_;
    return matrix;
  }
  // ½ m v² + ½ k x² + ¼ k3 x⁴ (J).
  double Energy(double x, double v) const { return 0.5 * mass_ * v * v + 0.5 * k_ * x * x + 0.25 * k3_ * std::pow(x, 4); }

 private:
  double mass_, k_, k3_, broken_above_;
};

// The kinetic, spring and gravity energy (J) of a SpringHeldRigidBody (toy_problems.hpp) at (q, v):
// ½ m |ẋ|² + ½ ωᵀ J ω + ½ k |x + R p − y|² − m g·x.
inline double RigidBodyEnergy(double mass, const Mat3& inertia, double stiffness, const Vec3& point_body,
                              const Vec3& anchor_world, const Vec3& gravity, const VecX& q, const VecX& v) {
  const Mat3 rotation = Quat(q[3], q[4], q[5], q[6]).toRotationMatrix();
  const Vec3 x = q.head<3>();
  const Vec3 stretch = x + rotation * point_body - anchor_world;
  const Vec3 omega = v.tail<3>();
  return 0.5 * mass * v.head<3>().squaredNorm() + 0.5 * omega.dot(inertia * omega) +
         0.5 * stiffness * stretch.squaredNorm() - mass * gravity.dot(x);
}

// The angular momentum about the world origin (N·m·s) of a rigid body at (q, v): R J ω + x × m ẋ.
inline Vec3 RigidBodyAngularMomentum(double mass, const Mat3& inertia, const VecX& q, const VecX& v) {
  const Mat3 rotation = Quat(q[3], q[4], q[5], q[6]).toRotationMatrix();
  const Vec3 x = q.head<3>();
  return rotation * (inertia * v.tail<3>()) + x.cross(mass * Vec3(v.head<3>()));
}

}  // namespace drillflex::solvers::testing
