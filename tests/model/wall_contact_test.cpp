// Wellbore contact (method.md §6) and the node-force helper (model/node_force.hpp):
//  * exact Jacobians (stiffness at non-zero velocity, damping) against central differences, for a
//    synthetic motion-dependent nodal force and for the contact in a straight inclined hole and in
//    a curved (build-and-turn) hole with a tapered section, sliding and viscous friction, prescribed
//    sliding; the elastic contact force against the gradient of its potential;
//  * the force direction and magnitude at the low side of a horizontal hole, friction and torque;
//  * the high-side angle convention;
//  * static strings lying on the low side: equilibrium of wall forces, supports and weight in an
//    inclined hole, and the tangency length and end reaction of a pinned string in a horizontal
//    hole against beam theory (validation.md V4, slick pendulum with P = 0).
#include "model/wall_contact.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <random>

#include "core/error.hpp"
#include "core/so3.hpp"
#include "model/builder.hpp"
#include "model/spring_elements.hpp"
#include "model_test_support.hpp"
#include "model/static_problem.hpp"
#include "solvers/newton.hpp"
#include "solvers/problem.hpp"

namespace drillflex::model {
namespace wall_contact_test {

// An element of another model whose bodies are copies of this model's (the builder's couplings,
// supports and loads, reused without rebuilding them).
class ForwardedElement : public ForceElement {
 public:
  ForwardedElement(const ForceElement* inner, std::vector<const Body*> bodies)
      : ForceElement(std::move(bodies)), inner_(inner) {}
  std::string Describe() const override { return inner_->Describe(); }
  const ForceElement& inner() const { return *inner_; }

 protected:
  void DoEvaluate(const ElementState& state, bool with_matrices, ElementContribution& out) const override {
    inner_->Evaluate(state, with_matrices, out);
  }
  double DoPotentialEnergy(const ElementState& state) const override { return inner_->PotentialEnergy(state); }

 private:
  const ForceElement* inner_;
};

// The model's force elements alone (no inertia, no elasticity), so that their stiffness can be
// checked at non-zero velocities (SystemModel::IterationMatrix refuses v ≠ 0 with cK ≠ 0).
class ElementsProblem : public solvers::Problem {
 public:
  explicit ElementsProblem(const SystemModel& model) : model_(model) {}
  Index num_positions() const override { return model_.num_positions(); }
  Index num_velocities() const override { return model_.num_velocities(); }
  VecX Increment(const VecX& q, const VecX& dv) const override { return model_.Increment(q, dv); }
  VecX Residual(double t, const VecX& q, const VecX& v, const VecX&) const override {
    VecX residual = VecX::Zero(num_velocities());
    const auto poses = model_.Poses(q);
    ElementContribution c;
    for (const auto& element : model_.elements()) {
      element->Evaluate(model_.StateOf(*element, poses, v, t, 1.0), false, c);
      int offset = 0;
      for (const Body* body : element->bodies()) {
        residual.segment(body->v_offset, body->velocity_count()) += c.force.segment(offset, body->velocity_count());
        offset += body->velocity_count();
      }
    }
    return residual;
  }
  SparseMat IterationMatrix(double t, const VecX& q, const VecX& v, const VecX&, double cK, double cD,
                            double) const override {
    MatX dense = MatX::Zero(num_velocities(), num_velocities());
    const auto poses = model_.Poses(q);
    ElementContribution c;
    for (const auto& element : model_.elements()) {
      element->Evaluate(model_.StateOf(*element, poses, v, t, 1.0), true, c);
      const Body& body = *element->bodies()[0];  // one-body elements only
      dense.block(body.v_offset, body.v_offset, body.velocity_count(), body.velocity_count()) +=
          cK * c.stiffness + cD * c.damping;
    }
    return dense.sparseView();
  }
  double Energy(const VecX& q) const {
    const auto poses = model_.Poses(q);
    const VecX v = VecX::Zero(num_velocities());
    double energy = 0.0;
    for (const auto& element : model_.elements()) energy += element->PotentialEnergy(model_.StateOf(*element, poses, v, 0.0, 1.0));
    return energy;
  }

