// Rotations: skew matrices, the exponential and logarithm maps of SO(3), and the Lie-group update
// of a unit quaternion by a rotation-vector increment (q ⊕ Δθ = q · exp(Δθ/2)), which is never
// singular and keeps unbounded spin exact. Reference: Géradin & Cardona, "Flexible Multibody
// Dynamics", ch. 4.
#pragma once

#include "core/types.hpp"

namespace drillflex::so3 {

// skew(a) b = a × b.
Mat3 Skew(const Vec3& a);

// vee(S) = a for the skew-symmetric part S of a matrix: vee(skew(a)) = a.
Vec3 Vee(const Mat3& m);

// Rotation matrix exp(skew(theta)) of a rotation vector theta (rad): Rodrigues' formula, with a
// Taylor series near zero.
Mat3 ExpMap(const Vec3& theta);

// Rotation vector of a rotation matrix, |theta| in [0, π].
Vec3 LogMap(const Mat3& rotation);

// Unit quaternion of a rotation vector: (cos(|θ|/2), sin(|θ|/2) θ/|θ|).
Quat QuatFromRotationVector(const Vec3& theta);

// Rotation vector of a unit quaternion (the shortest one, |theta| ≤ π).
Vec3 RotationVectorFromQuat(const Quat& q);

// q ⊕ Δθ = q · exp(Δθ/2) with Δθ in the body frame; the result is renormalized.
Quat Compose(const Quat& q, const Vec3& delta_theta_body);

// Tangent operator T(θ) of the exponential map: the body angular velocity is ω = T(θ) θ̇ for
// R = exp(θ). T(θ) = I - (1-cos|θ|)/|θ|² skew(θ) + (|θ|-sin|θ|)/|θ|³ skew(θ)².
Mat3 TangentOperator(const Vec3& theta);

}  // namespace drillflex::so3
