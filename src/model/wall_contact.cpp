// Wellbore contact element (method.md §6); formulas and choices in wall_contact.hpp.
#include "model/wall_contact.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "core/error.hpp"
#include "core/so3.hpp"
#include "model/hole_friction.hpp"

namespace drillflex::model {
namespace {

using so3::Skew;
using RowVec3 = Eigen::RowVector3d;

// R_h = D/2 at md and its slope dR_h/ds: the sections of well/hole.hpp are constant or linear, so
// the slope is that of the section holding md (the same search rule as HoleProfile: an MD on a
// boundary belongs to the section above; 0 outside a linear section's span).
struct HoleRadius {
  double radius = 0.0;
  double slope = 0.0;
};

HoleRadius HoleRadiusAt(const well::HoleProfile& hole, double md) {
  const auto& sections = hole.sections();
  const auto last = sections.end() - 1;
  const auto found = std::lower_bound(sections.begin(), last, md,
                                      [](const well::HoleSection& s, double value) { return *s.to_md < value; });
  HoleRadius result{0.5 * hole.Diameter(md), 0.0};
  if (found->diameter_at_end) {
    const double start = (found == sections.begin()) ? 0.0 : *(found - 1)->to_md;
    if (md >= start && md <= *found->to_md) {
      result.slope = 0.5 * (*found->diameter_at_end - found->diameter) / (*found->to_md - start);
    }
  }
  return result;
}

// Where the node sits in the hole (wall_contact.hpp: s*, e, n, δ).
struct HoleGeometry {
  double md = 0.0;               // s*
  double path_md = 0.0;          // s* clamped to the path (the warm start of the next search)
  Vec3 tangent = Vec3::UnitX();  // t(s*)
  Vec3 curvature = Vec3::Zero(); // κ(s*) = dt/ds
  Vec3 normal = Vec3::Zero();    // n = e/|e| (0 when e = 0)
  double distance = 0.0;         // ρ = |e|
  double scale = 1.0;            // c = 1 − e·κ: ds*/dx = tᵀ/c
  HoleRadius hole;
  double penetration = 0.0;      // δ = ρ + R_c − R_h
};

HoleGeometry LocateInHole(const Wellbore& wellbore, const Vec3& x, double md_hint, double contact_radius) {
  const well::Trajectory& path = wellbore.trajectory;
  const well::ClosestPoint closest = path.FindClosest(x, md_hint);
  HoleGeometry g;
  g.path_md = closest.md;
  Vec3 center;
  if (closest.clamped) {
    // Beyond an end of the path: the path continued straight along its end tangent.
    const Vec3 end = path.Position(closest.md);
    g.tangent = path.Tangent(closest.md);
    const double along = (x - end).dot(g.tangent);
    g.md = closest.md + along;
    center = end + along * g.tangent;
  } else {
    g.md = closest.md;
    const well::Trajectory::PathPoint point = path.Evaluate(g.md);
    center = point.position;
    g.tangent = point.tangent;
    g.curvature = point.curvature;
  }
  Vec3 offset = x - center;
  offset -= offset.dot(g.tangent) * g.tangent;  // the root's rounding residue along t
  g.distance = offset.norm();
  if (g.distance > 0.0) g.normal = offset / g.distance;
  g.scale = 1.0 - offset.dot(g.curvature);
  g.hole = HoleRadiusAt(wellbore.hole, g.md);
  g.penetration = g.distance + contact_radius - g.hole.radius;
  return g;
}

// Derivatives of the geometry with respect to x (curvature terms exact on circular arcs).
struct GeometryDerivatives {
  Mat3 normal;     // dn/dx = (I − n nᵀ − t tᵀ/c)/ρ
  Mat3 tangent;    // dt/dx = κ tᵀ/c
  Mat3 around;     // d(t × n)/dx = t̃ dn/dx − ñ dt/dx
  Vec3 gradient;   // ∇δ = n − R_h' t/c
  Mat3 hessian;    // d∇δ/dx = dn/dx − (R_h'/c²)(t κᵀ + κ tᵀ)   (R_h'' = 0, dc/dx = −κᵀ)
};

GeometryDerivatives Differentiate(const HoleGeometry& g) {
  const Vec3& n = g.normal;
  const Vec3& t = g.tangent;
  const double inv_c = 1.0 / g.scale;
  GeometryDerivatives d;
  d.normal = (Mat3::Identity() - n * n.transpose() - inv_c * t * t.transpose()) / g.distance;
  d.tangent = inv_c * g.curvature * t.transpose();
  d.around = Skew(t) * d.normal - Skew(n) * d.tangent;
  d.gradient = n - g.hole.slope * inv_c * t;
  d.hessian = d.normal - (g.hole.slope * inv_c * inv_c) * (t * g.curvature.transpose() + g.curvature * t.transpose());
  return d;
}

// The friction direction q = (μ_a v_a t + μ_t v_θ e_θ)/max(|v_t|, v_ε), so that F_t = −N q, and
// its derivatives with respect to the node position, velocity and angular velocity.
struct FrictionDirection {
  Vec3 value = Vec3::Zero();
  Mat3 position = Mat3::Zero();
  Mat3 velocity = Mat3::Zero();
  Mat3 angular_velocity = Mat3::Zero();
};

// The contact point velocity v_c and its derivatives (state or prescribed sliding).
struct ContactVelocity {
  Vec3 value = Vec3::Zero();
  Mat3 position = Mat3::Zero();
  Mat3 velocity = Mat3::Zero();
  Mat3 angular_velocity = Mat3::Zero();
};

ContactVelocity ContactPointVelocity(const HoleGeometry& g, const GeometryDerivatives* d, const NodeMotion& motion,
                                     const WallContactParameters& p) {
  const double radius = p.contact_radius;
  ContactVelocity v;
  // v_c = ṙ_k + ω_k × (R_c n): the node's own motion.
  v.value = motion.velocity + radius * motion.angular_velocity.cross(g.normal);
  if (d) {
    v.position = radius * Skew(motion.angular_velocity) * d->normal;
    v.velocity = Mat3::Identity();
    v.angular_velocity = -radius * Skew(g.normal);
  }
  if (p.prescribed_sliding) {
    // The steady sliding prescribed on top of it, −V t + Ω R_c (t × n): the string moves up-hole at V
    // and turns at Ω about t. A static state has ṙ = ω = 0 and slides at the steady speeds alone; the
    // linearized analyses take the friction's damping about that sliding from the node's own motion
    // (docs/method.md "The friction of a rotating string, linearized").
    const double axial = p.prescribed_sliding->axial_speed, spin = p.prescribed_sliding->rotary_speed;
    v.value += -axial * g.tangent + spin * radius * g.tangent.cross(g.normal);
    if (d) v.position += -axial * d->tangent + spin * radius * d->around;
  }
  return v;
}

FrictionDirection ComputeFrictionDirection(const HoleGeometry& g, const GeometryDerivatives* d,
                                           const NodeMotion& motion, const WallContactParameters& p) {
  const Vec3& n = g.normal;
  const Vec3& t = g.tangent;
  const Vec3 around = t.cross(n);  // e_θ
  const double mu_a = p.axial_friction, mu_t = p.tangential_friction;
  const ContactVelocity vc = ContactPointVelocity(g, d, motion, p);
  const double v_axial = t.dot(vc.value), v_around = around.dot(vc.value), v_normal = n.dot(vc.value);
  const Vec3 sliding = vc.value - v_normal * n;  // v_t
  const double speed = sliding.norm();
  const double scale = std::max(speed, p.regularization_velocity);  // ν
  const Vec3 a = mu_a * v_axial * t + mu_t * v_around * around;     // T v_c
  FrictionDirection q;
  q.value = a / scale;
  if (!d) return q;
  // a = T v_c with T = μ_a t tᵀ + μ_t e_θ e_θᵀ: da = (dT) v_c + T dv_c.
  const Mat3 T = mu_a * t * t.transpose() + mu_t * around * around.transpose();
  const RowVec3 vc_row = vc.value.transpose();
  const Mat3 a_position = mu_a * (v_axial * d->tangent + t * (vc_row * d->tangent)) +
                          mu_t * (v_around * d->around + around * (vc_row * d->around)) + T * vc.position;
  q.position = a_position / scale;
  q.velocity = T * vc.velocity / scale;
  q.angular_velocity = T * vc.angular_velocity / scale;
  if (speed > p.regularization_velocity) {
    // Coulomb branch: dν = τᵀ dv_t with v_t = v_c − n (n·v_c), τ = v_t/|v_t| ⊥ n:
    // dν = τᵀ dv_c − (n·v_c) τᵀ dn.
    const RowVec3 tau = (sliding / speed).transpose();
    const Vec3 lever = a / (scale * scale);
    q.position -= lever * (tau * vc.position - v_normal * (tau * d->normal));
    q.velocity -= lever * (tau * vc.velocity);
    q.angular_velocity -= lever * (tau * vc.angular_velocity);
  }
  return q;
}

// The force and moment on the node, with their derivatives when asked.
struct ContactForce {
  bool active = false;
  double normal_force = 0.0;
  Vec3 force = Vec3::Zero();
  Vec3 moment = Vec3::Zero();
  Vec3 friction = Vec3::Zero();
  PointForceJacobian jacobian;  // of the force at the contact point, lever R_c n
};

bool HasFriction(const WallContactParameters& p) { return p.axial_friction > 0.0 || p.tangential_friction > 0.0; }

ContactForce ComputeContactForce(const HoleGeometry& g, const NodeMotion& motion, const WallContactParameters& p,
                                 bool with_derivatives) {
  ContactForce c;
  if (!(g.penetration > 0.0) || !(g.distance > 0.0)) return c;
  const Vec3& n = g.normal;
  const Vec3 gradient = n - (g.hole.slope / g.scale) * g.tangent;  // ∇δ
  const double normal_force = p.normal_stiffness * g.penetration + p.normal_damping * gradient.dot(motion.velocity);
  if (!(normal_force > 0.0)) return c;
  c.active = true;
  c.normal_force = normal_force;
  GeometryDerivatives derivatives;
  const GeometryDerivatives* d = nullptr;
  if (with_derivatives) {
    derivatives = Differentiate(g);
    d = &derivatives;
  }
  FrictionDirection q;
  if (HasFriction(p)) q = ComputeFrictionDirection(g, d, motion, p);
  // F = −N (n + q), M = R_c n × F (n × n = 0: only the friction part has a moment).
  const double radius = p.contact_radius;
  c.friction = -normal_force * q.value;
  c.force = -normal_force * n + c.friction;
  c.moment = radius * n.cross(c.force);
  if (!d) return c;
  const Vec3 h = n + q.value;
  // N_x = k_n ∇δᵀ + c_n ṙ_kᵀ (d∇δ/dx) (symmetric), N_v = c_n ∇δᵀ.
  const RowVec3 n_position = p.normal_stiffness * d->gradient.transpose() +
                             p.normal_damping * (d->hessian * motion.velocity).transpose();
  const RowVec3 n_velocity = p.normal_damping * d->gradient.transpose();
  PointForceJacobian& J = c.jacobian;
  J.force_position = -h * n_position - normal_force * (d->normal + q.position);
  J.force_velocity = -h * n_velocity - normal_force * q.velocity;
  J.force_angular_velocity = -normal_force * q.angular_velocity;
  J.lever_position = radius * d->normal;
  return c;
}

void CheckParameters(const WallContactParameters& p) {
  auto require = [](bool ok, const char* what) {
    if (!ok) throw LogicError(std::string("WallContactElement: ") + what);
  };
  require(std::isfinite(p.contact_radius) && p.contact_radius > 0.0, "the contact radius must be positive");
  require(std::isfinite(p.normal_stiffness) && p.normal_stiffness > 0.0, "the normal stiffness must be positive");
  require(std::isfinite(p.normal_damping) && p.normal_damping >= 0.0, "the normal damping must be >= 0");
  require(std::isfinite(p.axial_friction) && p.axial_friction >= 0.0, "the axial friction must be >= 0");
  require(std::isfinite(p.tangential_friction) && p.tangential_friction >= 0.0,
          "the tangential friction must be >= 0");
  require(!HasFriction(p) || (std::isfinite(p.regularization_velocity) && p.regularization_velocity > 0.0),
          "friction needs a positive regularization velocity");
  if (p.prescribed_sliding) {
    require(std::isfinite(p.prescribed_sliding->axial_speed) && std::isfinite(p.prescribed_sliding->rotary_speed),
            "the prescribed sliding speeds must be finite");
  }
}

}  // namespace

WallContactElement::WallContactElement(const Body* body, Index node, std::shared_ptr<const Wellbore> wellbore,
                                       const WallContactParameters& parameters, double md_guess)
    : ForceElement({body}), node_(node), wellbore_(std::move(wellbore)), parameters_(parameters) {
  if (!wellbore_) throw LogicError("WallContactElement: no wellbore");
  if (wellbore_->hole.empty()) throw LogicError("WallContactElement: the hole profile is empty");
  if (node < 0 || node >= body->node_count()) throw LogicError("WallContactElement: node outside the body");
  CheckParameters(parameters_);
  const well::Trajectory& path = wellbore_->trajectory;
  const double start = std::isfinite(md_guess) ? md_guess : path.start_md();
  md_hint_.store(std::clamp(start, path.start_md(), path.end_md()), std::memory_order_relaxed);
}

std::string WallContactElement::Describe() const {
  const Body& body = *bodies()[0];
  return fmt::format("wall contact at {:.4g} m from the bit", body.NodeS(node_));
}

WallContactParameters WallContactElement::EffectiveParameters(const LoadParameters& load) const {
  WallContactParameters p = parameters_;
  const WallFriction friction =
      EffectiveFriction({{p.axial_friction, p.tangential_friction}, p.cased}, load);
  p.axial_friction = friction.axial;
  p.tangential_friction = friction.tangential;
  if (load.sliding_mode == SlidingMode::kVelocities) p.prescribed_sliding.reset();
  if (load.sliding_mode == SlidingMode::kPrescribed) p.prescribed_sliding = load.sliding;
  return p;
}

namespace {
// The parameters as built are the effective ones (no copy needed).
bool AsBuilt(const LoadParameters& load) {
  return load.friction_factor == 1.0 && !load.OverridesFriction() && load.sliding_mode == SlidingMode::kAsBuilt;
}
}  // namespace

void WallContactElement::DoEvaluate(const ElementState& state, bool with_matrices, ElementContribution& out) const {
  const Body& body = *bodies()[0];
  const BodyPose& pose = *state.poses[0];
  const NodeMotion motion = ComputeNodeMotion(body, pose, node_, state.velocity);
  const HoleGeometry g = LocateInHole(*wellbore_, motion.position, md_hint_.load(std::memory_order_relaxed),
                                      parameters_.contact_radius);
  md_hint_.store(g.path_md, std::memory_order_relaxed);
  const ContactForce c =
      AsBuilt(state.parameters)
          ? ComputeContactForce(g, motion, parameters_, with_matrices)
          : ComputeContactForce(g, motion, EffectiveParameters(state.parameters), with_matrices);
  if (!c.active) return;
  // The force acts at the contact point x + R_c n: moment R_c n × F about the node.
  AddPointForce(body, pose, node_, motion, c.force, parameters_.contact_radius * g.normal, &c.jacobian,
                with_matrices, out);
}

double WallContactElement::DoPotentialEnergy(const ElementState& state) const {
  const Body& body = *bodies()[0];
  const Vec3 x = state.poses[0]->NodePosition(body, node_);
  const HoleGeometry g = LocateInHole(*wellbore_, x, md_hint_.load(std::memory_order_relaxed),
                                      parameters_.contact_radius);
  return g.penetration > 0.0 ? 0.5 * parameters_.normal_stiffness * g.penetration * g.penetration : 0.0;
}

double WallContactElement::DoPotentialEnergyChange(const ElementState& from, const ElementState& to) const {
  const double elastic = DoPotentialEnergy(to) - DoPotentialEnergy(from);
  const WallContactParameters effective = EffectiveParameters(to.parameters);
  if (effective.tangential_friction == 0.0 && effective.axial_friction == 0.0) return elastic;
  const WallContactResult before = Result(from), after = Result(to);
  if (!before.in_contact && !after.in_contact) return elastic;
  const NodeMove move = NodeMoveBetween(*bodies()[0], *from.poses[0], *to.poses[0], node_);
  const double work = 0.5 * (before.friction_force + after.friction_force).dot(move.translation) +
                      0.5 * (before.moment + after.moment).dot(move.rotation);
  return elastic - work;
}

bool WallContactElement::DoPenalty(const ElementState& state, double& value, double& stiffness, VecX& gradient) const {
  const Body& body = *bodies()[0];
  const BodyPose& pose = *state.poses[0];
  const NodeMotion motion = ComputeNodeMotion(body, pose, node_, VecX::Zero(local_size()));
  const HoleGeometry g = LocateInHole(*wellbore_, motion.position, md_hint_.load(std::memory_order_relaxed),
                                      parameters_.contact_radius);
  value = g.penetration;
  stiffness = parameters_.normal_stiffness;
  if (!(g.distance > 0.0)) {  // on the hole axis: no direction to the wall, so no gradient
    gradient = VecX::Zero(local_size());
    return true;
  }
  // The residual carries −Lᵀ F for a force F on the node: F = −∇δ gives Lᵀ ∇δ.
  ElementContribution mapped;
  mapped.force = VecX::Zero(local_size());
  const Vec3 gradient_position = g.normal - (g.hole.slope / g.scale) * g.tangent;
  AddPointForce(body, pose, node_, motion, -gradient_position, Vec3::Zero(), nullptr, false, mapped);
  gradient = std::move(mapped.force);
  return true;
}

WallContactResult WallContactElement::Result(const ElementState& state) const {
  const Body& body = *bodies()[0];
  const NodeMotion motion = ComputeNodeMotion(body, *state.poses[0], node_, state.velocity);
  const HoleGeometry g = LocateInHole(*wellbore_, motion.position, md_hint_.load(std::memory_order_relaxed),
                                      parameters_.contact_radius);
  const ContactForce c = ComputeContactForce(g, motion, EffectiveParameters(state.parameters), false);
  WallContactResult r;
  r.in_contact = c.active;
  r.md = g.md;
  r.penetration = g.penetration;
  r.offset = g.distance;
  r.hole_diameter = 2.0 * g.hole.radius;
  r.normal_force = c.normal_force;
  r.normal = g.normal;
  r.contact_point = motion.position + parameters_.contact_radius * g.normal;
  r.friction_force = c.friction;
  r.force = c.force;
  r.moment = c.moment;
  r.axial_friction = g.tangent.dot(c.friction);
  r.torque = g.tangent.dot(c.moment);
  const well::PathFrame frame = well::HighSideFrame(g.tangent);
  double angle = std::atan2(g.normal.dot(frame.right), g.normal.dot(frame.high_side));
  if (angle < 0.0) angle += 2.0 * kPi;
  r.high_side_angle = angle >= 2.0 * kPi ? 0.0 : angle;
  return r;
}

}  // namespace drillflex::model