 private:
  const SystemModel& model_;
};

well::SurveyStation Station(double md, double inclination_deg, double azimuth_deg) {
  return {md, inclination_deg * kDegree, azimuth_deg * kDegree};
}

std::shared_ptr<const Wellbore> StraightWell(double inclination_deg, double azimuth_deg, double diameter) {
  well::Trajectory path({Station(0.0, inclination_deg, azimuth_deg), Station(500.0, inclination_deg, azimuth_deg)});
  return std::make_shared<const Wellbore>(Wellbore{std::move(path), well::HoleProfile({{{}, diameter, {}}})});
}

// Build-and-turn at 1°/m (inclination 20° → 50°, azimuth 10° → 40° over 100..130 m MD); the hole
// narrows linearly from 0.23 m to 0.21 m between MD 110 and 125 (slope dR_h/ds = −6.7e-4).
std::shared_ptr<const Wellbore> CurvedTaperedWell() {
  well::Trajectory path({Station(0.0, 0.0, 0.0), Station(100.0, 20.0, 10.0), Station(130.0, 50.0, 40.0),
                         Station(400.0, 50.0, 40.0)});
  well::HoleProfile hole({{110.0, 0.23, {}}, {125.0, 0.23, 0.21}, {{}, 0.21, {}}});
  return std::make_shared<const Wellbore>(Wellbore{std::move(path), std::move(hole)});
}

// A steel pipe (OD 0.127 m, ID 0.1086 m) of `length` cut into `bodies` bodies, in `wellbore`.
ModelInput PipeInput(double length, int bodies, int elements, int modes, const Wellbore& wellbore, double bit_md,
                     double gravity) {
  ModelInput input;
  Component pipe;
  pipe.type = ComponentType::Collar;
  pipe.outer_diameter = 0.127;
  pipe.inner_diameter = 0.1086;
  pipe.length = length;
  input.string.components.push_back(pipe);
  input.materials["steel"] = fe::Material{"steel", 2.1e11, 0.3, 7850.0};
  input.settings.body_length = length / bodies + 1e-9;
  input.settings.elements_per_body = elements;
  input.settings.modes_per_body = modes;
  input.gravity = gravity;
  input.well = MakeWellbore(wellbore.trajectory);  // the path alone: no hole, no contact
  input.bit_md = bit_md;
  return input;
}

struct ContactModel {
  std::unique_ptr<BuiltModel> built;    // owns the forwarded elements
  std::unique_ptr<SystemModel> system;  // copies of the bodies, forwarded elements, contacts
  std::vector<const WallContactElement*> contacts;
  std::vector<const SupportElement*> supports;  // the builder's, in case order
};

// The built model's bodies, optionally its elements, and a contact circle at every node (a joint's
// two coincident nodes get one circle, on the lower body's end node).
ContactModel WithContacts(const ModelInput& input, const std::shared_ptr<const Wellbore>& wellbore,
                          const WallContactParameters& parameters, bool keep_elements) {
  ContactModel m;
  cms::ReductionCache cache;
  m.built = std::make_unique<BuiltModel>(BuildSystemModel(input, cache));
  // The input has no hole profile, so the builder adds no wall contacts of its own.
  if (!m.built->contacts.empty()) throw LogicError("WithContacts: the built model has wall contacts");
  const SystemModel& source = m.built->system;
  std::vector<Body> bodies = source.bodies();
  std::vector<std::unique_ptr<ForceElement>> elements;
  if (keep_elements) {
    for (const auto& element : source.elements()) {
      std::vector<const Body*> mapped;
      for (const Body* body : element->bodies()) mapped.push_back(&bodies[source.IndexOf(body)]);
      elements.push_back(std::make_unique<ForwardedElement>(element.get(), std::move(mapped)));
    }
    for (const auto handle : m.built->supports) m.supports.push_back(&source.Get(handle));
  }
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    const Body& body = bodies[b];
    for (int k = (b == 0 ? 0 : 1); k < body.node_count(); ++k) {
      const double s = body.s_start + body.reduced->node_positions[k].x();
      auto contact = std::make_unique<WallContactElement>(&body, k, wellbore, parameters, input.bit_md - s);
      m.contacts.push_back(contact.get());
      elements.push_back(std::move(contact));
    }
  }
  m.system = std::make_unique<SystemModel>(std::move(bodies), std::move(elements), source.length());
  m.system->set_force_scale(m.built->force_scale);
  return m;
}

ElementState StateOf(const ContactModel& m, const ForceElement& element, const std::vector<BodyPose>& poses,
                     const VecX& v) {
  return m.system->StateOf(element, poses, v, 0.0, 1.0);
}

// Every body moved by `lateral` (string frame: y right, z high side) plus small random rotations
// (rad), translations (m) and modal coordinates.
VecX ShiftedPositions(const SystemModel& model, const Vec3& lateral, double rotation, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  VecX dv = VecX::Zero(model.num_velocities());
  for (const Body& body : model.bodies()) {
    const Mat3 frame = body.reference_orientation.toRotationMatrix();
    dv.segment<3>(body.v_offset) = frame * lateral + 0.002 * Vec3(u(rng), u(rng), u(rng));
    dv.segment<3>(body.v_offset + 3) = rotation * Vec3(u(rng), u(rng), u(rng));
    for (int j = 0; j < body.flexible_count; ++j) dv[body.v_offset + 6 + j] = 1e-4 * u(rng);
  }
  return model.Increment(model.ReferencePositions(), dv);
}

VecX RandomVelocities(const SystemModel& model, double speed, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  VecX v(model.num_velocities());
  for (const Body& body : model.bodies()) {
    for (int j = 0; j < 3; ++j) v[body.v_offset + j] = speed * u(rng);
    for (int j = 3; j < 6; ++j) v[body.v_offset + j] = 10.0 * speed * u(rng);  // R_c ω ~ speed
    for (int j = 6; j < body.velocity_count(); ++j) v[body.v_offset + j] = speed * u(rng);
  }
  return v;
}

int ActiveContacts(const ContactModel& m, const VecX& q, const VecX& v) {
  const auto poses = m.system->Poses(q);
  int active = 0;
  for (const WallContactElement* contact : m.contacts) {
    active += contact->Result(StateOf(m, *contact, poses, v)).in_contact ? 1 : 0;
  }
  return active;
}

struct JacobianErrors {
  double stiffness = 0.0;
  double damping = 0.0;
};

JacobianErrors ElementJacobianErrors(const SystemModel& model, const VecX& q, const VecX& v) {
  const ElementsProblem problem(model);
  const VecX a = VecX::Zero(model.num_velocities());
  JacobianErrors errors;
  errors.stiffness = solvers::RelativeMatrixError(
      MatX(problem.IterationMatrix(0.0, q, v, a, 1.0, 0.0, 0.0)),
      MatX(solvers::FiniteDifferenceIterationMatrix(problem, 0.0, q, v, a, 1.0, 0.0, 0.0, 1e-6)));
  errors.damping = solvers::RelativeMatrixError(
      MatX(problem.IterationMatrix(0.0, q, v, a, 0.0, 1.0, 0.0)),
      MatX(solvers::FiniteDifferenceIterationMatrix(problem, 0.0, q, v, a, 0.0, 1.0, 0.0, 1e-6)));
  return errors;
}

WallContactParameters FrictionParameters() {
  WallContactParameters p;
  p.contact_radius = 0.08;
  p.normal_stiffness = 1e5;
  p.normal_damping = 2e3;
  p.axial_friction = 0.3;
  p.tangential_friction = 0.2;
  p.regularization_velocity = 1e-3;
  return p;
}

// ---------------------------------------------------------------------------------------------
// The node-force helpers on a synthetic force with every kind of dependence (d = r_k − x0):
//   AddNodeForce:  F = K_r d + K_v ṙ_k + K_w ω_k + a (d × ṙ_k),  M = M_r d + M_v ṙ_k + M_w ω_k + b (ω_k × d);
//   AddPointForce: the same F at the point r_k + ℓ, ℓ = L d + c |d|² e,
// with random 3 × 3 matrices.
class SyntheticNodeForce : public ForceElement {
 public:
  SyntheticNodeForce(const Body* body, int node, bool at_point, std::mt19937& rng)
      : ForceElement({body}), node_(node), at_point_(at_point) {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (Mat3* m : {&kr_, &kv_, &kw_, &mr_, &mv_, &mw_}) *m = Mat3::NullaryExpr([&] { return 1e3 * u(rng); });
    lever_ = Mat3::NullaryExpr([&] { return 0.1 * u(rng); });
    origin_ = body->reference_position + Vec3(u(rng), u(rng), u(rng));
    direction_ = Vec3(u(rng), u(rng), u(rng));
  }
  std::string Describe() const override { return "synthetic nodal force"; }

