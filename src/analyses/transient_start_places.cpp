#include "analyses/transient_start_places.hpp"

#include "model/node_kinematics.hpp"

namespace drillflex::analyses {
namespace {

// t·(r(q) − p): how far a body's node has moved along the body's reference axis from its reference
// place p, m.
double AxialDisplacement(const model::SystemModel& system, const VecX& q, std::size_t body_index, int node) {
  const model::Body& body = system.bodies()[body_index];
  const Mat3 frame = body.reference_orientation.toRotationMatrix();
  const Vec3 reference = model::NodeReferencePosition(body, node);
  return frame.col(0).dot(system.Poses(q)[body_index].NodePosition(body, node) - reference);
}

}  // namespace

model::ModelInput PlaceBottomAtStart(model::ModelInput transient, const model::BuiltModel& start, const VecX& q0) {
  if (!transient.bit_rock || !transient.bit_rock->bottom) return transient;
  const double place = AxialDisplacement(start.system, q0, 0, 0);  // the bit: the first body's first node
  model::BitBottomParameters& bottom = *transient.bit_rock->bottom;
  const double stiffness = model::BitBottomStiffness(bottom, start.system.bodies().front(), transient.settings);
  bottom.level = place + transient.operation.weight_on_bit / stiffness;
  return transient;
}

model::ModelInput PlaceBlockAtStart(model::ModelInput transient, const model::BuiltModel& start, const VecX& q0) {
  if (!transient.block || transient.block->mode != model::BlockMode::Velocity || !transient.block->line_stiffness) {
    return transient;
  }
  // The string's top: the last body's last node.
  const std::size_t top = start.system.bodies().size() - 1;
  transient.block->start_top_displacement =
      AxialDisplacement(start.system, q0, top, start.system.bodies()[top].node_count() - 1);
  return transient;
}

}  // namespace drillflex::analyses
