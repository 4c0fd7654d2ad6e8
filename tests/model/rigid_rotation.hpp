// A rigid rotation of a whole model state about the global origin, for invariance tests.
#pragma once

#include "model/system_model.hpp"

namespace drillflex::model::testing {

// q with every body frame turned by R (A → R A) and every frame origin rotated about the global
// origin (r → R r); the modal coordinates are unchanged. The string keeps its shape and strains.
// q holds r − reference_position: the result is a state of `target` (by default `model` itself;
// a model whose reference placement is turned too, e.g. BuildTurnedModel's, takes R Δr).
inline VecX RotateRigidly(const SystemModel& model, const VecX& q, const Mat3& rotation,
                          const SystemModel* target = nullptr) {
  if (!target) target = &model;
  VecX rotated = q;
  const Quat turn(rotation);
  for (std::size_t b = 0; b < model.bodies().size(); ++b) {
    const Body& body = model.bodies()[b];
    const int qo = body.q_offset;
    rotated.segment<3>(qo) =
        rotation * (body.reference_position + q.segment<3>(qo)) - target->bodies()[b].reference_position;
    const Quat frame = (turn * Quat(q[qo + 3], q[qo + 4], q[qo + 5], q[qo + 6])).normalized();
    rotated.segment<4>(qo + 3) << frame.w(), frame.x(), frame.y(), frame.z();
  }
  return rotated;
}

// The velocities (or accelerations, forces) rotated with it: the global translational rows turn
// (ṙ → R ṙ); body-frame angular and modal rows are unchanged.
inline VecX RotateVelocities(const SystemModel& model, const VecX& v, const Mat3& rotation) {
  VecX rotated = v;
  for (const Body& body : model.bodies()) rotated.segment<3>(body.v_offset) = rotation * v.segment<3>(body.v_offset);
  return rotated;
}

}  // namespace drillflex::model::testing