 protected:
  void DoEvaluate(const ElementState& state, bool with_matrices, ElementContribution& out) const override {
    const Body& body = *bodies()[0];
    const NodeMotion m = ComputeNodeMotion(body, *state.poses[0], node_, state.velocity);
    const Vec3 d = m.position - origin_;
    const Vec3 force = kr_ * d + kv_ * m.velocity + kw_ * m.angular_velocity + a_ * d.cross(m.velocity);
    const Mat3 force_position = kr_ - a_ * so3::Skew(m.velocity);
    const Mat3 force_velocity = kv_ + a_ * so3::Skew(d);
    if (at_point_) {
      PointForceJacobian J;
      J.force_position = force_position;
      J.force_velocity = force_velocity;
      J.force_angular_velocity = kw_;
      J.lever_position = lever_ + 2.0 * c_ * direction_ * d.transpose();
      const Vec3 lever = lever_ * d + c_ * d.squaredNorm() * direction_;
      AddPointForce(body, *state.poses[0], node_, m, force, lever, &J, with_matrices, out);
      return;
    }
    const Vec3 moment = mr_ * d + mv_ * m.velocity + mw_ * m.angular_velocity + b_ * m.angular_velocity.cross(d);
    NodeForceJacobian J;
    J.force_position = force_position;
    J.force_velocity = force_velocity;
    J.force_angular_velocity = kw_;
    J.moment_position = mr_ + b_ * so3::Skew(m.angular_velocity);
    J.moment_velocity = mv_;
    J.moment_angular_velocity = mw_ - b_ * so3::Skew(d);
    AddNodeForce(body, *state.poses[0], node_, m, force, moment, &J, with_matrices, out);
  }
  double DoPotentialEnergy(const ElementState&) const override { return 0.0; }

