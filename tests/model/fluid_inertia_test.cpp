// The drilling fluid in the time domain (model/fluid_inertia.hpp): its Jacobians against central
// differences of the model's residual at random moving states; its power balance vᵀR_f = dT_f/dt +
// Σ c|Πt|² (the Lagrangian terms conserve the fluid's kinetic energy, the dashpots only dissipate);
// a pure spin of a straight string moves no fluid (no rotary inertia, no centrifugal or gyroscopic
// term of the pipe's spin); and the mass at rest is the linear analyses' (model/lateral_fluid.hpp).
#include "model/fluid_inertia.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <random>

#include "core/error.hpp"
#include "core/so3.hpp"
#include "fe/annulus_fluid.hpp"
#include "model/lateral_fluid.hpp"
#include "model_test_support.hpp"
#include "solvers/problem.hpp"

namespace drillflex::model {
namespace fluid_inertia_test {

// A hollow rod (OD 3 in, ID 1 in) of 3 bodies in a straight vertical 6 in hole, a viscous fluid of
// 1200 kg/m³ inside and out, no gravity; its transient model's fluid lumps taken at 10 rad/s.
ModelInput HollowRodInHole() {
  ModelInput input = testing::RodInput(3, 5, 4);
  input.string.components[0].inner_diameter = 0.0254;
  input.well =
      model::MakeWellbore(well::Trajectory(std::vector<well::SurveyStation>{{0.0, 0.0, 0.0}, {100.0, 0.0, 0.0}}),
                          std::vector<well::HoleSection>{well::HoleSection{std::nullopt, 0.1524, std::nullopt}});
  input.bit_md = 50.0;
  input.fluid = FluidConfig{1200.0, 0.02, std::nullopt, -1.0};
  return input;
}

// The bodies of a built model alone (no force elements: only their inertia, elasticity and fluid).
SystemModel BodiesOnly(const SystemModel& model) {
  return SystemModel(std::vector<Body>(model.bodies()), {}, model.length());
}

struct RandomState {
  VecX q, v, a;
};

// Arbitrary body rotations, modal coordinates of 0.05, velocities of ~1 m/s and 8 rad/s.
RandomState MakeRandomState(const SystemModel& model, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  RandomState s{model.ReferencePositions(), VecX::Zero(model.num_velocities()), VecX::Zero(model.num_velocities())};
  for (const Body& body : model.bodies()) {
    const int qo = body.q_offset, vo = body.v_offset;
    const Quat rotation = so3::QuatFromRotationVector(3.0 * Vec3(u(rng), u(rng), u(rng)));
    s.q.segment<4>(qo + 3) << rotation.w(), rotation.x(), rotation.y(), rotation.z();
    for (int j = 0; j < body.flexible_count; ++j) s.q[qo + 7 + j] = 0.05 * u(rng);
    for (int j = 0; j < body.velocity_count(); ++j) {
      s.v[vo + j] = (j >= 3 && j < 6 ? 8.0 : 1.0) * u(rng);
      s.a[vo + j] = 20.0 * u(rng);
    }
  }
  return s;
}

// The motion's part of the model's residual (R(q, v, a) − R(q, 0, 0)) and its matrices.
class MotionPartProblem : public solvers::Problem {
 public:
  explicit MotionPartProblem(const SystemModel& model) : model_(model) {}
  Index num_positions() const override { return model_.num_positions(); }
  Index num_velocities() const override { return model_.num_velocities(); }
  VecX Increment(const VecX& q, const VecX& dv) const override { return model_.Increment(q, dv); }
  VecX Residual(double t, const VecX& q, const VecX& v, const VecX& a) const override {
    return model_.Residual(t, q, v, a, 1.0) - model_.Residual(t, q, Zero(), Zero(), 1.0);
  }
  SparseMat IterationMatrix(double t, const VecX& q, const VecX& v, const VecX& a, double cK, double cD,
                            double cM) const override {
    return model_.IterationMatrix(t, q, v, a, 1.0, cK, cD, cM) -
           model_.IterationMatrix(t, q, Zero(), Zero(), 1.0, cK, 0.0, 0.0);
  }

