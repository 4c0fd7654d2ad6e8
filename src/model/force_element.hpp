// Force elements: everything that puts a force on the bodies besides their own inertia and
// elasticity (couplings, supports, loads, gravity, contact, fluid). An element touches one or two
// bodies; it returns its contribution to the residual over the concatenated velocity blocks of
// those bodies, with its exact derivatives, and reports its potential energy.
//
// Sign: the residual is R = M a + f_int − f_ext, so an element adds f_int (a spring's restoring
// force) or −f_ext (an applied load) to `force`. The power it delivers to the system is −force·v.
#pragma once

#include <string>
#include <vector>

#include "model/body.hpp"
#include "model/load_parameters.hpp"

namespace drillflex::model {

struct ElementState {
  std::vector<const BodyPose*> poses;  // of the element's bodies, in order
  VecX velocity;                       // concatenated velocities of the element's bodies
  double time = 0.0;
  LoadParameters parameters;           // the loads, friction and stiffness factors (model/load_parameters.hpp)
};

struct ElementContribution {
  VecX force;      // added to the residual
  MatX stiffness;  // ∂force/∂(position increment)
  MatX damping;    // ∂force/∂v
  // False where the caller will not read `damping` (an iteration matrix with c_D = 0: statics): an
  // element may then leave it zero and skip its cost.
  bool damping_needed = true;
};

class ForceElement {
 public:
  virtual ~ForceElement() = default;

  const std::vector<const Body*>& bodies() const { return bodies_; }
  Index local_size() const { return local_size_; }

  // Checks sizes, then computes. Matrices only when `with_matrices` (else left empty).
  void Evaluate(const ElementState& state, bool with_matrices, ElementContribution& out) const;
  // Potential energy (J) of a conservative element; 0 for dissipative or non-conservative parts.
  double PotentialEnergy(const ElementState& state) const;
  // The change of the element's potential energy from one state to another (J), including the work
  // a dead load does against the motion between them (−W: a dead moment has no potential of its
  // own, but over a step its work −M·ψ, ψ the turn between the states, is what the static solver's
  // energy merit needs). Default: PotentialEnergy(to) − PotentialEnergy(from).
  double PotentialEnergyChange(const ElementState& from, const ElementState& to) const;
  // A unilateral penalty ½ k ⟨δ⟩² that the element's energy is (a wall contact): δ, k and ∂δ/∂v over
  // the element's local coordinates (`gradient`, local_size). False: the element has none.
  bool Penalty(const ElementState& state, double& value, double& stiffness, VecX& gradient) const;
  virtual std::string Describe() const = 0;

 protected:
  explicit ForceElement(std::vector<const Body*> bodies);
  virtual void DoEvaluate(const ElementState& state, bool with_matrices, ElementContribution& out) const = 0;
  virtual double DoPotentialEnergy(const ElementState& state) const = 0;
  virtual double DoPotentialEnergyChange(const ElementState& from, const ElementState& to) const {
    return DoPotentialEnergy(to) - DoPotentialEnergy(from);
  }
  virtual bool DoPenalty(const ElementState& /*state*/, double& /*value*/, double& /*stiffness*/,
                         VecX& /*gradient*/) const {
    return false;
  }

 private:
  std::vector<const Body*> bodies_;
  Index local_size_ = 0;
};

}  // namespace drillflex::model