 private:
  int node_;
  bool at_point_;
  Mat3 kr_, kv_, kw_, mr_, mv_, mw_, lever_;
  Vec3 origin_, direction_;
  double a_ = 300.0, b_ = 200.0, c_ = 0.3;
};

TEST(NodeForceTest, MotionDependentForcesMatchCentralDifferences) {
  const auto wellbore = StraightWell(35.0, 20.0, 0.3);
  const ModelInput input = PipeInput(6.0, 2, 4, 5, *wellbore, 100.0, 0.0);
  cms::ReductionCache cache;
  const BuiltModel built = BuildSystemModel(input, cache);
  for (const bool at_point : {false, true}) {
    std::vector<Body> bodies = built.system.bodies();
    std::vector<std::unique_ptr<ForceElement>> elements;
    std::mt19937 rng(3);
    for (const Body& body : bodies) {
      for (const Index k : {Index{0}, Index{2}, body.node_count() - 1}) {
        elements.push_back(std::make_unique<SyntheticNodeForce>(&body, k, at_point, rng));
      }
    }
    const SystemModel model(std::move(bodies), std::move(elements), built.system.length());
    const VecX q = ShiftedPositions(model, Vec3(0.0, 0.01, -0.02), 0.05, rng);
    for (const double speed : {0.0, 0.7}) {
      const JacobianErrors errors = ElementJacobianErrors(model, q, RandomVelocities(model, speed, rng));
      std::printf("[ measure  ] synthetic %s, speed %.1f: stiffness %.2e, damping %.2e\n",
                  at_point ? "point force" : "node force and moment", speed, errors.stiffness, errors.damping);
      EXPECT_LT(errors.stiffness, 1e-7);
      EXPECT_LT(errors.damping, 1e-7);
    }
  }
}

// ---------------------------------------------------------------------------------------------
// Contact Jacobians. Every node is pushed 0.07 m off the axis (clearance 0.025–0.035 m), so all
// contacts carry load; the random velocities keep |v_t| far above v_ε (or far below it for the
// viscous branch).

struct HoleCase {
  const char* name;
  bool curved;
};

class ContactJacobianTest : public ::testing::TestWithParam<HoleCase> {
 protected:
  ContactModel Make(const WallContactParameters& parameters, double bit_md = 124.0) const {
    const auto wellbore = GetParam().curved ? CurvedTaperedWell() : StraightWell(40.0, 30.0, 0.22);
    const ModelInput input = PipeInput(6.0, 2, 5, 4, *wellbore, bit_md, 0.0);
    return WithContacts(input, wellbore, parameters, false);
  }
  void Check(const WallContactParameters& parameters, double speed, const char* what) const {
    const ContactModel m = Make(parameters);
    std::mt19937 rng(11);
    const VecX q = ShiftedPositions(*m.system, Vec3(0.0, 0.045, -0.054), 0.004, rng);
    const VecX v = RandomVelocities(*m.system, speed, rng);
    ASSERT_EQ(ActiveContacts(m, q, v), static_cast<int>(m.contacts.size())) << what;
    const JacobianErrors errors = ElementJacobianErrors(*m.system, q, v);
    std::printf("[ measure  ] %s hole, %s: stiffness %.2e, damping %.2e\n", GetParam().name, what, errors.stiffness,
                errors.damping);
    EXPECT_LT(errors.stiffness, 1e-6) << what;
    EXPECT_LT(errors.damping, 1e-6) << what;
  }
};

TEST_P(ContactJacobianTest, SlidingFriction) { Check(FrictionParameters(), 0.5, "sliding friction"); }

TEST_P(ContactJacobianTest, ViscousFrictionBranch) {
  WallContactParameters p = FrictionParameters();
  p.regularization_velocity = 0.5;  // |v_t| ~ 1e-3 m/s: far below v_ε
  Check(p, 1e-3, "viscous friction");
}

TEST_P(ContactJacobianTest, FrictionlessWithDamping) {
  WallContactParameters p = FrictionParameters();
  p.axial_friction = p.tangential_friction = 0.0;
  Check(p, 0.5, "frictionless");
}

TEST_P(ContactJacobianTest, PrescribedSliding) {
  WallContactParameters p = FrictionParameters();
  p.prescribed_sliding = PrescribedSliding{0.4, 3.0};
  Check(p, 0.5, "prescribed sliding");
}

// Where the hole diameter is constant the elastic normal force is the gradient of ½ k_n δ²,
// curvature included (at rest: no friction or damping forces). In the curved well the string is
// moved to 102–108 m MD, on the arc but above the taper.
TEST_P(ContactJacobianTest, ElasticForceIsTheGradientOfThePotential) {
  const ContactModel m = Make(FrictionParameters(), GetParam().curved ? 108.0 : 124.0);
  const ElementsProblem problem(*m.system);
  std::mt19937 rng(5);
  const VecX q = ShiftedPositions(*m.system, Vec3(0.0, 0.045, -0.054), 0.004, rng);
  const VecX zero = VecX::Zero(m.system->num_velocities());
  ASSERT_EQ(ActiveContacts(m, q, zero), static_cast<int>(m.contacts.size()));
  const VecX residual = problem.Residual(0.0, q, zero, zero);
  VecX gradient(m.system->num_velocities());
  const double h = 1e-6;
  for (int j = 0; j < gradient.size(); ++j) {
    VecX dv = VecX::Zero(gradient.size());
    dv[j] = h;
    gradient[j] = (problem.Energy(m.system->Increment(q, dv)) - problem.Energy(m.system->Increment(q, -dv))) / (2 * h);
  }
  const double error = (residual - gradient).norm() / residual.norm();
  std::printf("[ measure  ] %s hole: |R - grad E|/|R| = %.2e\n", GetParam().name, error);
  EXPECT_LT(error, 1e-7);
}

INSTANTIATE_TEST_SUITE_P(Wall, ContactJacobianTest,
                         ::testing::Values(HoleCase{"straight_inclined", false}, HoleCase{"curved_tapered", true}),
                         [](const auto& info) { return std::string(info.param.name); });

// ---------------------------------------------------------------------------------------------
// One 3 m body, bit end at 50 m MD, moved rigidly by `shift` (global); its contact at node 5 sits
// at s = 1.5 m, MD 48.5 m.
struct OneBody {
  ContactModel m;
  VecX q;
  const WallContactElement& contact() const { return *m.contacts[5]; }
  VecX Velocity(const Vec3& translation, const Vec3& body_rate) const {
    VecX v = VecX::Zero(m.system->num_velocities());
    v.head<3>() = translation;
    v.segment<3>(3) = body_rate;
    return v;
  }
  WallContactResult Result(const VecX& v) const {
    const auto poses = m.system->Poses(q);
    return contact().Result(StateOf(m, contact(), poses, v));
  }
};

OneBody MakeOneBody(const std::shared_ptr<const Wellbore>& wellbore, const WallContactParameters& parameters,
                    const Vec3& shift) {
  OneBody one{WithContacts(PipeInput(3.0, 1, 10, 4, *wellbore, 50.0, 0.0), wellbore, parameters, false), VecX()};
  VecX dv = VecX::Zero(one.m.system->num_velocities());
  dv.head<3>() = shift;
  one.q = one.m.system->Increment(one.m.system->ReferencePositions(), dv);
  return one;
}

WallContactParameters HorizontalParameters() {
  WallContactParameters p;
  p.contact_radius = 0.0635;
  p.normal_stiffness = 1e6;
  p.axial_friction = 0.3;
  p.tangential_friction = 0.2;
  p.regularization_velocity = 1e-4;
  return p;
}

// Horizontal hole due north: t = +x, high side = −z (up), right = +y (east). The node is pushed
// 0.05 m down: δ = 0.05 + 0.0635 − 0.1 = 0.0135 m.
TEST(WallContactTest, NodeOnTheLowSideOfAHorizontalHole) {
  const auto wellbore = StraightWell(90.0, 0.0, 0.2);
  const WallContactParameters p = HorizontalParameters();
  const OneBody one = MakeOneBody(wellbore, p, Vec3(0.0, 0.0, 0.05));
  const double penetration = 0.05 + 0.0635 - 0.1;
  const double normal = 1e6 * penetration;
  const VecX rest = VecX::Zero(one.m.system->num_velocities());
  const WallContactResult r = one.Result(rest);
  EXPECT_TRUE(r.in_contact);
  EXPECT_NEAR(r.penetration, penetration, 1e-12);
  EXPECT_NEAR(r.normal_force, normal, 1e-6);
  EXPECT_NEAR((r.force - Vec3(0.0, 0.0, -normal)).norm(), 0.0, 1e-6);  // pushes the node up
  EXPECT_NEAR(r.md, 48.5, 1e-9);
  EXPECT_NEAR(r.hole_diameter, 0.2, 1e-15);
  EXPECT_NEAR(r.high_side_angle, kPi, 1e-12);
  EXPECT_NEAR(r.moment.norm() + r.friction_force.norm(), 0.0, 1e-12);  // at rest: no friction
  // The element adds −F to the node's translation rows of the residual.
  const auto poses = one.m.system->Poses(one.q);
  ElementContribution out;
  one.contact().Evaluate(StateOf(one.m, one.contact(), poses, rest), false, out);
  EXPECT_NEAR((out.force.head<3>() - Vec3(0.0, 0.0, normal)).norm(), 0.0, 1e-6);
  EXPECT_NEAR(one.contact().PotentialEnergy(StateOf(one.m, one.contact(), poses, rest)),
              0.5 * 1e6 * penetration * penetration, 1e-9);
  // Sliding down-hole at 0.3 m/s: axial friction −μ_a N t, moment R_c n × F_t = (0, −R_c μ_a N, 0).
  const WallContactResult sliding = one.Result(one.Velocity(Vec3(0.3, 0.0, 0.0), Vec3::Zero()));
  EXPECT_NEAR((sliding.friction_force - Vec3(-0.3 * normal, 0.0, 0.0)).norm(), 0.0, 1e-6);
  EXPECT_NEAR((sliding.moment - Vec3(0.0, -0.0635 * 0.3 * normal, 0.0)).norm(), 0.0, 1e-6);
  EXPECT_NEAR(sliding.axial_friction, -0.3 * normal, 1e-6);
  // Turning at 2 rad/s about the body x axis (up-hole): ω = −2 t, the contact point moves east at
  // 2 R_c; friction −μ_t N east and a torque +μ_t N R_c about t that opposes the spin.
  const WallContactResult turning = one.Result(one.Velocity(Vec3::Zero(), Vec3(2.0, 0.0, 0.0)));
  EXPECT_NEAR((turning.friction_force - Vec3(0.0, -0.2 * normal, 0.0)).norm(), 0.0, 1e-6);
  EXPECT_NEAR(turning.torque, 0.2 * normal * 0.0635, 1e-6);
  // Both: F_t = −N (μ_a v_a, μ_t v_θ... ) / |v_t| with v_c = (0.3, 2 R_c, 0).
  const WallContactResult both = one.Result(one.Velocity(Vec3(0.3, 0.0, 0.0), Vec3(2.0, 0.0, 0.0)));
  const double speed = std::hypot(0.3, 2.0 * 0.0635);
  EXPECT_NEAR((both.friction_force - Vec3(-0.3 * 0.3, -0.2 * 2.0 * 0.0635, 0.0) * normal / speed).norm(), 0.0, 1e-6);
}

TEST(WallContactTest, PrescribedSlidingSetsTheFrictionDirection) {
  const auto wellbore = StraightWell(90.0, 0.0, 0.2);
  WallContactParameters p = HorizontalParameters();
  const double normal = 1e6 * (0.05 + 0.0635 - 0.1);
  // Pulling out (up-hole) at 0.5 m/s: the wall drags the string down-hole, +μ_a N along t.
  p.prescribed_sliding = PrescribedSliding{0.5, 0.0};
  const OneBody pulling = MakeOneBody(wellbore, p, Vec3(0.0, 0.0, 0.05));
  const VecX rest = VecX::Zero(pulling.m.system->num_velocities());
  EXPECT_NEAR(pulling.Result(rest).axial_friction, 0.3 * normal, 1e-6);
  EXPECT_NEAR(pulling.Result(rest).torque, 0.0, 1e-9);
  // Running in: −μ_a N.
  p.prescribed_sliding = PrescribedSliding{-0.5, 0.0};
  EXPECT_NEAR(MakeOneBody(wellbore, p, Vec3(0.0, 0.0, 0.05)).Result(rest).axial_friction, -0.3 * normal, 1e-6);
  // Rotating clockwise looking down-hole (+ about t): the wall torque −μ_t N R_c opposes it.
  p.prescribed_sliding = PrescribedSliding{0.0, 10.0};
  const WallContactResult rotating = MakeOneBody(wellbore, p, Vec3(0.0, 0.0, 0.05)).Result(rest);
  EXPECT_NEAR(rotating.torque, -0.2 * normal * 0.0635, 1e-6);
  EXPECT_NEAR(rotating.axial_friction, 0.0, 1e-9);
  EXPECT_NEAR(rotating.friction_force.norm(), 0.2 * normal, 1e-6);
}

// The high-side angle from the hole's high side toward the right, looking down-hole.
// The friction of a string turning steadily at Ω, linearized (docs/method.md "The friction of a rotating
// string, linearized"): the contact slides around the hole at Ω R_c, so a small axial velocity v_a tilts
// the Coulomb force, F_a = −μ_a N v_a / √(v_a² + (Ω R_c)²) ≈ −(μ_a N / Ω R_c) v_a: a viscous damping
// along the hole; across it the force's size does not change to first order (d(v_θ/|v|)/dv_θ = 0 at
// v = Ω R_c e_θ) and a radial velocity does not slide. The prescribed sliding (the static's) and the
// same node turning at Ω in its state velocities (the transient's path) give the same force and the
// same ∂F/∂v.
TEST(WallContactTest, RotatingFrictionLinearizedIsAnAxialDampingMuNOverOmegaR) {
  const auto wellbore = StraightWell(90.0, 0.0, 0.2);
  WallContactParameters p = HorizontalParameters();
  const double normal = 1e6 * (0.05 + 0.0635 - 0.1), spin = 10.0;  // N, rad/s
  const OneBody free_node = MakeOneBody(wellbore, p, Vec3(0.0, 0.0, 0.05));
  p.prescribed_sliding = PrescribedSliding{0.0, spin};
  const OneBody prescribed = MakeOneBody(wellbore, p, Vec3(0.0, 0.0, 0.05));
  const VecX rest = VecX::Zero(prescribed.m.system->num_velocities());
  // Clockwise looking down-hole: ω = +Ω t, the body's x axis pointing up-hole (t = −x_body).
  const VecX turning = free_node.Velocity(Vec3::Zero(), Vec3(-spin, 0.0, 0.0));
  ElementContribution steady, moving;
  prescribed.contact().Evaluate(StateOf(prescribed.m, prescribed.contact(), prescribed.m.system->Poses(prescribed.q), rest),
                                true, steady);
  free_node.contact().Evaluate(StateOf(free_node.m, free_node.contact(), free_node.m.system->Poses(free_node.q), turning),
                               true, moving);
  EXPECT_NEAR((steady.force - moving.force).norm(), 0.0, 1e-9 * normal);
  EXPECT_NEAR((steady.damping - moving.damping).norm(), 0.0, 1e-9 * steady.damping.norm());
  // The residual carries −F: D = −∂F/∂v. Hole along +x (north), contact on the low side (+z).
  const double axial_damping = 0.3 * normal / (spin * 0.0635);  // μ_a N / (Ω R_c), N·s/m
  EXPECT_NEAR(steady.damping(0, 0), axial_damping, 1e-9 * axial_damping);
  EXPECT_NEAR(steady.damping(1, 1), 0.0, 1e-9 * axial_damping);  // around the hole
  EXPECT_NEAR(steady.damping(2, 2), 0.0, 1e-9 * axial_damping);  // radial: no damping in p
  std::printf("[ measure  ] rotating friction: axial damping %.6g N*s/m (mu N / Omega R %.6g)\n", steady.damping(0, 0),
              axial_damping);
}

TEST(WallContactTest, HighSideAngleConvention) {
  const auto wellbore = StraightWell(60.0, 45.0, 0.3);
  const well::PathFrame frame = wellbore->trajectory.Frame(48.5);
  WallContactParameters p = HorizontalParameters();
  struct Direction {
    Vec3 shift;
    double angle;
  };
  for (const Direction& d : {Direction{frame.high_side, 0.0}, Direction{frame.right, 0.5 * kPi},
                             Direction{-frame.high_side, kPi}, Direction{-frame.right, 1.5 * kPi},
                             Direction{(frame.right - frame.high_side).normalized(), 0.75 * kPi}}) {
    const OneBody one = MakeOneBody(wellbore, p, 0.04 * d.shift);
    const WallContactResult r = one.Result(VecX::Zero(one.m.system->num_velocities()));
    EXPECT_NEAR(std::remainder(r.high_side_angle - d.angle, 2.0 * kPi), 0.0, 1e-9) << d.angle;
    EXPECT_GE(r.high_side_angle, 0.0);
    EXPECT_LT(r.high_side_angle, 2.0 * kPi);
    EXPECT_NEAR(r.offset, 0.04, 1e-10);
    EXPECT_NEAR(r.md, 48.5, 1e-9);
    EXPECT_FALSE(r.in_contact);  // clearance 0.15 − 0.0635 > 0.04
  }
}

// Below the last survey station the hole continues straight along the last tangent: a node moved
// 2 m past the end of the path (500 m MD) is measured in its own normal plane there.
TEST(WallContactTest, BeyondTheEndOfThePath) {
  const auto wellbore = StraightWell(60.0, 45.0, 0.3);
  const well::PathFrame frame = wellbore->trajectory.Frame(500.0);
  WallContactParameters p = HorizontalParameters();
  auto one = OneBody{WithContacts(PipeInput(3.0, 1, 10, 4, *wellbore, 499.0, 0.0), wellbore, p, false), VecX()};
  VecX dv = VecX::Zero(one.m.system->num_velocities());
  dv.head<3>() = 2.0 * frame.tangent - 0.12 * frame.high_side;
  one.q = one.m.system->Increment(one.m.system->ReferencePositions(), dv);
  const auto poses = one.m.system->Poses(one.q);
  const VecX rest = VecX::Zero(one.m.system->num_velocities());
  const WallContactResult bit = one.m.contacts[0]->Result(StateOf(one.m, *one.m.contacts[0], poses, rest));
  EXPECT_NEAR(bit.md, 501.0, 1e-9);
  EXPECT_NEAR(bit.offset, 0.12, 1e-10);
  EXPECT_NEAR(bit.penetration, 0.12 + 0.0635 - 0.15, 1e-10);
  EXPECT_NEAR(bit.normal_force, 1e6 * (0.12 + 0.0635 - 0.15), 1e-4);
  EXPECT_NEAR(bit.high_side_angle, kPi, 1e-9);
}

// ---------------------------------------------------------------------------------------------
// Static strings on the low side: 30 m of pipe (10 bodies), held at the hole centre at both ends
// (y, z; plus x and torsion at the bit), contact circles of R_c = 0.0635 m in a 0.2 m hole.

struct StaticString {
  ContactModel m;
  VecX q;
};

StaticString SolveLyingString(double inclination_deg) {
  const auto wellbore = StraightWell(inclination_deg, 30.0, 0.2);
  ModelInput input = PipeInput(30.0, 10, 10, 6, *wellbore, 200.0, 9.81);
  Support bottom;
  bottom.at = 0.0;
  bottom.fixed = {true, true, true, true, false, false};
  Support top;
  top.at = 30.0;
  top.fixed = {false, true, true, false, false, false};
  input.supports = {bottom, top};
  WallContactParameters p;
  p.contact_radius = 0.0635;
  p.normal_stiffness = 1e7;
  p.axial_friction = p.tangential_friction = 0.25;  // no force at rest
  p.regularization_velocity = 0.01;
  StaticString s{WithContacts(input, wellbore, p, true), VecX()};
  StaticModelProblem problem(*s.m.system);
  solvers::NewtonOptions options;
  options.increment_tolerance = 1e-10;
  options.line_search.enabled = false;
  const solvers::NewtonResult result = solvers::SolveStatic(problem, s.m.system->ReferencePositions(), options);
  EXPECT_TRUE(result.converged);
  std::printf("[ measure  ] lying string at %.0f deg: %d iterations, %d load steps (%d rejected), |R| = %.2e N\n",
              inclination_deg, result.iterations, result.load_steps, result.rejected_steps, result.residual_norm);
  s.q = result.q;
  return s;
}

double StringWeight(const SystemModel& model, double gravity) {
  double mass = 0.0;
  for (const Body& body : model.bodies()) mass += body.reduced->total_mass;
  return gravity * mass;
}

// Lateral reactions (string-frame z, toward the high side) of the case's supports.
std::vector<double> SupportHighSideReactions(const StaticString& s) {
  const auto poses = s.m.system->Poses(s.q);
  const VecX rest = VecX::Zero(s.m.system->num_velocities());
  std::vector<double> reactions;
  for (std::size_t i = 0; i < s.m.supports.size(); ++i) {
    const ForceElement& forwarded = *s.m.system->elements()[static_cast<std::size_t>(s.m.built->supports[i].index())];
    reactions.push_back(s.m.supports[i]->Reaction(StateOf(s.m, forwarded, poses, rest))[kZ]);
  }
  return reactions;
}

TEST(WallContactStaticTest, StringLiesOnTheLowSideOfAnInclinedHole) {
  const double inclination = 60.0 * kDegree;
  const StaticString s = SolveLyingString(60.0);
  const Vec3 high_side = well::HighSideFrame(well::TangentFromAngles(inclination, 30.0 * kDegree)).high_side;
  const auto poses = s.m.system->Poses(s.q);
  const VecX rest = VecX::Zero(s.m.system->num_velocities());
  double wall = 0.0;
  int active = 0;
  for (const WallContactElement* contact : s.m.contacts) {
    const WallContactResult r = contact->Result(StateOf(s.m, *contact, poses, rest));
    wall += r.force.dot(high_side);
    const Body& body = *contact->bodies()[0];
    const double at = body.s_start + body.reduced->node_positions[contact->node()].x();
    // Beam theory: the free spans from the supports are ~8 m long (tangency length, V4).
    if (at >= 10.0 && at <= 20.0) {
      EXPECT_TRUE(r.in_contact) << contact->Describe();
    }
    if (!r.in_contact) continue;
    ++active;
    EXPECT_NEAR(r.high_side_angle, kPi, 1.0 * kDegree) << contact->Describe();
  }
  const std::vector<double> reactions = SupportHighSideReactions(s);
  const double lateral_weight = StringWeight(*s.m.system, 9.81) * std::sin(inclination);
  const double error = (wall + reactions[0] + reactions[1]) / lateral_weight - 1.0;
  std::printf("[ measure  ] %d of %zu contacts active; wall %.2f N + supports %.2f, %.2f N vs w L sin I %.2f N: %.2e\n",
              active, s.m.contacts.size(), wall, reactions[0], reactions[1], lateral_weight, error);
  EXPECT_LT(std::abs(error), 5e-3);
}

// Horizontal hole (no axial load): a string pinned at the centre leaves the wall over the
// tangency length L_t = (24 EI r/q)^¼; the pin carries q L_t/2 and the string there tilts by
// q L_t³/(12 EI) (validation.md V4 closed form, r the radial clearance); where the string lies on
// the wall each node carries q ℓ. (The penalty spreads the concentrated force at the tangency
// point over ~(4 EI ℓ/k_n)^¼ ≈ 0.6 m, so the first node in contact is no sharp measure of L_t.)
TEST(WallContactStaticTest, PinnedStringInAHorizontalHoleMatchesBeamTheory) {
  const StaticString s = SolveLyingString(90.0);
  const SystemModel& model = *s.m.system;
  const double q = StringWeight(model, 9.81) / model.length();
  const Body& bit_body = model.bodies()[0];
  const double bending = bit_body.bending_rigidity;
  const double clearance = 0.1 - 0.0635;
  const double tangency = std::pow(24.0 * bending * clearance / q, 0.25);
  const std::vector<double> reactions = SupportHighSideReactions(s);
  const auto poses = model.Poses(s.q);
  // Tilt of the bit node in the string frame: the body's rotation plus the node's elastic one.
  const Mat3 reference = bit_body.reference_orientation.toRotationMatrix();
  const Vec3 tilt = so3::LogMap(reference.transpose() * poses[0].A) + poses[0].NodeRotation(bit_body, 0);
  const VecX rest = VecX::Zero(model.num_velocities());
  double middle_force = 0.0;
  for (const WallContactElement* contact : s.m.contacts) {
    const Body& body = *contact->bodies()[0];
    const double at = body.s_start + body.reduced->node_positions[contact->node()].x();
    if (std::abs(at - 15.0) < 1e-9) middle_force = contact->Result(StateOf(s.m, *contact, poses, rest)).normal_force;
  }
  const double element = bit_body.element_length;
  const double expected_tilt = q * std::pow(tangency, 3) / (12.0 * bending);
  std::printf("[ measure  ] horizontal: reactions %.3f, %.3f N vs q L_t/2 = %.3f N; bit tilt %.6f rad vs %.6f rad; "
              "mid-span node %.3f N vs q l = %.3f N\n",
              reactions[0], reactions[1], 0.5 * q * tangency, tilt.y(), expected_tilt, middle_force, q * element);
  for (const double reaction : reactions) EXPECT_NEAR(reaction / (0.5 * q * tangency), 1.0, 0.02);
  EXPECT_NEAR(std::abs(tilt.y()) / expected_tilt, 1.0, 0.02);
  EXPECT_NEAR(tilt.z() / expected_tilt, 0.0, 1e-3);  // in the vertical plane
  EXPECT_NEAR(middle_force / (q * element), 1.0, 1e-3);
}

}  // namespace wall_contact_test
}  // namespace drillflex::model

