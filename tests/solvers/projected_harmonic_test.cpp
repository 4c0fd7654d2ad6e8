// The reduced harmonic solver against the full one (solvers/harmonic.hpp) on a fixed-free chain of
// 40 masses with non-proportional damping and a frequency term: a basis that spans everything gives
// the full solve; a small rational Krylov basis holds the static response exactly and the response
// over a band with four resonances within a few percent.
#include "solvers/projected_harmonic.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/error.hpp"
#include "solvers/eigen.hpp"
#include "toy_problems.hpp"

namespace drillflex::solvers {
namespace projected_harmonic_test {

using testing::ChainStiffness;
using testing::ScaledIdentity;

constexpr int kMasses = 40;

struct Chain {
  LinearSystem system;
  std::vector<SparseMat> terms;
  MatX loads;  // a tip force and a mid-chain force (real patterns)

  Chain() {
    system.stiffness = ChainStiffness(kMasses, 1.0e6, true);
    system.mass = ScaledIdentity(kMasses, 2.0);
    // A dashpot at one mass only: damping that the modes do not diagonalize.
    system.damping = SparseMat(kMasses, kMasses);
    system.damping.coeffRef(5, 5) = 300.0;
    SparseMat added(kMasses, kMasses);  // an added mass over the upper half, as the annulus terms
    for (int i = kMasses / 2; i < kMasses; ++i) added.coeffRef(i, i) = 0.5;
    terms = {added};
    loads = MatX::Zero(kMasses, 2);
    loads(kMasses - 1, 0) = 1.0;
    loads(kMasses / 2, 1) = 1.0;
  }
  // The added mass grows by 2 % over the band (as a viscous annulus's C_m(ω) changes over a sweep).
  std::vector<FrequencyTermCoefficients> Coefficients(double omega) const { return {{1.0 + 1e-4 * omega, 0.2}}; }
  // The basis's mass: the added mass at its coefficient of ω = 0 (as the sweep takes the annulus at
  // a reference frequency; the projection takes each frequency's own).
  SparseMat ReferenceMass() const { return system.mass + terms[0]; }
  ComplexMat Direct(double omega) const {
    HarmonicSolver solver(system, terms);
    return solver.Solve(omega, loads.cast<std::complex<double>>(), 0.0, Coefficients(omega));
  }
  ProjectedHarmonicSolver Reduced(double lowest, double highest, int shifts, int depth) const {
    KrylovBasisOptions options;
    options.lowest_frequency = lowest;
    options.highest_frequency = highest;
    options.shifts = shifts;
    options.depth = depth;
    const KrylovBasis basis = BuildKrylovBasis(system.stiffness, ReferenceMass(), loads, options);
    return ProjectedHarmonicSolver(system, terms, basis.vectors, Coefficients(0.0));
  }
  double LowestFrequency() const { return SolveModes(system.stiffness, ReferenceMass(), 1).eigenvalues[0]; }
};

TEST(ProjectedHarmonic, ABasisThatSpansEverythingIsTheFullSolve) {
  const Chain chain;
  const double omega1 = std::sqrt(chain.LowestFrequency());
  // 2 static columns + 20 shifts × 2 loads: the columns past the 40th are dropped (in the span).
  const ProjectedHarmonicSolver reduced = chain.Reduced(0.0, 80.0 * omega1, 20, 1);
  ASSERT_EQ(reduced.basis_size(), kMasses);
  for (const double omega : {0.0, 30.0, 200.0, 900.0}) {
    const ComplexMat x = reduced.Solve(omega, chain.loads.cast<std::complex<double>>(), 0.0, chain.Coefficients(omega));
    const ComplexMat reference = chain.Direct(omega);
    EXPECT_LT((x - reference).norm(), 1e-8 * reference.norm()) << omega;
  }
}

TEST(ProjectedHarmonic, StaticResponseIsExactAndTheBandIsHeld) {
  // A basis of at most 2 + 8 × 2 × 2 = 34 of the 40 directions for the band 0.2–7.5 ω₁ (the
  // resonances ω₁, ω₂ ≈ 3 ω₁, ω₃ ≈ 5 ω₁ and ω₄ ≈ 7 ω₁, with the dashpot's non-proportional damping).
  const Chain chain;
  const double omega1 = std::sqrt(chain.LowestFrequency());
  const double top = 7.5 * omega1;
  const ProjectedHarmonicSolver reduced = chain.Reduced(0.2 * omega1, top, 8, 2);
  EXPECT_LT(reduced.basis_size(), kMasses);
  const ComplexMat loads = chain.loads.cast<std::complex<double>>();
  const ComplexMat at_rest = chain.Direct(0.0);
  EXPECT_LT((reduced.Solve(0.0, loads, 0.0, chain.Coefficients(0.0)) - at_rest).norm(), 1e-10 * at_rest.norm());
  double largest = 0.0;
  for (double omega = 0.2 * omega1; omega <= top; omega += 0.01 * omega1) {
    const ComplexMat x = reduced.Solve(omega, loads, 0.0, chain.Coefficients(omega));
    const ComplexMat reference = chain.Direct(omega);
    for (Eigen::Index c = 0; c < loads.cols(); ++c) {
      largest = std::max(largest, (x.col(c) - reference.col(c)).norm() / reference.col(c).norm());
    }
  }
  std::printf("chain, 0.2-7.5 omega1, %ld basis vectors: largest relative error %.3g\n",
              static_cast<long>(reduced.basis_size()), largest);
  // Measured: 2.4 % with 17 vectors (the columns past them are in the span to 1e-8), at the peaks of
  // the lightly damped resonances (one dashpot), where a Ritz value off by 10⁻³ moves the peak; the
  // drill string's sweep (2–3 % damping) is held to 0.3 % (tests/io/reduced_sweep_test.cpp).
  EXPECT_LT(largest, 0.03);
}

TEST(ProjectedHarmonic, PatternBandsExpandEachLoadOnlyOverItsOwnBand) {
  // The tip force over the lower half of the band, the mid-chain force at one frequency only (a
  // motor's): fewer vectors than with every load at every shift, an expansion at exactly that
  // frequency, and there the undamped response to that load is in the span (exact).
  const Chain chain;
  const double top = 3.0 * std::sqrt(chain.LowestFrequency());
  const double single = 0.77 * top;
  KrylovBasisOptions options;
  options.lowest_frequency = 0.0;
  options.highest_frequency = top;
  options.shifts = 6;
  options.depth = 2;
  const KrylovBasis every = BuildKrylovBasis(chain.system.stiffness, chain.ReferenceMass(), chain.loads, options);
  options.pattern_bands = {{0.0, 0.5 * top}, {single, single}};
  const KrylovBasis banded = BuildKrylovBasis(chain.system.stiffness, chain.ReferenceMass(), chain.loads, options);
  EXPECT_LT(banded.vectors.cols(), every.vectors.cols());
  EXPECT_TRUE(std::find(banded.shifts.begin(), banded.shifts.end(), single) != banded.shifts.end());
  LinearSystem undamped = chain.system;
  undamped.damping = SparseMat();
  const std::vector<FrequencyTermCoefficients> reference{{1.0, 0.0}};
  const ProjectedHarmonicSolver reduced(undamped, chain.terms, banded.vectors, reference);
  HarmonicSolver direct(undamped, chain.terms);
  const ComplexMat loads = chain.loads.cast<std::complex<double>>();
  const ComplexMat exact = direct.Solve(single, loads, 0.0, reference);
  const ComplexMat approximate = reduced.Solve(single, loads, 0.0, reference);
  EXPECT_LT((approximate.col(1) - exact.col(1)).norm(), 1e-8 * exact.col(1).norm());
  options.pattern_bands = {{0.0, top}};
  EXPECT_THROW(BuildKrylovBasis(chain.system.stiffness, chain.ReferenceMass(), chain.loads, options), LogicError);
}

TEST(ProjectedHarmonic, RejectsInconsistentInput) {
  const Chain chain;
  KrylovBasisOptions options;
  options.highest_frequency = 0.0;
  EXPECT_THROW(BuildKrylovBasis(chain.system.stiffness, chain.system.mass, chain.loads, options), LogicError);
  const ProjectedHarmonicSolver reduced = chain.Reduced(1.0, 100.0, 2, 1);
  EXPECT_THROW(reduced.Solve(1.0, ComplexMat::Ones(3, 1), 0.0, chain.Coefficients(1.0)), LogicError);
  EXPECT_THROW(reduced.Solve(1.0, ComplexMat::Ones(kMasses, 1), 0.0, {}), LogicError);
}

}  // namespace projected_harmonic_test
}  // namespace drillflex::solvers
