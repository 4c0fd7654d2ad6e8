#include "model/system_model.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>

#include <fmt/format.h>

#include "core/error.hpp"
#include "core/profile.hpp"
#include "core/so3.hpp"
#include "model/body_dynamics.hpp"
#include "model/body_inertia_jacobian.hpp"
#include "model/fluid_inertia.hpp"

namespace drillflex::model {

SystemModel::SystemModel(std::vector<Body> bodies, std::vector<std::unique_ptr<ForceElement>> elements,
                         double length)
    : bodies_(std::move(bodies)), elements_(std::move(elements)), length_(length) {
  for (const Body& body : bodies_) {
    num_positions_ = std::max(num_positions_, body.q_offset + body.position_count());
    num_velocities_ = std::max(num_velocities_, body.v_offset + body.velocity_count());
  }
  std::vector<std::pair<Index, Index>> coupled;
  for (const auto& element : elements_) {
    std::vector<Index>& indices = element_bodies_.emplace_back();
    for (const Body* body : element->bodies()) {
      if (IndexOf(body) < 0) throw LogicError(element->Describe() + " refers to a body outside the model");
      for (Index other : indices) coupled.emplace_back(other, IndexOf(body));
      indices.push_back(IndexOf(body));
    }
  }
  body_elements_.resize(bodies_.size());
  for (Index e = 0; e < std::ssize(element_bodies_); ++e) {
    const Index index = e;
    for (Index b : element_bodies_[e]) {
      if (body_elements_[b].empty() || body_elements_[b].back() != index) body_elements_[b].push_back(index);
    }
    if (element_bodies_[e].size() > 1) shared_elements_.push_back(index);
  }
  iteration_pattern_ = BlockPattern(bodies_, coupled, num_velocities_);
  mass_pattern_ = BlockPattern(bodies_, {}, num_velocities_);
}

Index SystemModel::IndexOf(const Body* body) const {
  if (bodies_.empty() || body < bodies_.data() || body >= bodies_.data() + bodies_.size()) return -1;
  return body - bodies_.data();
}

std::string SystemModel::DescribeCoordinate(Index index) const {
  for (Index b = 0; b < std::ssize(bodies_); ++b) {
    const Body& body = bodies_[b];
    const Index local = index - body.v_offset;
    if (local < 0 || local >= body.velocity_count()) continue;
    static constexpr const char* kFrame[6] = {"frame translation x", "frame translation y", "frame translation z",
                                              "frame rotation x",    "frame rotation y",    "frame rotation z"};
    const std::string kind = local < 6 ? std::string(kFrame[local]) : fmt::format("mode {}", local - 6 + 1);
    return fmt::format("body {} ({:.2f}–{:.2f} m from the bit), {}", b, body.s_start, body.s_start + body.length(),
                       kind);
  }
  return fmt::format("coordinate {}", index);
}

VecX SystemModel::ReferencePositions() const {
  VecX q = VecX::Zero(num_positions_);
  for (const Body& body : bodies_) SetReferencePose(body, q);
  return q;
}

std::vector<Eigen::Index> SystemModel::BodyCoordinateBlocks() const {
  std::vector<Eigen::Index> starts;
  starts.reserve(bodies_.size() + 1);
  for (const Body& body : bodies_) starts.push_back(body.v_offset);
  starts.push_back(num_velocities_);
  return starts;
}

VecX SystemModel::Increment(const VecX& q, const VecX& dv) const {
  VecX result = q;
  for (const Body& body : bodies_) {
    const Index qo = body.q_offset, vo = body.v_offset;
    result.segment<3>(qo) += dv.segment<3>(vo);
    const Quat rotation(q[qo + 3], q[qo + 4], q[qo + 5], q[qo + 6]);
    const Quat updated = so3::Compose(rotation, dv.segment<3>(vo + 3));
    result.segment<4>(qo + 3) << updated.w(), updated.x(), updated.y(), updated.z();
    result.segment(qo + 7, body.flexible_count) += dv.segment(vo + 6, body.flexible_count);
  }
  return result;
}

VecX SystemModel::IncrementKeepingShape(const VecX& q, const VecX& dv) const {
  VecX result = Increment(q, dv);
  for (const Body& body : bodies_) {
    const Index qo = body.q_offset, vo = body.v_offset, modes = body.flexible_count;
    const double turn = dv[vo + 3];  // φ: the frame's turn about its own x axis
    if (turn == 0.0) continue;
    // A ← A exp(δθ_⊥) Rx(φ): tilted first, then turned about the tilted axis, so that the turn moves
    // no point of the axis (A exp(δθ) tilts along an axis turned by ~φ/2: at φ = 0.27 rad, a 2e-5 rad
    // tilt of a 3 m body missed its far end by ~8e-6 m, 1.6e7 N in a stiff coupling).
    const Quat rotation(q[qo + 3], q[qo + 4], q[qo + 5], q[qo + 6]);
    const Quat turned = so3::Compose(so3::Compose(rotation, Vec3(0.0, dv[vo + 4], dv[vo + 5])), Vec3(turn, 0.0, 0.0));
    result.segment<4>(qo + 3) << turned.w(), turned.x(), turned.y(), turned.z();
    if (modes == 0) continue;
    const cms::ReducedBody& reduced = *body.reduced;
    // η + φ J η + δη, then turned back by φ (the frame turned forward by it): for a turn that keeps
    // the shape to first order (δη = −φ J η) the modes end where the turned frame needs them.
    const VecX eta = result.segment(qo + 7, modes) + turn * (reduced.twist_generator * q.segment(qo + 7, modes));
    result.segment(qo + 7, modes) =
        eta - (1.0 - std::cos(turn)) * (reduced.transverse_projection * eta) - std::sin(turn) * (reduced.twist_generator * eta);
  }
  return result;
}

void SystemModel::TurnCoordinates(const VecX& dv, VecX& x, bool inverse) const {
  thread_local VecX eta;
  for (const Body& body : bodies_) {
    const Index vo = body.v_offset, modes = body.flexible_count;
    const double turn = inverse ? -dv[vo + 3] : dv[vo + 3];
    // Below 1e-6 rad, |P − I| < 1e-6, far below what Newton notices: taken as 0 (a body vibrating
    // without spinning, where the map cost the V1 cantilever's transient a third of its time).
    if (std::abs(turn) < 1e-6) continue;
    const double c = std::cos(turn), s = std::sin(turn);
    const double y = x[vo + 4], z = x[vo + 5];  // δθ ← Rx(φ) δθ
    x[vo + 4] = c * y - s * z;
    x[vo + 5] = s * y + c * z;
    if (modes == 0) continue;
    const cms::ReducedBody& reduced = *body.reduced;
    eta = x.segment(vo + 6, modes);  // η ← G(φ) η = η − (1 − cos φ) P_⊥ η + sin φ J η
    x.segment(vo + 6, modes).noalias() -= (1.0 - c) * (reduced.transverse_projection * eta);
    x.segment(vo + 6, modes).noalias() += s * (reduced.twist_generator * eta);
  }
}

VecX SystemModel::StateResolution(const VecX& q) const {
  constexpr double kEpsilon = std::numeric_limits<double>::epsilon();
  VecX resolution(num_velocities_);
  for (const Body& body : bodies_) {
    const Index qo = body.q_offset, vo = body.v_offset;
    // The displacement as stored, and the node offsets A u (up to a body length) it is added to.
    resolution.segment<3>(vo).setConstant(kEpsilon * std::max(q.segment<3>(qo).lpNorm<Eigen::Infinity>(), body.length()));
    resolution.segment<3>(vo + 3).setConstant(kEpsilon);
    resolution.segment(vo + 6, body.flexible_count) = kEpsilon * q.segment(qo + 7, body.flexible_count).cwiseAbs();
  }
  return resolution;
}

double SystemModel::LargestLateralNodeTranslation(const VecX& q, const VecX& dv) const {
  double largest = 0.0;
  for (const Body& body : bodies_) {
    const BodyPose pose = PoseOf(body, q);
    const Vec3 dr = dv.segment<3>(body.v_offset);
    const Vec3 dtheta = dv.segment<3>(body.v_offset + 3);
    const auto deta = dv.segment(body.v_offset + 6, body.flexible_count);
    const Vec3 axis = pose.A.col(0);
    for (Index k = 0; k < body.node_count(); ++k) {
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
                                  double t, LoadParameters load) const {
  ElementState state;
  FillState(element, poses, v, t, load, state);
  return state;
}

void SystemModel::FillState(const ForceElement& element, const std::vector<BodyPose>& poses, const VecX& v, double t,
                            LoadParameters load, ElementState& state) const {
  state.time = t;
  state.parameters = load;
  state.poses.clear();
  state.velocity.resize(element.local_size());
  Index offset = 0;
  for (const Body* body : element.bodies()) {
    state.poses.push_back(&poses[IndexOf(body)]);
    state.velocity.segment(offset, body->velocity_count()) = v.segment(body->v_offset, body->velocity_count());
    offset += body->velocity_count();
  }
}

Index SystemModel::LocalOffset(Index element, Index body) const {
  Index offset = 0;
  for (Index b : element_bodies_[element]) {
    if (b == body) return offset;
    offset += bodies_[b].velocity_count();
  }
  throw LogicError("SystemModel: the body is not one of the element's");
}

namespace {

// Models of at least this many bodies evaluate their bodies and elements on OpenMP threads; below
// it the threads cost more than they save (the V1 cantilever's residual takes ~12 µs).
constexpr Index kParallelBodies = 32;

// Runs task(i) for i in [0, count), on OpenMP threads when `parallel`. An exception in a task is
// rethrown here (the first one caught) instead of escaping the parallel region.
template <typename Task>
void ForEachIndex(Index count, bool parallel, const Task& task) {
  if (!parallel) {  // no OpenMP region at all: a small model's residual takes ~12 µs
    for (Index i = 0; i < count; ++i) task(i);
    return;
  }
  std::exception_ptr failure;
#pragma omp parallel for schedule(static)
  for (Index i = 0; i < count; ++i) {
    try {
      task(i);
    } catch (...) {
#pragma omp critical(drillflex_model_failure)
      if (!failure) failure = std::current_exception();
    }
  }
  if (failure) std::rethrow_exception(failure);
}

}  // namespace

// Each body's rows (columns of the matrix) are summed by one thread, in an order fixed by the model
// alone (the residual: the body's own terms, then the elements touching it in ascending order; the
// iteration matrix: the body's terms and its single-body elements, then the shared ones); so the
// sum is bit for bit the same for any number of threads. The elements
// of one body are evaluated by the thread that owns it, into per-thread scratch (no allocation once
// warm); those of several bodies (couplings) beforehand, each once, and stored.
VecX SystemModel::Residual(double t, const VecX& q, const VecX& v, const VecX& a, LoadParameters load) const {
  const profile::Scope scope("model: residual");
  VecX residual = VecX::Zero(num_velocities_);
  const auto poses = Poses(q);
  const bool moving = !v.isZero(0.0);
  const bool accelerating = !a.isZero(0.0);
  const bool parallel = std::ssize(bodies_) >= kParallelBodies;
  std::vector<VecX> shared_forces(elements_.size());
  ForEachIndex(std::ssize(shared_elements_), parallel, [&](Index i) {
    const Index e = shared_elements_[i];
    thread_local ElementState state;
    ElementContribution contribution;
    FillState(*elements_[e], poses, v, t, load, state);
    elements_[e]->Evaluate(state, false, contribution);
    shared_forces[e] = std::move(contribution.force);
  });
  ForEachIndex(std::ssize(bodies_), parallel, [&](Index b) {
    thread_local ElementState state;
    thread_local ElementContribution contribution;
    thread_local VecX local, velocity;
    const Body& body = bodies_[b];
    const Index n = body.velocity_count();
    local.setZero(n);
    velocity = v.segment(body.v_offset, n);
    if (accelerating || moving) {
      local += BodyInertialForces(body, poses[b], velocity, a.segment(body.v_offset, n));
      if (HasLateralFluid(body)) local += BodyFluidForces(body, poses[b], velocity, a.segment(body.v_offset, n));
    }
    AddElasticForces(body, poses[b], velocity, local);
    auto rows = residual.segment(body.v_offset, n);
    rows = local;
    for (Index e : body_elements_[b]) {
      if (element_bodies_[e].size() > 1) {
        rows += shared_forces[e].segment(LocalOffset(e, b), n);
        continue;
      }
      FillState(*elements_[e], poses, v, t, load, state);
      elements_[e]->Evaluate(state, false, contribution);
      rows += contribution.force;
    }
  });
  return residual;
}

SparseMat SystemModel::IterationMatrix(double t, const VecX& q, const VecX& v, const VecX& a, LoadParameters load,
                                       double cK, double cD, double cM) const {
  SparseMat matrix;
  IterationMatrixInto(matrix, t, q, v, a, load, cK, cD, cM);
  return matrix;
}

void SystemModel::IterationMatrixInto(SparseMat& matrix, double t, const VecX& q, const VecX& v, const VecX& a,
                                      LoadParameters load, double cK, double cD, double cM) const {
  const profile::Scope scope("model: iteration matrix");
  const auto poses = Poses(q);
  const bool parallel = std::ssize(bodies_) >= kParallelBodies;
  // cK ∂f/∂q + cD ∂f/∂v of an element, into contribution.stiffness.
  const auto element_block = [&](Index e, ElementState& state, ElementContribution& contribution) {
    FillState(*elements_[e], poses, v, t, load, state);
    contribution.damping_needed = cD != 0.0;
    elements_[e]->Evaluate(state, true, contribution);
    contribution.stiffness *= cK;
    if (cD != 0.0) contribution.stiffness.noalias() += cD * contribution.damping;
  };
  // The elements have no mass: with c_K = c_D = 0 (the mass matrix alone) they add nothing.
  const bool with_elements = cK != 0.0 || cD != 0.0;
  std::vector<MatX> shared_blocks(elements_.size());
  ForEachIndex(with_elements ? std::ssize(shared_elements_) : 0, parallel, [&](Index i) {
    thread_local ElementState state;
    ElementContribution contribution;
    element_block(shared_elements_[i], state, contribution);
    shared_blocks[shared_elements_[i]] = std::move(contribution.stiffness);
  });
  iteration_pattern_.Prepare(matrix);
  ForEachIndex(std::ssize(bodies_), parallel, [&](Index b) {
    thread_local ElementState state;
    thread_local ElementContribution contribution;
    thread_local MatX local;
    const Body& body = bodies_[b];
    const Index n = body.velocity_count();
    const Index index = b;
    iteration_pattern_.ZeroColumns(index, matrix);  // only this body's task writes its columns
    local.setZero(n, n);
    // cK K_in + cD D_in + cM M of the inertia (exact, model/body_inertia_jacobian.hpp).
    AddInertiaMatrices(body, poses[b], v.segment(body.v_offset, n), a.segment(body.v_offset, n), cK, cD, cM, local);
    if (HasLateralFluid(body)) {
      AddFluidMatrices(body, poses[b], v.segment(body.v_offset, n), a.segment(body.v_offset, n), cK, cD, cM, local);
    }
    AddElasticMatrices(body, poses[b], cK, cD, local);
    // The body's own elements (wall contacts, loads, fluid) summed into its dense block first: one
    // scatter into the pattern a body instead of one an element (~10 contacts a body).
    for (Index e : body_elements_[b]) {
      if (element_bodies_[e].size() > 1 || !with_elements) continue;
      element_block(e, state, contribution);
      local += contribution.stiffness;
    }
    iteration_pattern_.AddColumns(local, std::span<const Index>(&index, 1), index, matrix);
    for (Index e : body_elements_[b]) {
      if (element_bodies_[e].size() > 1 && with_elements) {
        iteration_pattern_.AddColumns(shared_blocks[e], element_bodies_[e], index, matrix);
      }
    }
  });
}

SparseMat SystemModel::MassMatrix(const VecX& q) const {
  const auto poses = Poses(q);
  SparseMat matrix = mass_pattern_.Zero();
  for (Index b = 0; b < std::ssize(bodies_); ++b) {
    MatX mass = BodyMassMatrix(bodies_[b], poses[b]);
    if (HasLateralFluid(bodies_[b])) mass += BodyFluidMassMatrix(bodies_[b], poses[b]);
    mass_pattern_.Add(mass, {b}, matrix);
  }
  return matrix;
}

Energies SystemModel::ComputeEnergies(const VecX& q, const VecX& v, LoadParameters load) const {
  const auto poses = Poses(q);
  const bool parallel = std::ssize(bodies_) >= kParallelBodies;
  // Each term on any thread, the sums in the model's order: the same for any number of threads.
  std::vector<double> kinetic(bodies_.size()), elastic(bodies_.size()), potential(elements_.size());
  ForEachIndex(std::ssize(bodies_), parallel, [&](Index b) {
    const Body& body = bodies_[b];
    kinetic[b] = BodyKineticEnergy(body, poses[b], v.segment(body.v_offset, body.velocity_count()));
    if (HasLateralFluid(body)) {
      kinetic[b] += BodyFluidKineticEnergy(body, poses[b], v.segment(body.v_offset, body.velocity_count()));
    }
    elastic[b] = BodyElasticEnergy(body, poses[b]);
  });
  ForEachIndex(std::ssize(elements_), parallel, [&](Index e) {
    potential[e] = elements_[e]->PotentialEnergy(StateOf(*elements_[e], poses, v, 0.0, load));
  });
  Energies energies;
  for (Index b = 0; b < std::ssize(bodies_); ++b) {
    energies.kinetic += kinetic[b];
    energies.elastic += elastic[b];
  }
  for (const double term : potential) energies.potential += term;
  return energies;
}

double SystemModel::PotentialEnergyChange(const VecX& from, const VecX& to, LoadParameters load) const {
  const profile::Scope scope("model: energy change");
  const auto before = Poses(from);
  const auto after = Poses(to);
  const bool parallel = std::ssize(bodies_) >= kParallelBodies;
  const VecX rest = VecX::Zero(num_velocities_);
  std::vector<double> elastic(bodies_.size()), potential(elements_.size());
  ForEachIndex(std::ssize(bodies_), parallel, [&](Index b) {
    elastic[b] = BodyElasticEnergy(bodies_[b], after[b]) - BodyElasticEnergy(bodies_[b], before[b]);
  });
  ForEachIndex(std::ssize(elements_), parallel, [&](Index e) {
    const ForceElement& element = *elements_[e];
    potential[e] = element.PotentialEnergyChange(StateOf(element, before, rest, 0.0, load),
                                                 StateOf(element, after, rest, 0.0, load));
  });
  // Summed in model order: the same for any number of threads.
  double change = 0.0;
  for (const double term : elastic) change += term;
  for (const double term : potential) change += term;
  return change;
}

std::vector<solvers::PenaltyTerm> SystemModel::PenaltyTerms(const VecX& q, LoadParameters load) const {
  const profile::Scope scope("model: penalty terms");
  const auto poses = Poses(q);
  const VecX rest = VecX::Zero(num_velocities_);
  // Each element on any thread into its own slot, gathered in the model's order.
  std::vector<solvers::PenaltyTerm> slots(elements_.size());
  std::vector<char> has(elements_.size(), 0);
  ForEachIndex(std::ssize(elements_), std::ssize(bodies_) >= kParallelBodies, [&](Index e) {
    thread_local ElementState state;
    thread_local VecX gradient;
    const ForceElement& element = *elements_[e];
    FillState(element, poses, rest, 0.0, load, state);
    solvers::PenaltyTerm& term = slots[e];
    if (!element.Penalty(state, term.value, term.stiffness, gradient)) return;
    has[e] = 1;
    Index local = 0;
    for (const Index b : element_bodies_[e]) {
      const Body& body = bodies_[b];
      for (Index j = 0; j < body.velocity_count(); ++j, ++local) {
        if (gradient[local] == 0.0) continue;
        term.indices.push_back(body.v_offset + j);
        term.gradient.push_back(gradient[local]);
      }
    }
  });
  std::vector<solvers::PenaltyTerm> terms;
  for (Index e = 0; e < std::ssize(elements_); ++e) {
    if (has[e]) terms.push_back(std::move(slots[e]));
  }
  return terms;
}

std::pair<Index, Index> SystemModel::NodeAt(double s) const { return FindNodeAt(bodies_, s); }

std::pair<Index, Index> FindNodeAt(const std::vector<Body>& bodies_, double s) {
  Index best_body = 0, best_node = 0;
  double best = std::numeric_limits<double>::infinity();
  for (Index b = 0; b < std::ssize(bodies_); ++b) {
    const Body& body = bodies_[b];
    for (Index k = 0; k < body.node_count(); ++k) {
      const double distance = std::abs(body.NodeS(k) - s);
      if (distance <= best + 1e-12) {  // ties go to the later (upper) body
        best = distance;
        best_body = b;
        best_node = k;
      }
    }
  }
  return {best_body, best_node};
}

}  // namespace drillflex::model