namespace drillflex::model {
namespace wall_contact_test {

// The wall contacts' friction regularization velocity (builder.hpp kFrictionRegularizationSpin): by
// default Ω_ε R_c for each contact circle, its own radius; the case's friction_velocity replaces it.
TEST(WallContactBuilder, FrictionVelocityIsTheSpinTimesTheContactRadiusUnlessGiven) {
  ModelInput input = testing::RodInput(3, 5, 4);
  input.well =
      model::MakeWellbore(well::Trajectory(std::vector<well::SurveyStation>{{0.0, 0.5, 0.0}, {100.0, 0.5, 0.0}}),
                          std::vector<well::HoleSection>{well::HoleSection{std::nullopt, 0.1524, std::nullopt}});
  input.bit_md = 50.0;
  input.gravity = 9.81;
  input.settings.contact.friction = 0.25;
  cms::ReductionCache cache;
  auto velocities = [&](const ModelInput& in) {
    const BuiltModel built = BuildSystemModel(in, cache);
    std::vector<std::pair<double, double>> pairs;  // (R_c, v_ε)
    for (const auto handle : built.contacts) {
      const auto& contact = built.system.Get(handle);
      pairs.emplace_back(contact.parameters().contact_radius, contact.parameters().regularization_velocity);
    }
    return pairs;
  };
  const auto defaults = velocities(input);
  ASSERT_FALSE(defaults.empty());
  for (const auto& [radius, velocity] : defaults) {
    EXPECT_GT(radius, 0.0);
    EXPECT_DOUBLE_EQ(velocity, 0.01 * radius);  // Ω_ε = 0.01 rad/s (0.1 rpm)
  }
  input.settings.contact.friction_velocity = 2.5e-3;
  for (const auto& [radius, velocity] : velocities(input)) EXPECT_DOUBLE_EQ(velocity, 2.5e-3);
}

}  // namespace wall_contact_test
}  // namespace drillflex::model
