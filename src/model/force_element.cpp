#include "model/force_element.hpp"

#include "core/error.hpp"

namespace drillflex::model {

ForceElement::ForceElement(std::vector<const Body*> bodies) : bodies_(std::move(bodies)) {
  for (const Body* body : bodies_) local_size_ += body->velocity_count();
}

void ForceElement::Evaluate(const ElementState& state, bool with_matrices, ElementContribution& out) const {
  if (state.poses.size() != bodies_.size() || state.velocity.size() != local_size_) {
    throw LogicError(Describe() + ": evaluated with a state of the wrong size");
  }
  out.force = VecX::Zero(local_size_);
  if (with_matrices) {
    out.stiffness = MatX::Zero(local_size_, local_size_);
    out.damping = MatX::Zero(local_size_, local_size_);
  } else {
    out.stiffness.resize(0, 0);
    out.damping.resize(0, 0);
  }
  DoEvaluate(state, with_matrices, out);
}

double ForceElement::PotentialEnergy(const ElementState& state) const {
  if (state.poses.size() != bodies_.size()) throw LogicError(Describe() + ": wrong number of poses");
  return DoPotentialEnergy(state);
}

bool ForceElement::Penalty(const ElementState& state, double& value, double& stiffness, VecX& gradient) const {
  if (state.poses.size() != bodies_.size()) throw LogicError(Describe() + ": wrong number of poses");
  return DoPenalty(state, value, stiffness, gradient);
}

double ForceElement::PotentialEnergyChange(const ElementState& from, const ElementState& to) const {
  if (from.poses.size() != bodies_.size() || to.poses.size() != bodies_.size()) {
    throw LogicError(Describe() + ": wrong number of poses");
  }
  return DoPotentialEnergyChange(from, to);
}

}  // namespace drillflex::model
