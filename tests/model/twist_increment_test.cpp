// The static solver's increment (SystemModel::IncrementKeepingShape): a body's turn about its own
// axis keeps its deformed shape in space at any angle, and the increment agrees with the plain
// one to first order (so the tangent matrices of the plain one stay exact for it).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "model/system_model.hpp"
#include "model_test_support.hpp"

namespace drillflex::model {
namespace twist_increment_test {

// The turn's generator J of a round rod's modes squares to −P_⊥ when the modes span a subspace
// closed under turns about x (both modes of each bending pair): then G(φ) is the exact turn.
TEST(TwistIncrement, GeneratorOfARoundRodIsAnExactTurn) {
  cms::ReductionCache cache;
  const BuiltModel built = BuildSystemModel(testing::RodInput(2, 8, 6), cache);
  const cms::ReducedBody& reduced = *built.system.bodies()[0].reduced;
  const MatX& j = reduced.twist_generator;
  const MatX& across = reduced.transverse_projection;
  const double error = (j * j + across).norm() / across.norm();
  std::printf("|J² + P_⊥| / |P_⊥| = %.2e, |J + Jᵀ| = %.2e\n", error, (j + j.transpose()).norm());
  EXPECT_LT(error, 1e-10);
  EXPECT_LT((j + j.transpose()).norm(), 1e-10 * j.norm());  // skew in the mass metric
  EXPECT_GT(j.norm(), 0.5);                                 // the bending modes turn into each other
}

// Three rod bodies at a random bent and twisted state.
class BentRod : public ::testing::Test {
 protected:
  cms::ReductionCache cache;
  const BuiltModel built = BuildSystemModel(testing::RodInput(3, 8, 6), cache);
  const SystemModel& model = built.system;
  std::mt19937 rng{5};
  const VecX q = testing::PerturbedPositions(model, rng, 0.2);
};

// A bent, twisted body turned by φ about its axis with the modes' first-order correction
// (δη = −φ J η, what Newton's linear step does for a turn that keeps the shape): with the plain
// increment its nodes move by ½φ²|J²η|, with IncrementKeepingShape not at all, at every φ.
TEST_F(BentRod, TurnKeepsTheShapeAtLargeAngles) {
  const Body& body = model.bodies()[1];
  const VecX eta = q.segment(body.q_offset + 7, body.flexible_count);
  for (const double angle : {0.1, 0.8, 3.0}) {
    VecX dv = VecX::Zero(model.num_velocities());
    dv[body.v_offset + 3] = angle;
    dv.segment(body.v_offset + 6, body.flexible_count) = -angle * (body.reduced->twist_generator * eta);
    const BodyPose before = PoseOf(body, q), plain = PoseOf(body, model.Increment(q, dv)),
                   kept = PoseOf(body, model.IncrementKeepingShape(q, dv));
    double moved_plain = 0.0, moved_kept = 0.0, bent = 0.0;
    for (int k = 0; k < body.node_count(); ++k) {
      moved_plain = std::max(moved_plain, (plain.NodePosition(body, k) - before.NodePosition(body, k)).norm());
      moved_kept = std::max(moved_kept, (kept.NodePosition(body, k) - before.NodePosition(body, k)).norm());
      bent = std::max(bent, (before.NodeOffset(body, k) - body.reduced->node_positions[k]).norm());
    }
    std::printf("turn %.1f rad: nodes moved %.2e m (plain increment), %.2e m (keeping the shape); deflection %.2e m\n",
                angle, moved_plain, moved_kept, bent);
    EXPECT_GT(moved_plain, 0.1 * angle * angle * bent);
    EXPECT_LT(moved_kept, 1e-12 * body.length());
  }
}

// A tilt and a turn together put every node where the tilt alone puts it: the frame is tilted
// first and then turned about its new axis. (Composed in one rotation exp(δθ), the tilt would act
// about an axis turned by about φ/2.)
TEST_F(BentRod, TurnWithATiltMovesNodesOnlyByTheTilt) {
  const Body& body = model.bodies()[1];
  const VecX eta = q.segment(body.q_offset + 7, body.flexible_count);
  VecX tilt = VecX::Zero(model.num_velocities());
  tilt[body.v_offset + 4] = 2e-3;
  tilt[body.v_offset + 5] = -1e-3;
  const BodyPose tilted = PoseOf(body, model.IncrementKeepingShape(q, tilt));
  for (const double angle : {0.3, 2.0}) {
    VecX dv = tilt;
    dv[body.v_offset + 3] = angle;
    dv.segment(body.v_offset + 6, body.flexible_count) = -angle * (body.reduced->twist_generator * eta);
    const BodyPose both = PoseOf(body, model.IncrementKeepingShape(q, dv));
    double miss = 0.0;
    for (int k = 0; k < body.node_count(); ++k) {
      miss = std::max(miss, (both.NodePosition(body, k) - tilted.NodePosition(body, k)).norm());
    }
    std::printf("turn %.1f rad with a tilt: nodes %.2e m from the tilt's\n", angle, miss);
    EXPECT_LT(miss, 1e-12 * body.length());
  }
}

// Both increments agree to first order: their difference shrinks as the step squared.
TEST_F(BentRod, IncrementAgreesWithThePlainOneToFirstOrder) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  VecX direction(model.num_velocities());
  for (int i = 0; i < direction.size(); ++i) direction[i] = u(rng);
  double previous = 0.0;
  for (const double h : {1e-2, 1e-3, 1e-4}) {
    const double difference = (model.IncrementKeepingShape(q, h * direction) - model.Increment(q, h * direction)).norm();
    std::printf("step %.0e: |difference| %.3e\n", h, difference);
    if (previous > 0.0) {
      EXPECT_NEAR(difference / previous, 0.01, 0.002);  // ∝ h²
    }
    previous = difference;
  }
  EXPECT_GT(previous, 0.0);
}

// The iteration matrix after every body has turned about its axis by the same angle, shapes kept (a
// string spinning as a whole), is Pᵀ S P of the one before, P = TurnCoordinates: what lets the time
// integrator reuse a factorization while a string spins. Without P it differs by a tenth.
TEST_F(BentRod, IterationMatrixAfterATurnIsTheTurnedOneBefore) {
  const int n = model.num_velocities();
  VecX dv = VecX::Zero(n);
  const double turns[3] = {0.4, 0.4, 0.4};
  for (std::size_t b = 0; b < model.bodies().size(); ++b) {
    const Body& body = model.bodies()[b];
    const VecX eta = q.segment(body.q_offset + 7, body.flexible_count);
    dv[body.v_offset + 3] = turns[b];
    dv.segment(body.v_offset + 6, body.flexible_count) = -turns[b] * (body.reduced->twist_generator * eta);
  }
  const VecX turned = model.IncrementKeepingShape(q, dv);
  const VecX zero = VecX::Zero(n);
  MatX p(n, n);
  for (int j = 0; j < n; ++j) {
    VecX column = VecX::Unit(n, j);
    model.TurnCoordinates(dv, column, false);
    p.col(j) = column;
  }
  EXPECT_LT((p.transpose() * p - MatX::Identity(n, n)).norm(), 1e-12);  // orthogonal
  VecX back = VecX::LinSpaced(n, -1.0, 1.0), there = back;
  model.TurnCoordinates(dv, there, false);
  model.TurnCoordinates(dv, there, true);
  EXPECT_LT((there - back).norm(), 1e-13 * back.norm());  // the inverse is the transpose
  for (const auto& [cK, cM] : {std::pair{1.0, 0.0}, std::pair{0.0, 1.0}}) {
    const MatX before(model.IterationMatrix(0.0, q, zero, zero, 1.0, cK, 0.0, cM));
    const MatX after(model.IterationMatrix(0.0, turned, zero, zero, 1.0, cK, 0.0, cM));
    const double transported = (after - p.transpose() * before * p).norm() / before.norm();
    const double plain = (after - before).norm() / before.norm();
    std::printf("%s after the turns: |S − Pᵀ S₀ P| / |S₀| = %.2e, |S − S₀| / |S₀| = %.2e\n", cK > 0.0 ? "K" : "M",
                transported, plain);
    EXPECT_LT(transported, 1e-9);
    EXPECT_GT(plain, 1e-3);
  }
}

}  // namespace twist_increment_test
}  // namespace drillflex::model
