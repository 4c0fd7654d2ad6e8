#include "model/system_model.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
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
  std::vector<std::pair<int, int>> coupled;
  for (const auto& element : elements_) {
    std::vector<int>& indices = element_bodies_.emplace_back();
    for (const Body* body : element->bodies()) {
      if (IndexOf(body) < 0) throw LogicError(element->Describe() + " refers to a body outside the model");
      for (int other : indices) coupled.emplace_back(other, IndexOf(body));
      indices.push_back(IndexOf(body));
    }
  }
  iteration_pattern_ = BlockPattern(bodies_, coupled, num_velocities_);
  mass_pattern_ = BlockPattern(bodies_, {}, num_velocities_);
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

double SystemModel::LargestLateralNodeTranslation(const VecX& q, const VecX& dv) const {
  double largest = 0.0;
  for (const Body& body : bodies_) {
    const BodyPose pose = PoseOf(body, q);
    const Vec3 dr = dv.segment<3>(body.v_offset);
    const Vec3 dtheta = dv.segment<3>(body.v_offset + 3);
    const auto deta = dv.segment(body.v_offset + 6, body.flexible_count);
    const Vec3 axis = pose.A.col(0);
    for (int k = 0; k < body.node_count(); ++k) {
      const Vec3 local = dtheta.cross(pose.NodeOffset(body, k)) + body.reduced->node_translation_modes[k] * deta;
      const Vec3 move = dr + pose.A * local;
      largest = std::max(largest, (move - move.dot(axis) * axis).norm());
    }
  }
  return largest;
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

namespace {

// Models of at least this many bodies evaluate their bodies and elements on OpenMP threads; below
// it the threads cost more than they save (the V1 cantilever's residual takes ~12 µs).
constexpr std::size_t kParallelBodies = 32;

// Runs task(i) for i in [0, count), on OpenMP threads when `parallel`. An exception in a task is
// rethrown here (the first one caught) instead of escaping the parallel region.
template <typename Task>
void ForEachIndex(std::size_t count, bool parallel, const Task& task) {
  std::exception_ptr failure;
  const long n = static_cast<long>(count);
#pragma omp parallel for schedule(static) if (parallel)
  for (long i = 0; i < n; ++i) {
    try {
      task(static_cast<std::size_t>(i));
    } catch (...) {
#pragma omp critical(drillflex_model_failure)
      if (!failure) failure = std::current_exception();
    }
  }
  if (failure) std::rethrow_exception(failure);
}

}  // namespace

// Each body's and element's contribution is computed on its own (in parallel for large models) and
// stored, then added in the fixed order of bodies and elements: the sum is bit for bit the same for
// any number of threads.
VecX SystemModel::Residual(double t, const VecX& q, const VecX& v, const VecX& a, double load_factor) const {
  VecX residual = VecX::Zero(num_velocities_);
  const auto poses = Poses(q);
  const bool moving = !v.isZero(0.0);
  const bool accelerating = !a.isZero(0.0);
  const bool parallel = bodies_.size() >= kParallelBodies;
  std::vector<VecX> body_forces(bodies_.size());
  ForEachIndex(bodies_.size(), parallel, [&](std::size_t b) {
    const Body& body = bodies_[b];
    const int n = body.velocity_count();
    VecX local = VecX::Zero(n);
    const VecX velocity = v.segment(body.v_offset, n);
    if (accelerating || moving) local += BodyInertialForces(body, poses[b], velocity, a.segment(body.v_offset, n));
    AddElasticForces(body, poses[b], velocity, local);
    body_forces[b] = std::move(local);
  });
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    residual.segment(bodies_[b].v_offset, bodies_[b].velocity_count()) += body_forces[b];
  }
  std::vector<VecX> element_forces(elements_.size());
  ForEachIndex(elements_.size(), parallel, [&](std::size_t e) {
    ElementContribution contribution;
    elements_[e]->Evaluate(StateOf(*elements_[e], poses, v, t, load_factor), false, contribution);
    element_forces[e] = std::move(contribution.force);
  });
  for (std::size_t e = 0; e < elements_.size(); ++e) {
    int offset = 0;
    for (const Body* body : elements_[e]->bodies()) {
      residual.segment(body->v_offset, body->velocity_count()) +=
          element_forces[e].segment(offset, body->velocity_count());
      offset += body->velocity_count();
    }
  }
  return residual;
}

SparseMat SystemModel::IterationMatrix(double t, const VecX& q, const VecX& v, const VecX& a, double load_factor,
                                       double cK, double cD, double cM) const {
  const auto poses = Poses(q);
  const bool parallel = bodies_.size() >= kParallelBodies;
  std::vector<MatX> body_blocks(bodies_.size());
  ForEachIndex(bodies_.size(), parallel, [&](std::size_t b) {
    const Body& body = bodies_[b];
    const int n = body.velocity_count();
    MatX local = MatX::Zero(n, n);
    // cK K_in + cD D_in + cM M of the inertia (exact, model/body_inertia_jacobian.hpp).
    AddInertiaMatrices(body, poses[b], v.segment(body.v_offset, n), a.segment(body.v_offset, n), cK, cD, cM, local);
    AddElasticMatrices(body, poses[b], cK, cD, local);
    body_blocks[b] = std::move(local);
  });
  std::vector<MatX> element_blocks(elements_.size());
  ForEachIndex(elements_.size(), parallel, [&](std::size_t e) {
    const ForceElement& element = *elements_[e];
    ElementContribution contribution;
    element.Evaluate(StateOf(element, poses, v, t, load_factor), true, contribution);
    MatX local = cK * contribution.stiffness;
    if (cD != 0.0) local.noalias() += cD * contribution.damping;
    element_blocks[e] = std::move(local);
  });
  SparseMat matrix = iteration_pattern_.Zero();
  for (std::size_t b = 0; b < bodies_.size(); ++b) iteration_pattern_.Add(body_blocks[b], {static_cast<int>(b)}, matrix);
  for (std::size_t e = 0; e < elements_.size(); ++e) iteration_pattern_.Add(element_blocks[e], element_bodies_[e], matrix);
  return matrix;
}

SparseMat SystemModel::MassMatrix(const VecX& q) const {
  const auto poses = Poses(q);
  SparseMat matrix = mass_pattern_.Zero();
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    mass_pattern_.Add(BodyMassMatrix(bodies_[b], poses[b]), {static_cast<int>(b)}, matrix);
  }
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
