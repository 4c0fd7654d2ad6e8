#include "analyses/bit_bottom_start.hpp"

namespace drillflex::analyses {

model::ModelInput PlaceBottomAtStart(model::ModelInput transient, const model::BuiltModel& start, const VecX& q0) {
  if (!transient.bit_rock || !transient.bit_rock->bottom) return transient;
  const model::SystemModel& system = start.system;
  const model::Body& bit = system.bodies().front();
  const Mat3 frame = bit.reference_orientation.toRotationMatrix();
  const Vec3 reference = bit.reference_position + frame * bit.reduced->node_positions[0];
  const auto poses = system.Poses(q0);
  const double place = frame.col(0).dot(poses.front().NodePosition(bit, 0) - reference);
  model::BitBottomParameters& bottom = *transient.bit_rock->bottom;
  const double stiffness = model::BitBottomStiffness(bottom, bit, transient.settings);
  bottom.level = place + transient.operation.weight_on_bit / stiffness;
  return transient;
}

}  // namespace drillflex::analyses
