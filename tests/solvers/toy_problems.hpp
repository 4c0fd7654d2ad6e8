// Toy problems for the solver tests: no drill string, analytic residuals and Jacobians.
#pragma once

#include <cmath>
#include <vector>

#include "core/so3.hpp"
#include "core/types.hpp"
#include "solvers/problem.hpp"

namespace drillflex::solvers::testing {

// A chain of n masses on a line, node 0 fixed, spring i between nodes i−1 and i with the force
// f(e) = k e + k3 e³ (N) for the elongation e (m), and a tip load λ·P (N). Statics:
// R_i = f(e_i) − f(e_{i+1}) − δ_{in} λ P. Every spring carries P at equilibrium, so q_i = i·e*
// with f(e*) = P.
class SpringChain final : public StaticProblem {
 public:
  SpringChain(int n, double k, double k3, double tip_load)
      : n_(n), k_(k), k3_(k3), tip_load_(tip_load) {}

  Index num_positions() const override { return n_; }
  Index num_velocities() const override { return n_; }
  VecX Increment(const VecX& q, const VecX& dv) const override { return q + dv; }

  VecX Residual(double, const VecX& q, const VecX&, const VecX&) const override {
    VecX r = VecX::Zero(n_);
    for (int i = 0; i < n_; ++i) {
      const double force = SpringForce(Elongation(q, i));
      r[i] += force;
      if (i > 0) r[i - 1] -= force;
    }
    r[n_ - 1] -= load_factor_ * tip_load_;
    return r;
  }

  SparseMat IterationMatrix(double, const VecX& q, const VecX&, const VecX&, double cK, double,
                            double) const override {
    std::vector<Triplet> triplets;
    for (int i = 0; i < n_; ++i) {
      const double stiffness = cK * (k_ + 3.0 * k3_ * std::pow(Elongation(q, i), 2));
      triplets.emplace_back(i, i, stiffness);
      if (i > 0) {
        triplets.emplace_back(i - 1, i - 1, stiffness);
        triplets.emplace_back(i - 1, i, -stiffness);
        triplets.emplace_back(i, i - 1, -stiffness);
      }
    }
    SparseMat matrix(n_, n_);
    matrix.setFromTriplets(triplets.begin(), triplets.end());
    return matrix;
  }

  void SetLoadFactor(double load_factor) override { load_factor_ = load_factor; }
  double SpringForce(double e) const { return k_ * e + k3_ * e * e * e; }

 private:
  double Elongation(const VecX& q, int i) const { return q[i] - (i > 0 ? q[i - 1] : 0.0); }

  int n_;
  double k_, k3_, tip_load_;
  double load_factor_ = 1.0;
};

// The von Mises truss: two bars (axial stiffness EA, N) from (±b, 0) to an apex at height h − w,
// w the downward apex displacement (m), vertical load λ·P (N) at the apex. With s = h − w and
// L = √(b² + s²), the bar force is EA (L0 − L)/L0 (compression positive) and equilibrium reads
// R(w) = 2 EA s (1/L − 1/L0) − λ P (e.g. Crisfield, "Non-linear Finite Element Analysis of
// Solids and Structures", vol. 1, §1.2, with engineering strain).
class VonMisesTruss final : public StaticProblem {
 public:
  VonMisesTruss(double axial_stiffness, double half_span, double height, double load)
      : ea_(axial_stiffness), b_(half_span), h_(height), load_(load) {}

  Index num_positions() const override { return 1; }
  Index num_velocities() const override { return 1; }
  VecX Increment(const VecX& q, const VecX& dv) const override { return q + dv; }

  VecX Residual(double, const VecX& q, const VecX&, const VecX&) const override {
    return VecX::Constant(1, InternalForce(q[0]) - load_factor_ * load_);
  }

  SparseMat IterationMatrix(double, const VecX& q, const VecX&, const VecX&, double cK, double,
                            double) const override {
    // dR/dw = −dF/ds with dF/ds = 2 EA (b²/L³ − 1/L0).
    const double s = h_ - q[0];
    const double length = std::hypot(b_, s);
    SparseMat matrix(1, 1);
    matrix.insert(0, 0) = -cK * 2.0 * ea_ * (b_ * b_ / std::pow(length, 3) - 1.0 / InitialLength());
    return matrix;
  }

  void SetLoadFactor(double load_factor) override { load_factor_ = load_factor; }

  double InitialLength() const { return std::hypot(b_, h_); }
  // The load the truss carries at apex displacement w (N).
  double InternalForce(double w) const {
    const double s = h_ - w;
    return 2.0 * ea_ * s * (1.0 / std::hypot(b_, s) - 1.0 / InitialLength());
  }
  // The limit load: dF/ds = 0 at L = (b² L0)^{1/3}.
  double LimitLoad() const {
    const double length = std::cbrt(b_ * b_ * InitialLength());
    const double s = std::sqrt(length * length - b_ * b_);
    return 2.0 * ea_ * s * (1.0 / length - 1.0 / InitialLength());
  }

 private:
  double ea_, b_, h_, load_;
  double load_factor_ = 1.0;
};

// One-DOF problems R(q) given by two functions (residual and its derivative), for failure tests.
template <typename ResidualFn, typename DerivativeFn>
class ScalarProblem final : public StaticProblem {
 public:
  ScalarProblem(ResidualFn residual, DerivativeFn derivative)
      : residual_(residual), derivative_(derivative) {}