 private:
  VecX Zero() const { return VecX::Zero(num_velocities()); }
  const SystemModel& model_;
};

// The fluid's residual Σ_b R_f alone, with its analytic matrices (the elastic forces of the whole
// residual would bury R_f's differences in their round-off).
class FluidProblem : public solvers::Problem {
 public:
  explicit FluidProblem(const SystemModel& model) : model_(model) {}
  Index num_positions() const override { return model_.num_positions(); }
  Index num_velocities() const override { return model_.num_velocities(); }
  VecX Increment(const VecX& q, const VecX& dv) const override { return model_.Increment(q, dv); }
  VecX Residual(double, const VecX& q, const VecX& v, const VecX& a) const override {
    VecX residual = VecX::Zero(num_velocities());
    for (const Body& body : model_.bodies()) {
      const int n = body.velocity_count();
      residual.segment(body.v_offset, n) =
          BodyFluidForces(body, PoseOf(body, q), v.segment(body.v_offset, n), a.segment(body.v_offset, n));
    }
    return residual;
  }
  SparseMat IterationMatrix(double, const VecX& q, const VecX& v, const VecX& a, double cK, double cD,
                            double cM) const override {
    MatX matrix = MatX::Zero(num_velocities(), num_velocities());
    for (const Body& body : model_.bodies()) {
      const int n = body.velocity_count();
      MatX local = MatX::Zero(n, n);
      AddFluidMatrices(body, PoseOf(body, q), v.segment(body.v_offset, n), a.segment(body.v_offset, n), cK, cD, cM,
                       local);
      matrix.block(body.v_offset, body.v_offset, n, n) = local;
    }
    return matrix.sparseView();
  }

