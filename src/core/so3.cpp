#include "core/so3.hpp"

#include <cmath>

namespace drillflex::so3 {

Mat3 Skew(const Vec3& a) {
  Mat3 s;
  s << 0.0, -a.z(), a.y(),
       a.z(), 0.0, -a.x(),
       -a.y(), a.x(), 0.0;
  return s;
}

Vec3 Vee(const Mat3& m) {
  return 0.5 * Vec3(m(2, 1) - m(1, 2), m(0, 2) - m(2, 0), m(1, 0) - m(0, 1));
}

Mat3 ExpMap(const Vec3& theta) {
  const double angle2 = theta.squaredNorm();
  const Mat3 s = Skew(theta);
  double a = 0.0;  // sin|θ|/|θ|
  double b = 0.0;  // (1 - cos|θ|)/|θ|²
  if (angle2 < 1e-8) {
    a = 1.0 - angle2 / 6.0;
    b = 0.5 - angle2 / 24.0;
  } else {
    const double angle = std::sqrt(angle2);
    a = std::sin(angle) / angle;
    b = (1.0 - std::cos(angle)) / angle2;
  }
  return Mat3::Identity() + a * s + b * s * s;
}

Vec3 LogMap(const Mat3& rotation) {
  return RotationVectorFromQuat(Quat(rotation));
}

Quat QuatFromRotationVector(const Vec3& theta) {
  const double angle = theta.norm();
  const double half = 0.5 * angle;
  // sin(|θ|/2)/|θ| with its Taylor series near zero.
  const double k = angle < 1e-6 ? 0.5 - angle * angle / 48.0 : std::sin(half) / angle;
  return Quat(std::cos(half), k * theta.x(), k * theta.y(), k * theta.z());
}

Vec3 RotationVectorFromQuat(const Quat& q_in) {
  Quat q = q_in.normalized();
  if (q.w() < 0.0) q.coeffs() = -q.coeffs();  // shortest rotation
  const Vec3 v = q.vec();
  const double s = v.norm();
  if (s < 1e-12) return 2.0 * v;
  const double angle = 2.0 * std::atan2(s, q.w());
  return (angle / s) * v;
}

Quat Compose(const Quat& q, const Vec3& delta_theta_body) {
  Quat r = q * QuatFromRotationVector(delta_theta_body);
  r.normalize();
  return r;
}

Mat3 TangentOperator(const Vec3& theta) {
  const double angle2 = theta.squaredNorm();
  const Mat3 s = Skew(theta);
  double b = 0.0;  // (1 - cos|θ|)/|θ|²
  double c = 0.0;  // (|θ| - sin|θ|)/|θ|³
  if (angle2 < 1e-8) {
    b = 0.5 - angle2 / 24.0;
    c = 1.0 / 6.0 - angle2 / 120.0;
  } else {
    const double angle = std::sqrt(angle2);
    b = (1.0 - std::cos(angle)) / angle2;
    c = (angle - std::sin(angle)) / (angle2 * angle);
  }
  return Mat3::Identity() - b * s + c * s * s;
}

}  // namespace drillflex::so3