  Index num_positions() const override { return 1; }
  Index num_velocities() const override { return 1; }
  VecX Increment(const VecX& q, const VecX& dv) const override { return q + dv; }
  VecX Residual(double, const VecX& q, const VecX&, const VecX&) const override {
    return VecX::Constant(1, residual_(q[0], load_factor_));
  }
  SparseMat IterationMatrix(double, const VecX& q, const VecX&, const VecX&, double cK, double,
                            double) const override {
    SparseMat matrix(1, 1);
    matrix.insert(0, 0) = cK * derivative_(q[0], load_factor_);
    return matrix;
  }
  void SetLoadFactor(double load_factor) override { load_factor_ = load_factor; }

 private:
  ResidualFn residual_;
  DerivativeFn derivative_;
  double load_factor_ = 1.0;
};

// A free rigid body (mass m, body-frame inertia J) held by a spring of stiffness k between a
// body point p (body frame) and a world anchor y, under gravity. q = (x, quaternion w x y z):
// 7 positions; v = (ẋ world, ω body): 6 velocities; Increment: x + dx, q · exp(dθ/2).
//   R_trans = m a − F − m g,               F = −k (x + R p − y)
//   R_rot   = J α + ω × J ω − τ,           τ = p × Rᵀ F = −k p × Rᵀ(x − y)   (body frame)
class SpringHeldRigidBody final : public Problem {
 public:
  SpringHeldRigidBody(double mass, const Mat3& inertia, double stiffness, const Vec3& point_body,
                      const Vec3& anchor_world, const Vec3& gravity)
      : mass_(mass), inertia_(inertia), k_(stiffness), p_(point_body), y_(anchor_world),
        g_(gravity) {}

  Index num_positions() const override { return 7; }
  Index num_velocities() const override { return 6; }

  static Quat Orientation(const VecX& q) { return Quat(q[3], q[4], q[5], q[6]); }

  VecX Increment(const VecX& q, const VecX& dv) const override {
    VecX out(7);
    out.head<3>() = q.head<3>() + dv.head<3>();
    const Quat r = so3::Compose(Orientation(q), dv.tail<3>());
    out.tail<4>() << r.w(), r.x(), r.y(), r.z();
    return out;
  }

  VecX Residual(double, const VecX& q, const VecX& v, const VecX& a) const override {
    const Mat3 rotation = Orientation(q).toRotationMatrix();
    const Vec3 x = q.head<3>();
    const Vec3 force = -k_ * (x + rotation * p_ - y_);
    const Vec3 torque = p_.cross(rotation.transpose() * force);
    const Vec3 omega = v.tail<3>();
    VecX r(6);
    r.head<3>() = mass_ * a.head<3>() - force - mass_ * g_;
    r.tail<3>() = inertia_ * a.tail<3>() + omega.cross(inertia_ * omega) - torque;
    return r;
  }

  SparseMat IterationMatrix(double, const VecX& q, const VecX& v, const VecX&, double cK,
                            double cD, double cM) const override {
    const Mat3 rotation = Orientation(q).toRotationMatrix();
    const Vec3 relative_body = rotation.transpose() * (q.head<3>() - y_);
    const Mat3 skew_p = so3::Skew(p_);
    MatX k = MatX::Zero(6, 6);  // derivation in the class comment of the test
    k.block<3, 3>(0, 0) = k_ * Mat3::Identity();
    k.block<3, 3>(0, 3) = -k_ * rotation * skew_p;
    k.block<3, 3>(3, 0) = k_ * skew_p * rotation.transpose();
    k.block<3, 3>(3, 3) = k_ * skew_p * so3::Skew(relative_body);
    const Vec3 omega = v.tail<3>();
    MatX d = MatX::Zero(6, 6);
    d.block<3, 3>(3, 3) = so3::Skew(omega) * inertia_ - so3::Skew(inertia_ * omega);
    MatX m = MatX::Zero(6, 6);
    m.block<3, 3>(0, 0) = mass_ * Mat3::Identity();
    m.block<3, 3>(3, 3) = inertia_;
    return (cK * k + cD * d + cM * m).sparseView();
  }

 private:
  double mass_;
  Mat3 inertia_;
  double k_;
  Vec3 p_, y_, g_;
};

// Tridiagonal stiffness of a spring chain (k between neighbours) with node 0 fixed (fixed–free)
// or no support at all (free–free), n nodes.
inline SparseMat ChainStiffness(int n, double k, bool fixed_start) {
  std::vector<Triplet> triplets;
  for (int i = 0; i < n; ++i) {
    // The spring to the left of node i (to the wall for i = 0 when fixed).
    if (i > 0) {
      triplets.emplace_back(i, i, k);
      triplets.emplace_back(i - 1, i - 1, k);
      triplets.emplace_back(i, i - 1, -k);
      triplets.emplace_back(i - 1, i, -k);
    } else if (fixed_start) {
      triplets.emplace_back(0, 0, k);
    }
  }
  SparseMat matrix(n, n);
  matrix.setFromTriplets(triplets.begin(), triplets.end());
  return matrix;
}

inline SparseMat ScaledIdentity(int n, double value) {
  SparseMat matrix(n, n);
  matrix.setIdentity();
  return value * matrix;
}

// diag(a, b) as one sparse matrix.
inline SparseMat BlockDiagonal(const SparseMat& a, const SparseMat& b) {
  std::vector<Triplet> triplets;
  for (int col = 0; col < a.outerSize(); ++col) {
    for (SparseMat::InnerIterator it(a, col); it; ++it) {
      triplets.emplace_back(it.row(), it.col(), it.value());
    }
  }
  for (int col = 0; col < b.outerSize(); ++col) {
    for (SparseMat::InnerIterator it(b, col); it; ++it) {
      triplets.emplace_back(it.row() + a.rows(), it.col() + a.cols(), it.value());
    }
  }
  SparseMat matrix(a.rows() + b.rows(), a.cols() + b.cols());
  matrix.setFromTriplets(triplets.begin(), triplets.end());
  return matrix;
}

}  // namespace drillflex::solvers::testing
