// Harmonic response against closed-form answers: a 1-DOF oscillator (amplitude and phase at,
// below and above resonance, and the ODE itself in the time domain), a 2-DOF undamped system
// (its antiresonance), proportional damping against modal superposition, gyroscopic terms and a
// scrambled pattern against a dense solve, and singular systems (a clear SolverError).
#include "solvers/harmonic.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <complex>
#include <numeric>
#include <random>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "toy_problems.hpp"
#include "core/dense_eigen.hpp"

namespace drillflex::solvers {
namespace harmonic_test {

using Complex = std::complex<double>;
using testing::ChainStiffness;
using testing::ScaledIdentity;

SparseMat Scalar(double value) { return ScaledIdentity(1, value); }

ComplexMat Ones(Eigen::Index rows, Eigen::Index cols = 1) {
  return ComplexMat::Ones(rows, cols);
}

TEST(Harmonic, SingleDofAmplitudeAndPhaseAroundResonance) {
  // m ẍ + c ẋ + k x = F cos ωt: |X| = (F/k) / sqrt((1 − r²)² + (2ζr)²), the phase lag
  // φ = atan2(2ζr, 1 − r²), r = ω/ω_n, ζ = c/(2 sqrt(km)) (any vibration text, e.g. Thomson,
  // Theory of Vibration, §3.1).
  const double m = 2.0, k = 800.0, zeta = 0.05, force = 3.0;
  const double omega_n = std::sqrt(k / m);  // 20 rad/s
  const double c = 2.0 * zeta * std::sqrt(k * m);
  HarmonicSolver solver({Scalar(m), Scalar(c), {}, Scalar(k)});
  for (const double r : {0.0, 0.5, 1.0, 2.0}) {
    const double omega = r * omega_n;
    const Complex x = solver.Solve(omega, force * Ones(1))(0, 0);
    const double amplitude =
        (force / k) / std::sqrt(std::pow(1.0 - r * r, 2) + std::pow(2.0 * zeta * r, 2));
    const double lag = std::atan2(2.0 * zeta * r, 1.0 - r * r);
    EXPECT_NEAR(std::abs(x), amplitude, 1e-14 * amplitude) << r;
    EXPECT_NEAR(-std::arg(x), lag, 1e-13) << r;
    // x(t) = Re(X e^{iωt}) satisfies the ODE at any t.
    for (const double t : {0.0, 0.013, 0.21}) {
      const Complex e = std::exp(Complex(0.0, omega * t));
      const double displacement = (x * e).real();
      const double velocity = (Complex(0.0, omega) * x * e).real();
      const double acceleration = (-omega * omega * x * e).real();
      EXPECT_NEAR(m * acceleration + c * velocity + k * displacement, force * std::cos(omega * t),
                  1e-12 * force);
    }
  }
  // At resonance: amplitude F/(c ω_n), 90° behind the force; below, nearly in phase; above,
  // nearly opposite.
  const Complex at = solver.Solve(omega_n, force * Ones(1))(0, 0);
  EXPECT_NEAR(std::abs(at), force / (c * omega_n), 1e-15);
  EXPECT_NEAR(std::arg(at), -kPi / 2.0, 1e-14);
  EXPECT_GT(std::arg(solver.Solve(0.3 * omega_n, Ones(1))(0, 0)), -0.1);
  EXPECT_LT(std::arg(solver.Solve(3.0 * omega_n, Ones(1))(0, 0)), -kPi + 0.1);
}

TEST(Harmonic, TwoDofUndampedExactResponseAndAntiresonance) {
  // Ground –k1– m1 –k2– m2, force F on m1:
  //   Δ = (k1 + k2 − m1ω²)(k2 − m2ω²) − k2², X1 = F (k2 − m2ω²)/Δ, X2 = F k2/Δ.
  // At ω² = k2/m2 mass 1 stands still and X2 = −F/k2 (the tuned absorber, Den Hartog).
  const double m1 = 1.0, m2 = 0.5, k1 = 1000.0, k2 = 200.0, force = 2.0;
  std::vector<Triplet> mass = {{0, 0, m1}, {1, 1, m2}};
  std::vector<Triplet> stiffness = {{0, 0, k1 + k2}, {0, 1, -k2}, {1, 0, -k2}, {1, 1, k2}};
  LinearSystem system;
  system.mass.resize(2, 2);
  system.mass.setFromTriplets(mass.begin(), mass.end());
  system.stiffness.resize(2, 2);
  system.stiffness.setFromTriplets(stiffness.begin(), stiffness.end());
  HarmonicSolver solver(system);
  ComplexMat load = ComplexMat::Zero(2, 1);
  load(0, 0) = force;
  for (const double omega : {0.0, 5.0, 17.0, 20.0, 25.0, 60.0}) {
    const double w2 = omega * omega;
    const double det = (k1 + k2 - m1 * w2) * (k2 - m2 * w2) - k2 * k2;
    const ComplexMat x = solver.Solve(omega, load);
    const double x1 = force * (k2 - m2 * w2) / det, x2 = force * k2 / det;
    const double scale = std::abs(x2);
    EXPECT_NEAR(x(0, 0).real(), x1, 1e-13 * scale) << omega;
    EXPECT_NEAR(x(1, 0).real(), x2, 1e-13 * scale) << omega;
    EXPECT_EQ(x(0, 0).imag(), 0.0);
    EXPECT_EQ(x(1, 0).imag(), 0.0);
  }
  const double antiresonance = std::sqrt(k2 / m2);  // 20 rad/s
  const ComplexMat x = solver.Solve(antiresonance, load);
  EXPECT_LT(std::abs(x(0, 0)), 1e-15 * force / k2);
  EXPECT_NEAR(x(1, 0).real(), -force / k2, 1e-15);
}

TEST(Harmonic, ProportionalDampingMatchesModalSuperposition) {
  // D = a M + b K (Rayleigh) keeps the undamped modes: with M-normalised Φ,
  //   X = Σ_j φ_j φ_jᵀ F / (ω_j² − ω² + iω (a + b ω_j²)).
  const int n = 8;
  const SparseMat stiffness = ChainStiffness(n, 5e4, true);
  std::vector<Triplet> mass_entries;
  for (int i = 0; i < n; ++i) mass_entries.emplace_back(i, i, 1.0 + 0.25 * i);
  SparseMat mass(n, n);
  mass.setFromTriplets(mass_entries.begin(), mass_entries.end());
  const double a = 0.8, b = 2e-4;
  const SparseMat damping = a * mass + b * stiffness;
  const DenseEigenpairs modes = GeneralizedSymmetricEigen(MatX(stiffness), MatX(mass));
  ASSERT_TRUE(modes.converged);
  ComplexMat loads = ComplexMat::Zero(n, 2);
  loads(n - 1, 0) = 100.0;                 // a tip force
  loads(3, 1) = Complex(0.0, 40.0);         // a force at node 3, 90° ahead
  loads(5, 1) = -25.0;
  HarmonicSweep sweep;
  for (double omega = 1.0; omega < 400.0; omega *= 1.3) sweep.frequencies.push_back(omega);
  for (const double lambda : modes.values) sweep.frequencies.push_back(std::sqrt(lambda));
  const std::vector<ComplexMat> responses =
      SweepHarmonicResponse({mass, damping, {}, stiffness}, sweep, loads);
  ASSERT_EQ(responses.size(), sweep.frequencies.size());
  for (std::size_t p = 0; p < responses.size(); ++p) {
    const double omega = sweep.frequencies[p];
    ComplexMat expected = ComplexMat::Zero(n, 2);
    for (int j = 0; j < n; ++j) {
      const double lambda = modes.values(j);
      const Eigen::VectorXcd phi = modes.vectors.col(j).cast<Complex>();
      const Complex denominator(lambda - omega * omega, omega * (a + b * lambda));
      expected += phi * (phi.transpose() * loads) / denominator;
    }
    EXPECT_LT((responses[p] - expected).norm(), 1e-10 * expected.norm()) << omega;
  }
}

TEST(Harmonic, SweepCallbackSeesEveryPointInOrderWithItsLoads) {
  // An imbalance force m e Ω² at Ω = ω on a 1-DOF rotor: X = m e ω² / (k − Mω² + icω).
  const double m = 10.0, k = 4e4, c = 30.0, imbalance = 0.02;  // kg·m
  HarmonicSweep sweep{{10.0, 40.0, 63.0, 90.0}, {}};
  std::vector<Eigen::Index> seen;
  SweepHarmonicResponse(
      {Scalar(m), Scalar(c), {}, Scalar(k)}, sweep,
      [&](Eigen::Index, double omega) { return ComplexMat(imbalance * omega * omega * Ones(1)); },
      [&](Eigen::Index point, double omega, const ComplexMat& x) {
        seen.push_back(point);
        EXPECT_EQ(omega, sweep.frequencies[static_cast<std::size_t>(point)]);
        const Complex expected = imbalance * omega * omega / Complex(k - m * omega * omega,
                                                                     c * omega);
        EXPECT_LT(std::abs(x(0, 0) - expected), 1e-14 * std::abs(expected));
      });
  EXPECT_EQ(seen, (std::vector<Eigen::Index>{0, 1, 2, 3}));
  HarmonicSweep bad{{1.0, 2.0}, {3.0}};
  EXPECT_THROW(SweepHarmonicResponse({Scalar(m), {}, {}, Scalar(k)}, bad, Ones(1)), LogicError);
}

// K − ω²M + iω(D + ΩG) assembled densely and solved by dense LU.
ComplexMat DenseResponse(const LinearSystem& s, double omega, double rotor_speed,
                         const ComplexMat& loads) {
  Eigen::MatrixXcd a = (MatX(s.stiffness) - omega * omega * MatX(s.mass)).cast<Complex>();
  a += Complex(0.0, omega) * (MatX(s.damping) + rotor_speed * MatX(s.gyroscopic)).cast<Complex>();
  return a.partialPivLu().solve(loads);
}

TEST(Harmonic, GyroscopicTermsAndScrambledPatternsMatchADenseSolve) {
  // A chain of n masses moving in x and y (DOFs 2i, 2i+1), lightly damped, with a skew
  // gyroscopic coupling g (x_i, y_i); then the same with the DOFs randomly permuted (a wide
  // band: the COLAMD path).
  const int nodes = 60, n = 2 * nodes;
  std::vector<Triplet> k_entries, m_entries, d_entries, g_entries;
  for (int i = 0; i < nodes; ++i) {
    for (int axis = 0; axis < 2; ++axis) {
      const int dof = 2 * i + axis;
      m_entries.emplace_back(dof, dof, 3.0);
      d_entries.emplace_back(dof, dof, 0.7);
      k_entries.emplace_back(dof, dof, (i == 0 ? 1.0 : 2.0) * 1e5);
      if (i > 0) {
        k_entries.emplace_back(dof, dof - 2, -1e5);
        k_entries.emplace_back(dof - 2, dof, -1e5);
      }
    }
    g_entries.emplace_back(2 * i, 2 * i + 1, 0.4);
    g_entries.emplace_back(2 * i + 1, 2 * i, -0.4);
  }
  auto build = [n](const std::vector<Triplet>& entries, const std::vector<int>& order) {
    std::vector<Triplet> mapped;
    for (const Triplet& t : entries) mapped.emplace_back(order[t.row()], order[t.col()], t.value());
    SparseMat matrix(n, n);
    matrix.setFromTriplets(mapped.begin(), mapped.end());
    return matrix;
  };
  std::vector<int> identity(n), scrambled(n);
  std::iota(identity.begin(), identity.end(), 0);
  scrambled = identity;
  std::shuffle(scrambled.begin(), scrambled.end(), std::mt19937(7));
  ComplexMat loads = ComplexMat::Random(n, 3);
  for (const auto* order : {&identity, &scrambled}) {
    const LinearSystem system{build(m_entries, *order), build(d_entries, *order),
                              build(g_entries, *order), build(k_entries, *order)};
    HarmonicSolver solver(system);
    for (const double omega : {0.0, 3.0, 57.0, 180.0}) {
      for (const double rotor_speed : {0.0, 12.0, -40.0}) {
        const ComplexMat x = solver.Solve(omega, loads, rotor_speed);
        const ComplexMat expected = DenseResponse(system, omega, rotor_speed, loads);
        EXPECT_LT((x - expected).norm(), 1e-9 * expected.norm()) << omega << " " << rotor_speed;
      }
    }
  }
}

TEST(Harmonic, UndampedSystemAtANaturalFrequencyIsAClearError) {
  // k − ω²m = 0 exactly (k = 4, m = 1, ω = 2): a zero pivot.
  HarmonicSolver one({Scalar(1.0), {}, {}, Scalar(4.0)});
  try {
    one.Solve(2.0, Ones(1));
    FAIL() << "no SolverError";
  } catch (const SolverError& error) {
    EXPECT_NE(std::string(error.what()).find("singular at ω = 2 rad/s"), std::string::npos)
        << error.what();
  }
  EXPECT_NO_THROW(one.Solve(2.0 * (1 + 1e-6), Ones(1)));
  // A 10-mass chain at its (irrational) natural frequencies: singular to round-off only.
  const int n = 10;
  const SparseMat stiffness = ChainStiffness(n, 1e3, true);
  const SparseMat mass = ScaledIdentity(n, 2.0);
  const DenseEigenpairs modes = GeneralizedSymmetricEigen(MatX(stiffness), MatX(mass), false);
  HarmonicSolver chain({mass, {}, {}, stiffness});
  const ComplexMat loads = Ones(n, 2);
  for (const double lambda : modes.values) {
    EXPECT_THROW(chain.Solve(std::sqrt(lambda), loads), SolverError) << std::sqrt(lambda);
    // Just beside it the response is large but finite.
    const ComplexMat near = chain.Solve(std::sqrt(lambda) * (1 + 1e-7), loads);
    EXPECT_TRUE(near.allFinite());
  }
  // A little damping makes every frequency solvable.
  HarmonicSolver damped({mass, ScaledIdentity(n, 0.01), {}, stiffness});
  for (const double lambda : modes.values) {
    EXPECT_TRUE(damped.Solve(std::sqrt(lambda), loads).allFinite());
  }
}

TEST(Harmonic, RejectsInconsistentInput) {
  const SparseMat two = ScaledIdentity(2, 1.0);
  EXPECT_THROW(HarmonicSolver({two, {}, {}, Scalar(1.0)}), LogicError);
  EXPECT_THROW(HarmonicSolver({two, Scalar(1.0), {}, two}), LogicError);
  EXPECT_THROW(HarmonicSolver({two, {}, ScaledIdentity(3, 1.0), two}), LogicError);
  SparseMat bad = two;
  bad.coeffRef(0, 0) = std::nan("");
  EXPECT_THROW(HarmonicSolver({two, {}, {}, bad}), LogicError);
  HarmonicSolver solver({two, {}, {}, two});
  EXPECT_EQ(solver.size(), 2);
  EXPECT_THROW(solver.Solve(1.0, Ones(3)), LogicError);
  EXPECT_THROW(solver.Solve(-1.0, Ones(2)), LogicError);
  EXPECT_THROW(solver.Solve(std::nan(""), Ones(2)), LogicError);
}

TEST(Harmonic, FrequencyTermsEqualASystemThatHoldsThem) {
  // (K − ω²(M + a T₁) + iω(D + b T₂)) X = F with T₁, T₂ passed as frequency terms equals the solve
  // of a system built with M + a T₁ and D + b T₂ (4-DOF chain; T₁ off the chain's pattern).
  const SparseMat k = ChainStiffness(4, 1000.0, true);
  const SparseMat m = ScaledIdentity(4, 2.0);
  const SparseMat d = ScaledIdentity(4, 0.3);
  SparseMat first(4, 4), second(4, 4);
  first.coeffRef(1, 1) = 0.7;
  first.coeffRef(0, 3) = first.coeffRef(3, 0) = 0.1;
  second.coeffRef(3, 3) = 1.5;
  HarmonicSolver split({m, d, {}, k}, {first, second});
  for (const double omega : {0.0, 7.0, 19.0, 40.0}) {
    const double a = 1.0 + 0.01 * omega, b = 2.0 / (1.0 + omega);
    HarmonicSolver whole({SparseMat(m + a * first), SparseMat(d + b * second), {}, k});
    const ComplexMat x = split.Solve(omega, Ones(4, 2), 0.0, {{a, 0.0}, {0.0, b}});
    const ComplexMat reference = whole.Solve(omega, Ones(4, 2));
    EXPECT_LT((x - reference).norm(), 1e-12 * reference.norm()) << omega;
  }
  EXPECT_THROW(split.Solve(1.0, Ones(4), 0.0, {{1.0, 0.0}}), LogicError);
}

}  // namespace harmonic_test
}  // namespace drillflex::solvers
