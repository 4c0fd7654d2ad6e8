// The drives of model/drives.hpp as force elements on the top node k of the string.
//
// TopDriveElement, speed: a stiff viscous-elastic torsional spring between the node and a frame
// G(t) = F Rx(ψ(t)) that turns with the drive (F: the node's reference frame, ψ(t) = −∫ speed dt
// about the string's x axis: clockwise looking down-hole is about −x). With the node frame A (the
// body frame; the node's small elastic rotation Ψ_k η added as in model/coupling_kinematics.hpp):
//   R = Gᵀ A,  e = e_xᵀ vee(skew(R)) + e_xᵀ Ψ_k η   (the twist of the node behind the drive, rad),
//   ė = e_xᵀ g2 ω + e_xᵀ Ψ_k η̇ + ψ̇ e_xᵀ g1 e_x,  g2 = ½ (tr R I − Rᵀ),  g1 = −½ (tr R I − R)
// (δR = R skew(δθ) for a body increment δθ, δR = −skew(δφ) R for a turn δφ of G in its own frame:
// the coupling kinematics' ∂vee/∂θ with R0 = I). The torque τ = k e + c ė acts through
// b = ∂ė/∂v = [0; g2ᵀ e_x; Ψ_kᵀ e_x], residual += τ b. Exact tangent (δ tr R = −2 vee(skew R)ᵀ δθ,
// δ(Rᵀ) = −skew(δθ) Rᵀ, with vee_r = vee(skew(R))):
//   ∂/∂q (τ b) = b (k b + c s)ᵀ + τ ∂b/∂q,  ∂b_ω/∂θ = −e_x vee_rᵀ + ½ R skew(e_x),
//   s_θ = ∂ė/∂θ = −ω_x vee_r + ½ (Rᵀ ω) × e_x + ψ̇ (vee_r + ½ e_x × Rᵀ e_x),
// damping ∂(τ b)/∂v = c b bᵀ. G(t) is built from cos ψ, sin ψ of the drive's total angle, so the
// frame stays on the rotation group however many turns the drive makes, and R stays a small
// rotation (the lag of the top behind the drive); the twist measure e_x·vee(skew R) = sin(lag)
// for a pure lag, which is the lag itself to 1e-7 at the lags a stiff drive allows (< 1e-3 rad).
//
// TopDriveElement, torque: the moment −T(t) F e_x (about the fixed down-hole axis at the top),
// a dead moment with its geometric tangent (model/node_force.hpp).
//
// BlockElement, velocity: an axial spring along a = F e_x (up-hole, fixed in space) between the
// node and the point that travels z(t) = ∫ velocity dt from the node's reference place p:
//   e = a·(r_k − p) − z(t), ė = a·ṙ_k − ż(t), force on the node −(k e + c ė) a,
// with ∂F/∂r_k = −k a aᵀ, ∂F/∂ṙ_k = −c a aᵀ (model/node_force.hpp maps them exactly).
// BlockElement, hook load: the dead force H(t) a.
//
// The applied torque and hook load scale with the load factor; the springs do not (they are
// supports that move).
#pragma once

#include "model/drives.hpp"
#include "model/force_element.hpp"
#include "model/node_force.hpp"

namespace drillflex::model {

class TopDriveElement : public ForceElement {
 public:
  // `frame`: the node's reference frame (columns: string frame x up-hole, y, z; global).
  // `stiffness` (N·m/rad) and `damping` (N·m·s/rad) of the speed drive's spring (unused for torque).
  TopDriveElement(const Body* body, Index node, const Mat3& frame, const TopDrive& drive, double stiffness,
                  double damping);
  std::string Describe() const override;
  const TopDrive& drive() const { return drive_; }
  Index node() const { return node_; }
  // The drive's angle ∫ speed dt (rad, clockwise looking down-hole) at time t; 0 for a torque drive.
  double DriveAngle(double t) const;
  // The torque the drive puts on the string, N·m, clockwise looking down-hole.
  double Torque(const ElementState& state) const;
  // The twist e of the node behind the drive frame (speed drive), rad; 0 for a torque drive.
  double Lag(const ElementState& state) const;

 protected:
  void DoEvaluate(const ElementState& state, bool with_matrices, ElementContribution& out) const override;
  double DoPotentialEnergy(const ElementState& state) const override;

 private:
  struct Twist;
  Twist Kinematics(const ElementState& state) const;
  void EvaluateSpeed(const ElementState& state, bool with_matrices, ElementContribution& out) const;
  Index node_;
  Mat3 frame_;
  TopDrive drive_;
  double stiffness_, damping_;
};

class BlockElement : public ForceElement {
 public:
  // `position`, `frame`: the node's reference place and frame (global). Velocity: the line's
  // `stiffness` and `damping`, and its `preload` (N, tension), the force it carries where the top
  // is where the block has taken it: k e + c ė + preload, e the top's axial lag behind the block.
  BlockElement(const Body* body, Index node, const Vec3& position, const Mat3& frame, const BlockDrive& drive,
               double stiffness, double damping, double preload = 0.0);
  std::string Describe() const override;
  const BlockDrive& drive() const { return drive_; }
  // The axial force the block puts on the string, N (tension: pulling up-hole is positive).
  double HookLoad(const ElementState& state) const;

 protected:
  void DoEvaluate(const ElementState& state, bool with_matrices, ElementContribution& out) const override;
  double DoPotentialEnergy(const ElementState& state) const override;

 private:
  // k e + c ė + preload of the velocity drive's line (tension), N.
  double SpringForce(const NodeMotion& motion, double t) const;
  Index node_;
  Vec3 position_, axis_;
  BlockDrive drive_;
  double stiffness_, damping_, preload_;
};

}  // namespace drillflex::model
