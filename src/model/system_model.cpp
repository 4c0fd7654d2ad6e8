#include "model/system_model.hpp"

#include <cmath>
#include <limits>

#include "core/error.hpp"
#include "core/so3.hpp"
#include "model/body_dynamics.hpp"
#include "model/body_inertia_jacobian.hpp"

namespace drillflex::model {

SystemModel::SystemModel(std::vector<Body> bodies, std::vector<std::unique_ptr<ForceElement>> elements,
                         double length)
    : bodies_(std::move(bodies)), elements_(std::move(elements)), length_(length) {
  for (const Body& body : bodies_) {
    num_positions_ = std::max(num_positions_, body.q_offset + body.position_count());
    num_velocities_ = std::max(num_velocities_, body.v_offset + body.velocity_count());
  }
  for (const auto& element : elements_) {
    for (const Body* body : element->bodies()) {
      if (IndexOf(body) < 0) throw LogicError(element->Describe() + " refers to a body outside the model");
    }
  }
}

int SystemModel::IndexOf(const Body* body) const {
  if (bodies_.empty() || body < bodies_.data() || body >= bodies_.data() + bodies_.size()) return -1;
  return static_cast<int>(body - bodies_.data());
}

VecX SystemModel::ReferencePositions() const {
  VecX q = VecX::Zero(num_positions_);
  for (const Body& body : bodies_) SetReferencePose(body, q);
  return q;
}

VecX SystemModel::Increment(const VecX& q, const VecX& dv) const {
  VecX result = q;
  for (const Body& body : bodies_) {
    const int qo = body.q_offset, vo = body.v_offset;
    result.segment<3>(qo) += dv.segment<3>(vo);
    const Quat rotation(q[qo + 3], q[qo + 4], q[qo + 5], q[qo + 6]);
    const Quat updated = so3::Compose(rotation, dv.segment<3>(vo + 3));
    result.segment<4>(qo + 3) << updated.w(), updated.x(), updated.y(), updated.z();
    result.segment(qo + 7, body.flexible_count) += dv.segment(vo + 6, body.flexible_count);
  }
  return result;
}

std::vector<BodyPose> SystemModel::Poses(const VecX& q) const {
  std::vector<BodyPose> poses;
  poses.reserve(bodies_.size());
  for (const Body& body : bodies_) poses.push_back(PoseOf(body, q));
  return poses;
}

ElementState SystemModel::StateOf(const ForceElement& element, const std::vector<BodyPose>& poses, const VecX& v,
                                  double t, double load_factor) const {
  ElementState state;
  state.time = t;
  state.load_factor = load_factor;
  state.velocity.resize(element.local_size());
  int offset = 0;
  for (const Body* body : element.bodies()) {
    state.poses.push_back(&poses[IndexOf(body)]);
    state.velocity.segment(offset, body->velocity_count()) = v.segment(body->v_offset, body->velocity_count());
    offset += body->velocity_count();
  }
  return state;
}

VecX SystemModel::Residual(double t, const VecX& q, const VecX& v, const VecX& a, double load_factor) const {
  VecX residual = VecX::Zero(num_velocities_);
  const auto poses = Poses(q);
  const bool moving = !v.isZero(0.0);
  const bool accelerating = !a.isZero(0.0);
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    const Body& body = bodies_[b];
    const int n = body.velocity_count();
    VecX local = VecX::Zero(n);
    const VecX velocity = v.segment(body.v_offset, n);
    if (accelerating) local.noalias() += BodyMassMatrix(body, poses[b]) * a.segment(body.v_offset, n);
    if (moving) local += BodyVelocityForces(body, poses[b], velocity);
    AddElasticForces(body, poses[b], velocity, local);
    residual.segment(body.v_offset, n) += local;
  }
  ElementContribution contribution;
  for (const auto& element : elements_) {
    element->Evaluate(StateOf(*element, poses, v, t, load_factor), false, contribution);
    int offset = 0;
    for (const Body* body : element->bodies()) {
      residual.segment(body->v_offset, body->velocity_count()) +=
          contribution.force.segment(offset, body->velocity_count());
      offset += body->velocity_count();
    }
  }
  return residual;
}

