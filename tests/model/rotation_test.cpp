// Rotations: unbounded spin through the quaternion increment, and the invariance of the model under a
// rigid rotation of the whole string (the builder lays strings along +x only; here the same string is
// turned to lie along z, at 37° and along an arbitrary direction by rotating its reference state,
// supports and loads, and nothing of K, M or the static deflection in its own frame may change).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "core/error.hpp"
#include "core/so3.hpp"
#include "model/nodal_loads.hpp"
#include "model/spring_elements.hpp"
#include "model/static_problem.hpp"
#include "model_test_support.hpp"
#include "rigid_rotation.hpp"
#include "solvers/eigen.hpp"
#include "solvers/newton.hpp"
#include "core/dense_eigen.hpp"

namespace drillflex::model {
namespace rotation_test {

using testing::RotateRigidly;
using testing::RotateVelocities;

// A body turned through 1000 revolutions about its own axis in steps of 2π/100, then back, returns
// to its start: the quaternion increment q ⊕ Δθ = q·exp(Δθ/2) keeps unbounded spin exact.
TEST(Rotation, ThousandRevolutionsAndBack) {
  cms::ReductionCache cache;
  const BuiltModel built = BuildSystemModel(testing::RodInput(3, 4, 5), cache);
  const SystemModel& model = built.system;
  std::mt19937 rng(31);
  const VecX start =
      RotateRigidly(model, testing::PerturbedPositions(model, rng, 0.1), so3::ExpMap(Vec3(0.4, 1.3, -0.8)));
  const Body& spun = model.bodies()[1];
  const int steps_per_revolution = 100, revolutions = 1000;
  VecX step = VecX::Zero(model.num_velocities());
  step[spun.v_offset + 3] = 2.0 * kPi / steps_per_revolution;  // about the body's x axis
  VecX q = start;
  double largest_excursion = 0.0;
  for (int i = 0; i < steps_per_revolution * revolutions; ++i) {
    q = model.Increment(q, step);
    if (i == steps_per_revolution * revolutions / 2 + steps_per_revolution / 4 - 1) {
      largest_excursion = (q - start).cwiseAbs().maxCoeff();  // a quarter turn away: the test can fail
    }
  }
  const double after_forward = (q - start).cwiseAbs().maxCoeff();
  for (int i = 0; i < steps_per_revolution * revolutions; ++i) q = model.Increment(q, -step);
  const double after_back = (q - start).cwiseAbs().maxCoeff();
  std::printf("1000 revolutions: |q − q0|∞ = %.2e after the forward spin, %.2e after spinning back "
              "(%.2f a quarter of a turn away)\n", after_forward, after_back, largest_excursion);
  EXPECT_GT(largest_excursion, 0.3);
  EXPECT_LT(after_forward, 1e-10);
  EXPECT_LT(after_back, 1e-10);
  // The axis and the frame origin of the spun body never moved: its node 0 and axis direction.
  const BodyPose pose = PoseOf(spun, q), pose0 = PoseOf(spun, start);
  EXPECT_LT((pose.A.col(0) - pose0.A.col(0)).norm(), 1e-10);
  EXPECT_EQ((pose.r - pose0.r).norm(), 0.0);
}

Mat3 RotationAboutY(double angle) { return so3::ExpMap(Vec3(0.0, angle, 0.0)); }

// The lowest `count` eigenvalues ω² of K x = ω² M x at q (K at rest, without applied loads).
VecX ModalEigenvalues(const SystemModel& model, const VecX& q, int count) {
  const VecX zero = VecX::Zero(model.num_velocities());
  const SparseMat stiffness = model.IterationMatrix(0.0, q, zero, zero, 0.0, 1.0, 0.0, 0.0);
  return solvers::SolveModes(stiffness, model.MassMatrix(q), count).eigenvalues;
}

// A free string's free-free frequencies at its reference and after a large arbitrary rigid rotation.
TEST(Rotation, FreeStringFrequenciesInvariantUnderRigidRotation) {
  cms::ReductionCache cache;
  const BuiltModel built = BuildSystemModel(testing::RodInput(3, 4, 5), cache);
  const SystemModel& model = built.system;
  const VecX q = model.ReferencePositions();
  const VecX before = ModalEigenvalues(model, q, 20);
  for (const Vec3& turn : {Vec3(0.3, -2.9, 1.7), Vec3(0.0, -kPi / 2, 0.0), Vec3(1000.5 * kPi, 0.0, 0.0)}) {
    const VecX after = ModalEigenvalues(model, RotateRigidly(model, q, so3::ExpMap(turn)), 20);
    // Six rigid-body modes at ω² ≈ 0, then the elastic ones.
    EXPECT_LT(before.head<6>().cwiseAbs().maxCoeff(), 1e-6 * before[6]);
    EXPECT_LT(after.head<6>().cwiseAbs().maxCoeff(), 1e-6 * before[6]);
    const double error = ((after.tail(14) - before.tail(14)).array() / before.tail(14).array()).abs().maxCoeff();
    std::printf("free string turned by |θ| = %.3f rad: lowest elastic %.4f Hz, max relative change of ω² %.2e\n",
                turn.norm(), std::sqrt(before[6]) / (2 * kPi), error);
    EXPECT_LT(error, 1e-9);
  }
}

// The model of `input` laid along R x instead of x: built by the builder, then every body's reference
// placement, every support frame and every point load turned by R about the origin; the couplings
// keep the builder's stiffness. Damping is left out (zero): these tests use K, M and statics only.
// Only couplings, supports and point loads are rebuilt (no gravity, no distributed loads).
SystemModel BuildTurnedModel(const ModelInput& input, const Mat3& R, cms::ReductionCache& cache) {
  if (input.gravity != 0.0) throw LogicError("BuildTurnedModel: gravity is not turned");
  const BuiltModel built = BuildSystemModel(input, cache);
  std::vector<Body> bodies = built.system.bodies();
  for (Body& body : bodies) {
    body.reference_position = R * body.reference_position;
    body.reference_orientation = (Quat(R) * body.reference_orientation).normalized();
  }
  std::vector<std::unique_ptr<ForceElement>> elements;
  for (const auto& element : built.system.elements()) {
    if (const auto* coupling = dynamic_cast<const CouplingElement*>(element.get())) {
      const int lower = built.system.IndexOf(coupling->bodies()[0]);
      const int upper = built.system.IndexOf(coupling->bodies()[1]);
      elements.push_back(std::make_unique<CouplingElement>(&bodies[lower], bodies[lower].node_count() - 1,
                                                           &bodies[upper], 0, coupling->stiffness(), Vec6::Zero()));
    }
  }
  for (const Support& support : input.supports) {
    const auto [b, node] = FindNodeAt(bodies, support.at);
    const Body& body = bodies[b];
    const Mat3 frame = body.reference_orientation.toRotationMatrix();
    const Vec3 position = body.reference_position + frame * body.reduced->node_positions[node];
    Vec6 stiffness = kSupportStiffnessFactor * SectionCouplingStiffness(body, input.settings.coupling_factor);
    for (int d = 0; d < 6; ++d) if (!support.fixed[d]) stiffness[d] = 0.0;
    elements.push_back(std::make_unique<SupportElement>(&body, node, position, frame, stiffness, Vec6::Zero()));
  }
  for (const Load& load : input.loads) {
    if (load.distributed) throw LogicError("BuildTurnedModel: distributed loads are not turned");
    const auto [b, node] = FindNodeAt(bodies, load.at);
    std::vector<Vec3> forces(bodies[b].node_count(), Vec3::Zero()), moments(forces);
    forces[node] = R * load.force;
    moments[node] = R * load.moment;
    elements.push_back(std::make_unique<NodalLoadElement>(&bodies[b], std::move(forces), std::move(moments)));
  }
  SystemModel model(std::move(bodies), std::move(elements), built.system.length());
  model.set_force_scale(built.force_scale);
  return model;
}

// The V1 cantilever (4 bodies × 10 elements, 6 modes a body), clamped at s = 0, with a tip load
// that bends, stretches and twists it (moderately nonlinear: tip rotation ~0.1 rad).
ModelInput LoadedCantilever() {
  ModelInput input = testing::RodInput(4, 10, 6, 1000.0);
  Support root;
  root.at = 0.0;
  root.fixed.fill(true);
  input.supports = {root};
  Load tip;
  tip.at = 5.08;
  tip.force = Vec3(-5000.0, 1500.0, -800.0);
  tip.moment = Vec3(300.0, 100.0, -200.0);
  input.loads = {tip};
  return input;
}

struct Placement {
  const char* name;
  Mat3 rotation;
};

std::vector<Placement> Placements() {
  return {{"along x", Mat3::Identity()},
          {"along z", RotationAboutY(-kPi / 2)},  // x → z (down)
          {"at 37 degrees", RotationAboutY(-37.0 * kDegree)},
          {"arbitrary", so3::ExpMap(Vec3(1.1, -0.7, 2.3))}};
}

double MaxRelativeDifference(const VecX& a, const VecX& b, double scale) {
  return (a - b).cwiseAbs().maxCoeff() / scale;
}

// The sorted eigenvalues of a symmetric matrix.
VecX SymmetricEigenvalues(const SparseMat& matrix) {
  return SymmetricEigen(MatX(matrix), false).values;
}

TEST(Rotation, CantileverStiffnessAndMassInvariantUnderPlacement) {
  const ModelInput input = LoadedCantilever();
  cms::ReductionCache cache;
  const BuiltModel reference = BuildSystemModel(input, cache);
  const VecX q0 = reference.system.ReferencePositions();
  const VecX zero = VecX::Zero(reference.system.num_velocities());
  const SparseMat k0 = reference.system.IterationMatrix(0.0, q0, zero, zero, 0.0, 1.0, 0.0, 0.0);
  const SparseMat m0 = reference.system.MassMatrix(q0);
  const VecX k_eigen0 = SymmetricEigenvalues(k0), m_eigen0 = SymmetricEigenvalues(m0);
  const VecX modes0 = solvers::SolveModes(k0, m0, 10).eigenvalues;
  for (const Placement& placement : Placements()) {
    const SystemModel turned = BuildTurnedModel(input, placement.rotation, cache);
    const VecX q = turned.ReferencePositions();
    EXPECT_LT((q - RotateRigidly(reference.system, q0, placement.rotation, &turned)).norm(), 1e-13 * q.norm());
    const SparseMat k = turned.IterationMatrix(0.0, q, zero, zero, 0.0, 1.0, 0.0, 0.0);
    const SparseMat m = turned.MassMatrix(q);
    const double k_error = MaxRelativeDifference(SymmetricEigenvalues(k), k_eigen0, k_eigen0.cwiseAbs().maxCoeff());
    const double m_error = MaxRelativeDifference(SymmetricEigenvalues(m), m_eigen0, m_eigen0.cwiseAbs().maxCoeff());
    const VecX k_eigen = SymmetricEigenvalues(k);
    const double k_each = ((k_eigen - k_eigen0).array() / k_eigen0.array().abs()).abs().maxCoeff();
    std::printf("  K eigenvalues %.3e..%.3e, largest change relative to each eigenvalue %.2e\n", k_eigen0.minCoeff(),
                k_eigen0.maxCoeff(), k_each);
    const VecX modes = solvers::SolveModes(k, m, 10).eigenvalues;
    const double mode_error = ((modes - modes0).array() / modes0.array()).abs().maxCoeff();
    std::printf("cantilever %s: eigenvalues of K %.2e, of M %.2e (of the largest), 10 lowest ω² %.2e (each)\n",
                placement.name, k_error, m_error, mode_error);
    EXPECT_LT(k_error, 1e-9);
    EXPECT_LT(m_error, 1e-9);
    // The generalized problem spans ω² from ~2e2 to ~1e13 (stiff couplings): the dense solver's
    // round-off on the lowest ones is ~ε·κ, measured 2.6e-7 (0 for the unturned copy).
    EXPECT_LT(mode_error, 2e-6);
  }
}

// At a deflected, moving state the residual and the matrices transform with the placement:
// R' = T R and X' = T X Tᵀ (X = K, D, M), T = diag(R, I, I) per body: the global translational rows
// turn, the body-frame rows do not. This covers the springs, the loads and the inertia terms at a
// moving state (K_in, D_in of model/body_inertia_jacobian.hpp). Both models come from
// BuildTurnedModel, so both have undamped springs.
TEST(Rotation, MatricesAtDeflectedMovingStateTransformWithThePlacement) {
  const ModelInput input = LoadedCantilever();
  cms::ReductionCache cache;
  const SystemModel model0 = BuildTurnedModel(input, Mat3::Identity(), cache);
  std::mt19937 rng(41);
  const VecX q0 = testing::PerturbedPositions(model0, rng, 1e-4);
  const int n = model0.num_velocities();
  const VecX v0 = 5.0 * VecX::Random(n), a0 = 50.0 * VecX::Random(n);
  for (const Placement& placement : Placements()) {
    const Mat3& R = placement.rotation;
    const SystemModel turned = BuildTurnedModel(input, R, cache);
    MatX transform = MatX::Identity(n, n);
    for (const Body& body : model0.bodies()) transform.block<3, 3>(body.v_offset, body.v_offset) = R;
    const VecX q = RotateRigidly(model0, q0, R, &turned);
    const VecX v = RotateVelocities(model0, v0, R), a = RotateVelocities(model0, a0, R);
    const VecX r0 = model0.Residual(0.0, q0, v0, a0, 0.8), r = turned.Residual(0.0, q, v, a, 0.8);
    double worst = (r - transform * r0).norm() / r0.norm();
    for (int part = 0; part < 3; ++part) {
      const double cK = part == 0, cD = part == 1, cM = part == 2;
      const MatX x0(model0.IterationMatrix(0.0, q0, v0, a0, 0.8, cK, cD, cM));
      const MatX x(turned.IterationMatrix(0.0, q, v, a, 0.8, cK, cD, cM));
      worst = std::max(worst, (x - transform * x0 * transform.transpose()).norm() / x0.norm());
    }
    std::printf("deflected moving cantilever %s: residual and K, D, M transform to %.2e\n", placement.name, worst);
    EXPECT_LT(worst, 1e-10) << placement.name;
  }
}

// The static deflection under a load turned with the string is the same in the string's own frame.
TEST(Rotation, CantileverStaticDeflectionInvariantUnderPlacement) {
  const ModelInput input = LoadedCantilever();
  cms::ReductionCache cache;
  solvers::NewtonOptions options;
  options.increment_tolerance = 1e-12;
  options.line_search.enabled = false;
  const SystemModel model0 = BuildTurnedModel(input, Mat3::Identity(), cache);
  StaticModelProblem problem0(model0);
  const VecX q0 = solvers::SolveStatic(problem0, model0.ReferencePositions(), options).q;
  const Body& tip_body = model0.bodies().back();
  const int tip = tip_body.node_count() - 1;
  const auto tip_pose0 = model0.Poses(q0).back();
  const Vec3 tip_deflection0 = tip_pose0.NodePosition(tip_body, tip) - Vec3(5.08, 0.0, 0.0);
  const double tip_rotation0 = so3::LogMap(tip_pose0.A).norm();
  for (const Placement& placement : Placements()) {
    const Mat3& R = placement.rotation;
    const SystemModel turned = BuildTurnedModel(input, R, cache);
    StaticModelProblem problem(turned);
    const VecX q = solvers::SolveStatic(problem, turned.ReferencePositions(), options).q;
    const auto tip_pose = turned.Poses(q).back();
    // In the string's own frame: R^T (r_tip − R r_tip,ref).
    const Vec3 tip_deflection = R.transpose() * tip_pose.NodePosition(tip_body, tip) - Vec3(5.08, 0.0, 0.0);
    const double deflection_error = (tip_deflection - tip_deflection0).norm() / tip_deflection0.norm();
    const double state_error = (q - RotateRigidly(model0, q0, R, &turned)).cwiseAbs().maxCoeff();
    std::printf("cantilever %s: tip deflection (%.6f, %.6f, %.6f) m (tip rotation %.3f rad), relative "
                "difference %.2e, |q − R q0|∞ %.2e\n", placement.name, tip_deflection.x(), tip_deflection.y(),
                tip_deflection.z(), tip_rotation0, deflection_error, state_error);
    EXPECT_LT(deflection_error, 1e-9);
    EXPECT_LT(state_error, 1e-9);
  }
}

}  // namespace rotation_test
}  // namespace drillflex::model
