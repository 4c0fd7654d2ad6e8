// Stiff viscous-elastic springs on the kinematics of model/coupling_kinematics.hpp:
//  * CouplingElement joins the end node of one body to the start node of the next (method.md §5);
//  * SupportElement holds a node to its reference place and orientation in chosen directions of the
//    string frame (a penalty support: `supports` of the case).
// Force f = K e + C ė with diagonal K, C in side 1's frame (axial x, lateral y, z, torsion,
// bending y, z); generalized force Bᵀ f; tangent Bᵀ K B + H(f), damping Bᵀ C B. The parameter
// block scales K by a factor s and C by √s, keeping the damping ratio (LoadParameters: the
// couplings' coupling_factor, the bit's supports' bit_support_factor).
#pragma once

#include "model/coupling_kinematics.hpp"
#include "model/force_element.hpp"

namespace drillflex::model {

class CouplingElement : public ForceElement {
 public:
  // `placement_kink`: the relative rotation (rotation vector, lower body frame) of the two bodies in
  // their reference placement along a curved well. It is taken as stress-free at load factor 0 and
  // fades linearly with the load factor, so that the placement is an equilibrium where the static
  // continuation starts and the straight pipe's bending is fully felt at load factor 1.
  CouplingElement(const Body* lower, Index lower_node, const Body* upper, Index upper_node, const Vec6& stiffness,
                  const Vec6& damping, const Mat3& built_in_rotation = Mat3::Identity(),
                  const Vec3& placement_kink = Vec3::Zero());
  std::string Describe() const override;
  const Vec6& stiffness() const { return stiffness_; }  // as built (factor 1)
  // The force f = K e + C ė (side-1 frame) at a state.
  Vec6 Force(const ElementState& state) const;

 protected:
  void DoEvaluate(const ElementState& state, bool with_matrices, ElementContribution& out) const override;
  double DoPotentialEnergy(const ElementState& state) const override;

 private:
  CouplingKinematics Kinematics(const ElementState& state) const;
  Index lower_node_, upper_node_;
  Vec6 stiffness_, damping_;
  Mat3 built_in_rotation_;
  Vec3 placement_kink_;
};

class SupportElement : public ForceElement {
 public:
  // Holds `node` of `body` at `position` with the string frame `frame` (columns x, y, z);
  // stiffness and damping 0 in the free directions.
  // `holds_bit`: the node is the bit's (LoadParameters::bit_support_factor scales it).
  SupportElement(const Body* body, Index node, const Vec3& position, const Mat3& frame, const Vec6& stiffness,
                 const Vec6& damping, bool holds_bit = false);
  std::string Describe() const override;
  // The reaction the support exerts on the string, in the string frame (force N, moment N·m).
  Vec6 Reaction(const ElementState& state) const;
  Index node() const { return node_; }
  const Vec6& stiffness() const { return stiffness_; }  // as built (factor 1)
  bool holds_bit() const { return holds_bit_; }

 protected:
  void DoEvaluate(const ElementState& state, bool with_matrices, ElementContribution& out) const override;
  double DoPotentialEnergy(const ElementState& state) const override;

 private:
  CouplingKinematics Kinematics(const ElementState& state) const;
  double Factor(const ElementState& state) const { return holds_bit_ ? state.parameters.bit_support_factor : 1.0; }
  Index node_;
  BodyPose ground_;
  Vec6 stiffness_, damping_;
  bool holds_bit_ = false;
};

}  // namespace drillflex::model