namespace {

void AddBlockTriplets(const MatX& block, const std::vector<const Body*>& bodies, std::vector<Triplet>& triplets) {
  int row_offset = 0;
  for (const Body* row_body : bodies) {
    int col_offset = 0;
    for (const Body* col_body : bodies) {
      for (int i = 0; i < row_body->velocity_count(); ++i) {
        for (int j = 0; j < col_body->velocity_count(); ++j) {
          const double value = block(row_offset + i, col_offset + j);
          if (value != 0.0) triplets.emplace_back(row_body->v_offset + i, col_body->v_offset + j, value);
        }
      }
      col_offset += col_body->velocity_count();
    }
    row_offset += row_body->velocity_count();
  }
}

}  // namespace

SparseMat SystemModel::IterationMatrix(double t, const VecX& q, const VecX& v, const VecX& a, double load_factor,
                                       double cK, double cD, double cM) const {
  const auto poses = Poses(q);
  std::vector<Triplet> triplets;
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    const Body& body = bodies_[b];
    const int n = body.velocity_count();
    MatX local = MatX::Zero(n, n);
    // cK K_in + cD D_in + cM M of the inertia (exact, model/body_inertia_jacobian.hpp).
    AddInertiaMatrices(body, poses[b], v.segment(body.v_offset, n), a.segment(body.v_offset, n), cK, cD, cM, local);
    AddElasticMatrices(body, poses[b], cK, cD, local);
    AddBlockTriplets(local, {&body}, triplets);
  }
  ElementContribution contribution;
  for (const auto& element : elements_) {
    element->Evaluate(StateOf(*element, poses, v, t, load_factor), true, contribution);
    AddBlockTriplets(cK * contribution.stiffness + cD * contribution.damping, element->bodies(), triplets);
  }
  SparseMat matrix(num_velocities_, num_velocities_);
  matrix.setFromTriplets(triplets.begin(), triplets.end());
  return matrix;
}

SparseMat SystemModel::MassMatrix(const VecX& q) const {
  const auto poses = Poses(q);
  std::vector<Triplet> triplets;
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    AddBlockTriplets(BodyMassMatrix(bodies_[b], poses[b]), {&bodies_[b]}, triplets);
  }
  SparseMat matrix(num_velocities_, num_velocities_);
  matrix.setFromTriplets(triplets.begin(), triplets.end());
  return matrix;
}

Energies SystemModel::ComputeEnergies(const VecX& q, const VecX& v, double load_factor) const {
  Energies energies;
  const auto poses = Poses(q);
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    const Body& body = bodies_[b];
    energies.kinetic += BodyKineticEnergy(body, poses[b], v.segment(body.v_offset, body.velocity_count()));
    energies.elastic += BodyElasticEnergy(body, poses[b]);
  }
  for (const auto& element : elements_) {
    energies.potential += element->PotentialEnergy(StateOf(*element, poses, v, 0.0, load_factor));
  }
  return energies;
}

std::pair<int, int> SystemModel::NodeAt(double s) const { return FindNodeAt(bodies_, s); }

std::pair<int, int> FindNodeAt(const std::vector<Body>& bodies_, double s) {
  int best_body = 0, best_node = 0;
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    const Body& body = bodies_[b];
    for (int k = 0; k < body.node_count(); ++k) {
      const double distance = std::abs(body.s_start + body.reduced->node_positions[k].x() - s);
      if (distance <= best + 1e-12) {  // ties go to the later (upper) body
        best = distance;
        best_body = static_cast<int>(b);
        best_node = k;
      }
    }
  }
  return {best_body, best_node};
}

}  // namespace drillflex::model
