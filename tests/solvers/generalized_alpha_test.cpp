// The generalized-α integrator (solvers/generalized_alpha.hpp) on toy problems: a 2-DOF linear
// oscillator (period error against the trapezoidal rule's exact phase error and its h² convergence,
// energy conservation at ρ∞ = 1, the dissipation of the scheme's amplification matrix at ρ∞ < 1), a
// torque-free symmetric top (the analytic precession of ω, energy and world angular momentum), a
// spinning heavy pendulum on a stiff spring, adaptive steps against a fine fixed-step reference, and
// failures that stop with a SolverError.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <cstdio>
#include <vector>

#include "core/error.hpp"
#include "dynamic_toy_problems.hpp"
#include "solvers/generalized_alpha.hpp"
#include "toy_problems.hpp"
#include "core/dense_eigen.hpp"

namespace drillflex::solvers {
namespace generalized_alpha_test {

using testing::DuffingOscillator;
using testing::LinearOscillator;

// The amplification matrix of one step on ẍ + ω² x = 0 for the state (x, v, a): the scheme's three
// relations (header of generalized_alpha.hpp) with v̇ = −ω² x, solved for the new state.
Eigen::Matrix3d AmplificationMatrix(const GeneralizedAlphaParameters& p, double omega, double h) {
  Eigen::Matrix3d lhs, rhs;
  const double w2 = omega * omega;
  lhs << 1.0, 0.0, -h * h * p.beta, 0.0, 1.0, -h * p.gamma, (1.0 - p.alpha_f) * w2, 0.0, 1.0 - p.alpha_m;
  rhs << 1.0, h, h * h * (0.5 - p.beta), 0.0, 1.0, h * (1.0 - p.gamma), -p.alpha_f * w2, 0.0, -p.alpha_m;
  return lhs.inverse() * rhs;
}

double SpectralRadius(const Eigen::Matrix3d& a) { return GeneralEigen(a, false).values.cwiseAbs().maxCoeff(); }

// The principal (complex) roots' phase per step, rad (the spurious root is real).
double PrincipalPhase(const Eigen::Matrix3d& a) {
  double phase = 0.0;
  for (const auto& lambda : GeneralEigen(a, false).values) {
    if (std::abs(lambda.imag()) > 1e-12) phase = std::abs(std::arg(lambda));
  }
  return phase;
}

// A 2-DOF chain: masses 2 and 1 kg, springs 400 N/m to the wall and 200 N/m between them.
LinearOscillator TwoMassChain() {
  MatX mass = MatX::Zero(2, 2), stiffness(2, 2);
  mass.diagonal() << 2.0, 1.0;
  stiffness << 600.0, -200.0, -200.0, 200.0;
  return LinearOscillator(mass, MatX::Zero(2, 2), stiffness);
}

struct Modes {
  VecX omega;  // rad/s
  MatX shapes; // mass-normalized columns
};

Modes ModesOf(const LinearOscillator& problem) {
  const DenseEigenpairs eigen = GeneralizedSymmetricEigen(problem.stiffness(), problem.mass());
  return {eigen.values.cwiseSqrt(), eigen.vectors};
}

// Mean period (s) of a modal coordinate y(t) over its upward zero crossings, each located by the
// cubic Hermite interpolant of (y, ẏ) over the step (error O(h⁴), below the scheme's O(h²)).
struct PeriodMeter {
  double previous_time = 0.0, previous_y = 0.0, previous_rate = 0.0;
  bool started = false;
  std::vector<double> crossings;

