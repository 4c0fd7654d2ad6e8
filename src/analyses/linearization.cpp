#include "analyses/linearization.hpp"

namespace drillflex::analyses {

LinearizedSystem Linearize(const model::SystemModel& model, const VecX& q, model::LoadParameters load) {
  const VecX zero = VecX::Zero(model.num_velocities());
  // The wall friction of a sliding string is no stiffness: about the steady sliding its position
  // derivatives are circulatory (a tangential force μ k δn from a radial move, a radial one from the
  // contact moving around the hole), and their symmetric part read as a negative stiffness of about
  // ±μk/2 (the bundled example's "mode" at ω² = −134 rad²/s²). The stiffness is the string's with the
  // friction off; the friction's velocity derivative about the sliding stays in the damping
  // (docs/method.md "The friction of a rotating string, linearized").
  model::LoadParameters conservative = load;
  conservative.SetWallFriction({0.0, 0.0});
  const SparseMat tangent = model.IterationMatrix(0.0, q, zero, zero, conservative, 1.0, 0.0, 0.0);
  const SparseMat mass = model.MassMatrix(q);
  LinearizedSystem system;
  system.stiffness = (0.5 * (tangent + SparseMat(tangent.transpose()))).pruned();
  system.mass = (0.5 * (mass + SparseMat(mass.transpose()))).pruned();
  system.damping = model.IterationMatrix(0.0, q, zero, zero, load, 0.0, 1.0, 0.0).pruned();
  return system;
}

}  // namespace drillflex::analyses
