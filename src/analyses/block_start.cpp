#include "analyses/block_start.hpp"

namespace drillflex::analyses {

model::ModelInput PlaceBlockAtStart(model::ModelInput transient, const model::BuiltModel& start, const VecX& q0) {
  if (!transient.block || transient.block->mode != model::BlockMode::Velocity || !transient.block->line_stiffness) {
    return transient;
  }
  const model::SystemModel& system = start.system;
  const model::Body& top = system.bodies().back();  // the string's top: the last body's last node
  const int node = top.node_count() - 1;
  const Mat3 frame = top.reference_orientation.toRotationMatrix();
  const Vec3 reference = top.reference_position + frame * top.reduced->node_positions[node];
  const Vec3 place = system.Poses(q0).back().NodePosition(top, node);
  transient.block->start_top_displacement = frame.col(0).dot(place - reference);
  return transient;
}

}  // namespace drillflex::analyses