  void Add(double time, double y, double rate) {
    if (started && previous_y < 0.0 && y >= 0.0) {
      const double h = time - previous_time;
      double s = previous_y / (previous_y - y);  // Newton on the Hermite cubic from the linear guess
      for (int it = 0; it < 20; ++it) {
        const double h00 = 2 * s * s * s - 3 * s * s + 1, h10 = s * s * s - 2 * s * s + s;
        const double h01 = -2 * s * s * s + 3 * s * s, h11 = s * s * s - s * s;
        const double d00 = 6 * s * s - 6 * s, d10 = 3 * s * s - 4 * s + 1, d01 = -d00, d11 = 3 * s * s - 2 * s;
        const double value = h00 * previous_y + h10 * h * previous_rate + h01 * y + h11 * h * rate;
        const double slope = d00 * previous_y + d10 * h * previous_rate + d01 * y + d11 * h * rate;
        s -= value / slope;
      }
      crossings.push_back(previous_time + s * h);
    }
    previous_time = time;
    previous_y = y;
    previous_rate = rate;
    started = true;
  }
  double MeanPeriod() const {
    return (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
  }
};

// The measured period of mode `mode` of the chain started in that mode alone, at step h.
double MeasuredPeriod(double rho_infinity, int mode, double h, double periods) {
  const LinearOscillator problem = TwoMassChain();
  const Modes modes = ModesOf(problem);
  GeneralizedAlphaOptions options;
  options.rho_infinity = rho_infinity;
  options.adaptive = false;
  options.initial_step = h;
  GeneralizedAlphaIntegrator integrator(problem, options);
  const VecX shape = modes.shapes.col(mode);
  integrator.Initialize(0.0, -0.01 * shape, VecX::Zero(2));
  PeriodMeter meter;
  const VecX projector = problem.mass() * shape;
  integrator.on_step = [&](const GeneralizedAlphaState& s) { meter.Add(s.time, projector.dot(s.q), projector.dot(s.v)); };
  integrator.AdvanceTo(periods * 2.0 * kPi / modes.omega[mode]);
  return meter.MeanPeriod();
}

TEST(GeneralizedAlpha, ParametersGiveTheSpectralRadiusAtInfiniteFrequency) {
  for (const double rho : {0.0, 0.3, 0.6, 0.8, 1.0}) {
    const auto p = GeneralizedAlphaParameters::FromSpectralRadius(rho);
    // Second order (Chung & Hulbert eq. 17) and the spectral radius ρ∞ as ωh → ∞ (the principal
    // roots meet there as a double root, so they approach ρ∞ like (ωh)^(-1/2): 1e-4 at ωh = 1e6).
    EXPECT_NEAR(p.gamma, 0.5 - p.alpha_m + p.alpha_f, 1e-15);
    EXPECT_NEAR(SpectralRadius(AmplificationMatrix(p, 1e10, 1.0)), rho, 1e-5) << "rho " << rho;
    // Unconditional stability: no root outside the unit circle at any ωh.
    for (const double omega_h : {0.1, 1.0, 3.0, 10.0, 100.0}) {
      EXPECT_LE(SpectralRadius(AmplificationMatrix(p, omega_h, 1.0)), 1.0 + 1e-10) << rho << " " << omega_h;
    }
  }
  EXPECT_THROW(GeneralizedAlphaParameters::FromSpectralRadius(1.2), LogicError);
}

// ρ∞ = 1 is the trapezoidal rule: its phase per step is exactly 2 atan(ωh/2), so the period is
// lengthened by the factor ωh / (2 atan(ωh/2)) ≈ 1 + (ωh)²/12.
TEST(GeneralizedAlpha, PeriodErrorOfTheLinearOscillatorConvergesAsHSquared) {
  const Modes modes = ModesOf(TwoMassChain());
  for (const double rho : {1.0, 0.8}) {
    const auto p = GeneralizedAlphaParameters::FromSpectralRadius(rho);
    for (int mode = 0; mode < 2; ++mode) {
      const double period = 2.0 * kPi / modes.omega[mode];
      double previous_error = 0.0;
      for (const int steps_per_period : {20, 40, 80}) {
        const double h = period / steps_per_period;
        const double measured = MeasuredPeriod(rho, mode, h, 21.0);
        const double error = measured / period - 1.0;
        const double predicted = 2.0 * kPi * h / PrincipalPhase(AmplificationMatrix(p, modes.omega[mode], h)) / period - 1.0;
        std::printf("rho %.1f mode %d h = T/%d: period error %.4e (amplification matrix %.4e)\n", rho, mode + 1,
                    steps_per_period, error, predicted);
        EXPECT_NEAR(error, predicted, 2e-3 * std::abs(predicted));
        if (rho == 1.0) {
          const double omega_h = modes.omega[mode] * h;
          EXPECT_NEAR(error, omega_h / (2.0 * std::atan(0.5 * omega_h)) - 1.0, 2e-3 * error);
        }
        if (previous_error != 0.0) {
          EXPECT_NEAR(previous_error / error, 4.0, 0.1);  // h² convergence
        }
        previous_error = error;
      }
    }
  }
}

TEST(GeneralizedAlpha, EnergyOfTheLinearOscillatorIsConservedWithoutNumericalDamping) {
  const LinearOscillator problem = TwoMassChain();
  const Modes modes = ModesOf(problem);
  GeneralizedAlphaOptions options;
  options.rho_infinity = 1.0;
  options.adaptive = false;
  options.initial_step = 0.1 * 2.0 * kPi / modes.omega[1];  // ten steps per period of the fast mode
  GeneralizedAlphaIntegrator integrator(problem, options);
  const VecX q0 = 0.01 * modes.shapes.col(0) + 0.004 * modes.shapes.col(1);
  const VecX v0 = 0.05 * modes.shapes.col(1);
  integrator.Initialize(0.0, q0, v0);
  const double e0 = problem.Energy(q0, v0);
  double worst = 0.0;
  integrator.on_step = [&](const GeneralizedAlphaState& s) {
    worst = std::max(worst, std::abs(problem.Energy(s.q, s.v) / e0 - 1.0));
  };
  integrator.AdvanceTo(100.0 * 2.0 * kPi / modes.omega[0]);
  std::printf("100 periods, %ld steps, %ld factorizations, %ld Newton iterations: largest energy error %.3e\n",
              integrator.statistics().steps, integrator.statistics().factorizations,
              integrator.statistics().newton_iterations, worst);
  EXPECT_LT(worst, 1e-6);
  // A linear problem at a fixed step: one factorization kept for the whole run.
  EXPECT_EQ(integrator.statistics().factorizations, 1);
  EXPECT_LE(integrator.statistics().newton_iterations, 2 * integrator.statistics().steps);
}

// ρ∞ < 1: the state after n steps is A(ωh)ⁿ times the start (the integrator implements the scheme),
// and the energy decays at the rate of the principal roots, |λ|^(2n) (the numerical damping).
TEST(GeneralizedAlpha, NumericalDampingMatchesTheSpectralRadius) {
  for (const double omega_h : {0.5, 2.0, 20.0}) {
    const double rho = 0.6, h = 1e-3, omega = omega_h / h;
    const auto p = GeneralizedAlphaParameters::FromSpectralRadius(rho);
    const LinearOscillator problem(MatX::Identity(1, 1), MatX::Zero(1, 1), MatX::Constant(1, 1, omega * omega));
    GeneralizedAlphaOptions options;
    options.rho_infinity = rho;
    options.adaptive = false;
    options.initial_step = h;
    options.absolute_tolerance = 1e-14;
    options.relative_tolerance = 0.0;
    GeneralizedAlphaIntegrator integrator(problem, options);
    integrator.Initialize(0.0, VecX::Constant(1, 1.0), VecX::Zero(1));
    const Eigen::Matrix3d a = AmplificationMatrix(p, omega, h);
    Eigen::Vector3d expected(1.0, 0.0, -omega * omega);
    std::vector<double> log_energy;
    // Enough periods to average the energy's oscillation within one, before the amplitude decays
    // to the Newton tolerance.
    const int steps = omega_h < 1.0 ? 4000 : omega_h < 10.0 ? 400 : 30;
    for (int n = 1; n <= steps; ++n) {
      integrator.AdvanceTo(n * h);
      expected = a * expected;
      const auto& s = integrator.state();
      const Eigen::Vector3d got(s.q[0], s.v[0], s.pseudo_acceleration[0]);
      EXPECT_LT((got - expected).norm(), 1e-9 * expected.norm()) << "omega h " << omega_h << " step " << n;
      log_energy.push_back(std::log(problem.Energy(s.q, s.v)));
    }
    // Least-squares slope of ln E over the second half (the spurious root has died out by then).
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    const int first = steps / 2;
    for (int n = first; n < steps; ++n) {
      sx += n, sy += log_energy[n], sxx += double(n) * n, sxy += n * log_energy[n];
    }
    const double count = steps - first;
    const double slope = (count * sxy - sx * sy) / (count * sxx - sx * sx);
    // The principal roots: the complex pair (or, should they be real, the largest root).
    double principal = 0.0;
    for (const auto& lambda : GeneralEigen(a, false).values) {
      if (std::abs(lambda.imag()) > 1e-12) principal = std::max(principal, std::abs(lambda));
    }
    if (principal == 0.0) principal = SpectralRadius(a);
    std::printf("omega h %.1f: energy decay per step %.5f, 2 ln|lambda| %.5f\n", omega_h, slope, 2 * std::log(principal));
    EXPECT_NEAR(slope, 2.0 * std::log(principal), 0.03 * std::abs(2.0 * std::log(principal)));
  }
}

// Torque-free symmetric top, J = diag(J₁, J₁, J₃): ω₃ is constant and (ω₁ + i ω₂) turns at
// λ = (J₃ − J₁) ω₃ / J₁ in the body frame (Euler's equations); the energy ½ ωᵀJω and the world
// angular momentum R J ω are constant. 80 revolutions about the body axis.
struct TopRun {
  double omega_error = 0.0;     // |ω(T) − ω_exact(T)| / |ω₀|
  double energy_error = 0.0;    // largest |E/E₀ − 1|
  double momentum_error = 0.0;  // largest |L − L₀| / |L₀|
};

TopRun RunSymmetricTop(double h) {
  const Mat3 inertia = Vec3(2.0, 2.0, 5.0).asDiagonal();
  const testing::SpringHeldRigidBody top(3.0, inertia, 0.0, Vec3::Zero(), Vec3::Zero(), Vec3::Zero());
  GeneralizedAlphaOptions options;
  options.rho_infinity = 1.0;
  options.adaptive = false;
  options.initial_step = h;
  options.absolute_tolerance = 1e-12;
  GeneralizedAlphaIntegrator integrator(top, options);
  VecX q = VecX::Zero(7), v = VecX::Zero(6);
  const Quat start = so3::QuatFromRotationVector(Vec3(0.3, -0.7, 1.1));
  q.tail<4>() << start.w(), start.x(), start.y(), start.z();
  const Vec3 omega0(1.0, 0.5, 50.0);
  v.tail<3>() = omega0;
  integrator.Initialize(0.0, q, v);
  const double e0 = testing::RigidBodyEnergy(3.0, inertia, 0.0, Vec3::Zero(), Vec3::Zero(), Vec3::Zero(), q, v);
  const Vec3 l0 = testing::RigidBodyAngularMomentum(3.0, inertia, q, v);
  TopRun run;
  integrator.on_step = [&](const GeneralizedAlphaState& s) {
    const double e = testing::RigidBodyEnergy(3.0, inertia, 0.0, Vec3::Zero(), Vec3::Zero(), Vec3::Zero(), s.q, s.v);
    run.energy_error = std::max(run.energy_error, std::abs(e / e0 - 1.0));
    run.momentum_error =
        std::max(run.momentum_error, (testing::RigidBodyAngularMomentum(3.0, inertia, s.q, s.v) - l0).norm() / l0.norm());
  };
  const double end = 10.0;
  integrator.AdvanceTo(end);
  const double precession = (5.0 - 2.0) / 2.0 * omega0.z();
  const std::complex<double> transverse =
      std::complex<double>(omega0.x(), omega0.y()) * std::exp(std::complex<double>(0.0, precession * end));
  const Vec3 exact(transverse.real(), transverse.imag(), omega0.z());
  run.omega_error = (Vec3(integrator.state().v.tail<3>()) - exact).norm() / omega0.norm();
  return run;
}

TEST(GeneralizedAlpha, SymmetricTopPrecessesAtTheEulerRateAndKeepsItsInvariants) {
  double previous = 0.0;
  for (const double h : {1e-3, 5e-4, 2.5e-4}) {
    const TopRun run = RunSymmetricTop(h);
    std::printf("top h = %.2e: omega error %.3e, energy %.3e, angular momentum %.3e\n", h, run.omega_error,
                run.energy_error, run.momentum_error);
    // Second order: the precession phase error after 10 s, λ T (λh)²/12 (the trapezoidal rule's
    // phase error at λ = 75 rad/s), times |ω⊥|/|ω|, within a factor 1.5.
    EXPECT_LT(run.omega_error, 1.5 * 75.0 * 10.0 * std::pow(75.0 * h, 2) / 12.0 * std::sqrt(1.25) / 50.0);
    EXPECT_LT(run.energy_error, 1e-12);  // the kinetic energy of a torque-free body is kept exactly
    // The world angular momentum drifts at second order: 2.2e-6 at h = 1e-3 (measured).
    EXPECT_LT(run.momentum_error, 5e-6 * std::pow(h / 1e-3, 2));
    if (previous > 0.0) {
      EXPECT_NEAR(previous / run.omega_error, 4.0, 0.3);
    }
    previous = run.omega_error;
  }
}

// A heavy body swinging and spinning on a stiff spring (k = 1e5 N/m, 0.5 m from its centre of mass)
// under gravity: a spinning pendulum through large 3-D rotations. Energy and the vertical angular
// momentum about the anchor (gravity and the spring have no moment about the vertical through it)
// are constant.
TEST(GeneralizedAlpha, SpinningPendulumConservesEnergyAndVerticalAngularMomentum) {
  const double mass = 1.0, stiffness = 1e5;
  const Mat3 inertia = Vec3(0.02, 0.02, 0.01).asDiagonal();
  const Vec3 arm(0.0, 0.0, -0.5), gravity(0.0, 0.0, 9.81);
  const testing::SpringHeldRigidBody pendulum(mass, inertia, stiffness, arm, Vec3::Zero(), gravity);
  GeneralizedAlphaOptions options;
  options.rho_infinity = 1.0;
  options.adaptive = false;
  options.initial_step = 5e-4;
  // Newton to round-off: a modified Newton that stops at a loose tolerance leaves an error of the
  // same sign every step, which does work on the stiff spring (8e-3 of the energy at rtol = 1e-4).
  options.relative_tolerance = 1e-8;
  options.absolute_tolerance = 1e-12;
  GeneralizedAlphaIntegrator integrator(pendulum, options);
  VecX q = VecX::Zero(7), v = VecX::Zero(6);
  const Quat tilt = so3::QuatFromRotationVector(Vec3(1.0, 0.0, 0.0));
  q.head<3>() = -(tilt.toRotationMatrix() * arm);
  q.tail<4>() << tilt.w(), tilt.x(), tilt.y(), tilt.z();
  v.tail<3>() = Vec3(0.0, 2.0, 40.0);
  v.head<3>() = tilt.toRotationMatrix() * Vec3(v.tail<3>()).cross(-arm);  // the spring starts unstretched
  integrator.Initialize(0.0, q, v);
  const double e0 = testing::RigidBodyEnergy(mass, inertia, stiffness, arm, Vec3::Zero(), gravity, q, v);
  const double lz0 = testing::RigidBodyAngularMomentum(mass, inertia, q, v).z();
  const double l_scale = testing::RigidBodyAngularMomentum(mass, inertia, q, v).norm();
  double energy_error = 0.0, momentum_error = 0.0, lowest = 0.0;
  integrator.on_step = [&](const GeneralizedAlphaState& s) {
    const double e = testing::RigidBodyEnergy(mass, inertia, stiffness, arm, Vec3::Zero(), gravity, s.q, s.v);
    energy_error = std::max(energy_error, std::abs(e / e0 - 1.0));
    momentum_error = std::max(
        momentum_error, std::abs(testing::RigidBodyAngularMomentum(mass, inertia, s.q, s.v).z() - lz0) / l_scale);
    lowest = std::max(lowest, s.q[2]);
  };
  integrator.AdvanceTo(5.0);
  std::printf("pendulum: %ld steps, %ld factorizations, %ld iterations; energy %.3e, L_z %.3e, lowest z %.3f m\n",
              integrator.statistics().steps, integrator.statistics().factorizations,
              integrator.statistics().newton_iterations, energy_error, momentum_error, lowest);
  EXPECT_GT(lowest, 0.45);  // it swings through the bottom (z down)
  // The scheme's own O(h²) error: ωh = 0.16 for the spring, 0.02 for the spin (measured 4.8e-6
  // and 3.5e-5).
  EXPECT_LT(energy_error, 1e-5);
  EXPECT_LT(momentum_error, 1e-4);
}

// Adaptive steps on a hardening Duffing oscillator (k x + k3 x³, the cubic term 100 times the linear
// one at the amplitude) against a fine fixed-step reference: the error falls with the tolerance as
// tol^(2/3) (error per step of a second-order scheme: a factor 21.5 for 100 times the tolerance),
// and the steps vary along the cycle.
TEST(GeneralizedAlpha, AdaptiveStepsReachTheReferenceSolution) {
  const DuffingOscillator duffing(1.0, 1.0, 1e4);
  for (const double rho : {1.0, 0.9}) {
    auto run = [&](bool adaptive, double step, double tolerance) {
      GeneralizedAlphaOptions options;
      options.rho_infinity = rho;
      options.adaptive = adaptive;
      options.initial_step = step;
      options.relative_tolerance = tolerance;
      options.absolute_tolerance = 1e-3 * tolerance;
      GeneralizedAlphaIntegrator integrator(duffing, options);
      integrator.Initialize(0.0, VecX::Constant(1, 0.1), VecX::Zero(1));
      integrator.AdvanceTo(2.0);
      if (adaptive) {
        EXPECT_GT(integrator.statistics().largest_step, 2.0 * integrator.statistics().smallest_step);
      }
      // Position relative to the 0.1 m amplitude, velocity to the ~1 m/s peak.
      return Eigen::Vector2d(integrator.state().q[0] / 0.1, integrator.state().v[0]);
    };
    const Eigen::Vector2d reference = run(false, 2e-6, 1e-10);
    const double coarse = (run(true, 1e-4, 1e-5) - reference).norm();
    const double fine = (run(true, 1e-4, 1e-7) - reference).norm();
    std::printf("Duffing rho %.1f adaptive: error %.3e at tol 1e-5, %.3e at tol 1e-7\n", rho, coarse, fine);
    EXPECT_LT(fine, coarse / 10.0);
    EXPECT_LT(fine, 1e-3);  // over three cycles
  }
}

TEST(GeneralizedAlpha, AResidualThatTurnsNonFiniteStopsWithTheTimeAndReason) {
  const DuffingOscillator broken(1.0, 1.0, 0.0, 0.5);  // NaN once |x| > 0.5 m
  GeneralizedAlphaOptions options;
  options.initial_step = 1e-3;
  options.min_step = 1e-9;
  GeneralizedAlphaIntegrator integrator(broken, options);
  integrator.Initialize(0.0, VecX::Zero(1), VecX::Constant(1, 10.0));  // reaches 0.5 m at t ≈ 0.05 s
  try {
    integrator.AdvanceTo(1.0);
    ADD_FAILURE() << "expected a SolverError";
  } catch (const SolverError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("t = 0.05"), std::string::npos) << message;
    EXPECT_NE(message.find("not finite"), std::string::npos) << message;
  }
  EXPECT_TRUE(integrator.state().q.allFinite());
  EXPECT_LE(std::abs(integrator.state().q[0]), 0.5);
  GeneralizedAlphaIntegrator from_broken(broken, options);
  EXPECT_THROW(from_broken.Initialize(0.0, VecX::Constant(1, 1.0), VecX::Zero(1)), SolverError);
}

TEST(GeneralizedAlpha, StepLimitStopsWithAMessage) {
  const LinearOscillator problem = TwoMassChain();
  GeneralizedAlphaOptions options;
  options.adaptive = false;
  options.initial_step = 1e-3;
  options.max_steps = 10;
  GeneralizedAlphaIntegrator integrator(problem, options);
  integrator.Initialize(0.0, VecX::Constant(2, 0.01), VecX::Zero(2));
  EXPECT_THROW(integrator.AdvanceTo(1.0), SolverError);
}

}  // namespace generalized_alpha_test
}  // namespace drillflex::solvers