 private:
  const SystemModel& model_;
};

BuiltModel BuildWithFluid(cms::ReductionCache& cache, double frequency) {
  ModelInput input = HollowRodInHole();
  input.transient_fluid_frequency = frequency;
  return BuildSystemModel(input, cache);
}

TEST(FluidInertia, TheBuilderGivesEveryNodeItsLumpsAtTheFrequency) {
  cms::ReductionCache cache;
  const BuiltModel built = BuildWithFluid(cache, 10.0);
  const ModelInput input = HollowRodInHole();
  const LateralFluid fluid = MakeLateralFluid(input, built.system);
  for (std::size_t i = 0; i < fluid.nodes.size(); ++i) {
    const NodeFluidTerms terms = ComputeNodeFluidTerms(fluid, i, 10.0);
    const Body& body = built.system.bodies()[fluid.nodes[i].body];
    EXPECT_DOUBLE_EQ(body.fluid_lateral_mass[fluid.nodes[i].node], terms.mass);
    EXPECT_DOUBLE_EQ(body.fluid_lateral_damping[fluid.nodes[i].node], terms.damping);
    EXPECT_GT(terms.damping, 0.0);
  }
  // Without the frequency no body carries fluid; a viscous fluid needs one.
  const BuiltModel steel = BuildSystemModel(input, cache);
  for (const Body& body : steel.system.bodies()) EXPECT_FALSE(HasLateralFluid(body));
  EXPECT_THROW(BuildWithFluid(cache, 0.0), LogicError);
}

TEST(FluidInertia, JacobiansMatchCentralDifferences) {
  cms::ReductionCache cache;
  const SystemModel model = BodiesOnly(BuildWithFluid(cache, 10.0).system);
  const FluidProblem fluid(model);
  const MotionPartProblem whole(model);
  std::mt19937 rng(3);
  for (int trial = 0; trial < 3; ++trial) {
    RandomState s = MakeRandomState(model, rng);
    // All three parts together, then a state with velocity only and one with acceleration only.
    for (int variant = 0; variant < 3; ++variant) {
      if (variant == 1) s.a.setZero();
      if (variant == 2) s = RandomState{s.q, VecX::Zero(s.v.size()), MakeRandomState(model, rng).a};
      for (int part = 0; part < 3; ++part) {
        const double cK = part == 0, cD = part == 1, cM = part == 2;
        double errors[2];
        const solvers::Problem* problems[2] = {&fluid, &whole};
        for (int p = 0; p < 2; ++p) {
          const MatX analytic(problems[p]->IterationMatrix(0.0, s.q, s.v, s.a, cK, cD, cM));
          const MatX numeric(
              solvers::FiniteDifferenceIterationMatrix(*problems[p], 0.0, s.q, s.v, s.a, cK, cD, cM, 1e-6));
          errors[p] = solvers::RelativeMatrixError(analytic, numeric);
        }
        std::printf("trial %d variant %d part %d: relative error, fluid alone %.2e, the model's motion part %.2e\n",
                    trial, variant, part, errors[0], errors[1]);
        EXPECT_LT(errors[0], 1e-7) << "trial " << trial << " variant " << variant << " part " << part;
        // Through SystemModel (the elastic forces' round-off in the differences: ~1e-6).
        EXPECT_LT(errors[1], 2e-5) << "trial " << trial << " variant " << variant << " part " << part;
      }
    }
  }
}

// vᵀ R_f = dT_f/dt + Σ c |Π t|², dT_f/dt by central differences along (q ⊕ ±h v, v ± h a).
TEST(FluidInertia, PowerIsTheRateOfKineticEnergyPlusTheDampersDissipation) {
  cms::ReductionCache cache;
  const SystemModel model = BodiesOnly(BuildWithFluid(cache, 10.0).system);
  std::mt19937 rng(7);
  for (int trial = 0; trial < 4; ++trial) {
    const RandomState s = MakeRandomState(model, rng);
    double power = 0.0, rate = 0.0, dissipation = 0.0, scale = 0.0;
    const double h = 1e-6;
    const auto ahead = model.Poses(model.Increment(s.q, h * s.v));
    const auto behind = model.Poses(model.Increment(s.q, -h * s.v));
    const auto poses = model.Poses(s.q);
    for (std::size_t b = 0; b < model.bodies().size(); ++b) {
      const Body& body = model.bodies()[b];
      const int n = body.velocity_count();
      const VecX v = s.v.segment(body.v_offset, n), a = s.a.segment(body.v_offset, n);
      const VecX forces = BodyFluidForces(body, poses[b], v, a);
      power += v.dot(forces);
      scale += v.cwiseAbs().dot(forces.cwiseAbs());
      rate += (BodyFluidKineticEnergy(body, ahead[b], v + h * a) - BodyFluidKineticEnergy(body, behind[b], v - h * a)) /
              (2.0 * h);
      dissipation += BodyFluidDampingPower(body, poses[b], v);
    }
    std::printf("trial %d: power %.6e W, dT/dt %.6e W, dissipation %.6e W\n", trial, power, rate, dissipation);
    EXPECT_GT(dissipation, 0.0);
    EXPECT_NEAR(power, rate + dissipation, 1e-7 * scale);
  }
}

// A straight string spinning about its axis (and sliding along it) moves no fluid: no force, no
// kinetic energy. A rigid lateral translation carries the whole lateral mass.
TEST(FluidInertia, SpinMovesNoFluidAndLateralTranslationCarriesItAll) {
  cms::ReductionCache cache;
  const SystemModel model = BodiesOnly(BuildWithFluid(cache, 10.0).system);
  const VecX q = model.ReferencePositions();
  const auto poses = model.Poses(q);
  double lateral_mass = 0.0;
  for (std::size_t b = 0; b < model.bodies().size(); ++b) {
    const Body& body = model.bodies()[b];
    const int n = body.velocity_count();
    VecX v = VecX::Zero(n), a = VecX::Zero(n);
    v.head<3>() = 0.3 * poses[b].A.col(0);  // sliding along the axis (global ṙ), m/s
    v[3] = 12.0;   // spin, rad/s
    a[3] = 40.0;   // spin-up, rad/s²
    EXPECT_EQ(BodyFluidForces(body, poses[b], v, a).norm(), 0.0);
    EXPECT_EQ(BodyFluidKineticEnergy(body, poses[b], v), 0.0);
    VecX sideways = VecX::Zero(n);
    sideways[1] = 1.0;
    lateral_mass += 2.0 * BodyFluidKineticEnergy(body, poses[b], sideways);
  }
  // Hand sum over the 5.08 m rod: (ρ A_i + C_m(ω) ρ π a²) L, C_m of the viscous annulus at 10 rad/s
  // (Chen et al. 1976, fe/annulus_fluid.hpp).
  const double a = 0.0381, b = 0.0762, rho = 1200.0, length = 5.08;
  const fe::AnnulusFluidCoefficients c = fe::ComputeAnnulusFluidCoefficients(a, b, 10.0, 0.02 / rho);
  const double expected = (rho * kPi * 0.0127 * 0.0127 + c.added_mass * rho * kPi * a * a) * length;
  EXPECT_NEAR(lateral_mass, expected, 1e-12 * expected);
}

// At rest the fluid's mass is the linear analyses' Σ m_k J_latᵀ J_lat at the same frequency.
TEST(FluidInertia, MassAtRestIsTheLinearAnalysesMass) {
  cms::ReductionCache cache;
  const BuiltModel built = BuildWithFluid(cache, 10.0);
  const SystemModel model = BodiesOnly(built.system);
  const ModelInput input = HollowRodInHole();
  std::mt19937 rng(5);
  const VecX q = MakeRandomState(model, rng).q;
  const SystemModel steel = BodiesOnly(BuildSystemModel(input, cache).system);
  const MatX transient(model.MassMatrix(q));
  const MatX linear = MatX(steel.MassMatrix(q)) +
                      MatX(ComputeLateralFluidMatrices(steel, MakeLateralFluid(input, steel), q, 10.0).mass);
  EXPECT_LT(solvers::RelativeMatrixError(transient, linear), 1e-13);
}

}  // namespace fluid_inertia_test
}  // namespace drillflex::model