namespace drillflex::solvers {
namespace generalized_alpha_test {

// The four factorizations of the iteration matrix (dense LU up to dense_limit, block tridiagonal on
// the problem's coordinate blocks, LAPACK's banded LU, SparseLinearSolver for a matrix whose band is
// too wide) give the same motion of a 40-mass spring chain with an unsymmetric (gyroscopic-like)
// coupling, to round-off.
TEST(GeneralizedAlpha, DenseBlockBandedAndSparseFactorizationsGiveTheSameMotion) {
  const int n = 40;
  MatX mass = MatX::Identity(n, n), damping = MatX::Zero(n, n), stiffness = MatX::Zero(n, n);
  for (int i = 0; i < n; ++i) {
    stiffness(i, i) = 2.0e4;
    if (i + 1 < n) {
      stiffness(i, i + 1) = stiffness(i + 1, i) = -1.0e4;
      damping(i, i + 1) = 3.0;  // skew: the matrix is unsymmetric
      damping(i + 1, i) = -3.0;
    }
  }
  LinearOscillator chain(mass, damping, stiffness);
  for (int k = 0; k <= 8; ++k) chain.blocks.push_back(5 * k);  // 8 blocks of 5 masses
  auto run = [&](int dense_limit, double band_storage_limit, bool block_tridiagonal = false) {
    GeneralizedAlphaOptions options;
    options.dense_limit = dense_limit;
    options.band_storage_limit = band_storage_limit;
    options.block_tridiagonal = block_tridiagonal;
    options.reuse_contraction_factored = options.reuse_contraction;  // the same Newton path for all
    options.initial_step = 1e-3;
    GeneralizedAlphaIntegrator integrator(chain, options);
    integrator.Initialize(0.0, VecX::LinSpaced(n, 0.0, 0.01), VecX::Zero(n));
    integrator.AdvanceTo(0.2);
    return integrator.state().q;
  };
  const VecX dense = run(200, 4.0);
  const VecX banded = run(0, 4.0);
  const VecX sparse = run(0, 0.0);
  const VecX blocked = run(0, 0.0, true);
  EXPECT_GT(dense.norm(), 1e-3);  // it moved
  EXPECT_LT((banded - dense).norm(), 1e-10 * dense.norm());
  EXPECT_LT((blocked - dense).norm(), 1e-10 * dense.norm());
  EXPECT_LT((sparse - dense).norm(), 1e-10 * dense.norm());
}

}  // namespace generalized_alpha_test
}  // namespace drillflex::solvers
