// Steady-state harmonic response of a linear system (method.md §9.2, the forced response):
//   M ẍ + (D + Ω G) ẋ + K x = Re(F e^{iωt})  →  x = Re(X e^{iωt}),
//   (K − ω² M + iω (D + Ω G)) X = F,
// with M, D, G, K real sparse n×n (D and G may be left empty: zero) and F complex n×m (m load
// cases at once). ω is the excitation frequency, Ω the rotor speed that scales the gyroscopic
// matrix G (they differ, e.g. a bit exciting at 3× the rotary speed). |X_i| is the amplitude of
// DOF i, arg X_i its phase lead on the force's cosine.
//
// Solver: with the coordinates' blocks given (HarmonicOptions::block_starts, a string's bodies) and
// the matrix block-tridiagonal in them, the block LU of solvers/block_tridiagonal_lu.hpp, each
// solution accepted when its backward error is below kBlockBackwardErrorTolerance (after at most
// two steps of iterative refinement), else the frequency is solved again by the general sparse LU.
// The general one: Eigen::SparseLU on the complex matrix, the symbolic analysis (ordering,
// elimination tree) done once for the union of the four patterns and reused at every frequency; one
// numerical factorization per frequency serves all m load cases. Ordering as in
// linear_solver.hpp: the matrix's own order when its band is narrow, COLAMD otherwise.
// Measured on the 3 km string of bench/vibration_bench (17 370 coordinates, 965 blocks of 18):
// see docs/validation.md "Vibration speed".
// Measured (factorize once, then solve 3 right-hand sides; beam-like banded complex matrix, 6
// DOFs per node, 12×12 blocks; Release, this 2-core machine while another build was running, two
// runs): n = 2004: SparseLU natural 1.3 / 0.3 ms, COLAMD 1.3-1.7 / 0.3-0.5 ms, UMFPACK
// (Eigen::UmfPackLU) 2.0-2.7 / 3-5 ms; n = 18000: SparseLU natural 12-20 / 3 ms, COLAMD 17-21 /
// 3-6 ms, UMFPACK 21-30 / 27-34 ms. So UMFPACK is not used.
//
// Near-singular matrices: an undamped system driven at a natural frequency has no steady state.
// After each factorization the pivots of U are checked: min |u_jj| below
// singular_pivot_tolerance · max |a_ij| throws SolverError (naming ω), and so does a solution
// that is not finite; the solver never returns NaN or Inf.
#pragma once

#include <Eigen/Core>
#include <complex>
#include <functional>
#include <memory>
#include <vector>

#include "core/types.hpp"

namespace drillflex::solvers {

using ComplexMat = Eigen::MatrixXcd;

// The plain linear system of a linearized model (architecture.md: solvers see {M, D, G, K}).
struct LinearSystem {
  SparseMat mass;        // M, kg (or the generalized unit of each DOF)
  SparseMat damping;     // D, N·s/m; empty (0×0) = none
  SparseMat gyroscopic;  // G, per rad/s of rotor speed (velocity matrix D + Ω G); empty = none
  SparseMat stiffness;   // K, N/m
};

// A matrix T whose coefficients change with the frequency (a viscous fluid's added mass and
// damping, a hysteretic loss factor): it adds (−ω² a + iω b) T to the dynamic matrix with the
// coefficients (a, b) given at each Solve.
struct FrequencyTermCoefficients {
  double mass = 0.0;     // a
  double damping = 0.0;  // b
};

struct HarmonicOptions {
  // Relative pivot size min |u_jj| / max |a_ij| below which the matrix counts as singular.
  double singular_pivot_tolerance = 1e-12;
  // The first coordinate of each block and, last, n (e.g. each body's v_offset): the block LU is
  // used when every entry lies in a diagonal block or next to one. Empty: the general sparse LU.
  std::vector<Eigen::Index> block_starts;
};

// The largest backward error max_c ‖F_c − A X_c‖∞ / (‖A‖∞ ‖X_c‖∞ + ‖F_c‖∞) of a block-LU solution
// accepted; a backward-stable LU reaches about n·ε ≈ 1e-12 for n ≈ 2e4 at worst (Higham, "Accuracy and
// Stability of Numerical Algorithms", 2nd ed., 2002, §9.3), usually 1e-16.
inline constexpr double kBlockBackwardErrorTolerance = 1e-12;

// One factorization per frequency, the pattern analysed once. Throws LogicError on bad sizes
// (every matrix n×n, D and G may be empty) or non-finite entries.
class HarmonicSolver {
 public:
  explicit HarmonicSolver(LinearSystem system, HarmonicOptions options = {});
  // With frequency-dependent terms T_t (n×n; their patterns join the factorized one).
  HarmonicSolver(LinearSystem system, std::vector<SparseMat> terms, HarmonicOptions options = {});
  ~HarmonicSolver();
  HarmonicSolver(HarmonicSolver&&) noexcept;
  HarmonicSolver& operator=(HarmonicSolver&&) noexcept;

  // X (n×m) with (K − ω² M + iω (D + Ω G)) X = F, for ω ≥ 0 (rad/s) and the rotor speed Ω
  // (rad/s). Throws SolverError if the matrix is singular at ω (see the header comment),
  // LogicError if F has the wrong number of rows or ω, Ω are not finite.
  ComplexMat Solve(double frequency, const ComplexMat& loads, double rotor_speed = 0.0);

  // The same with the terms of the constructor: (K − ω² M + iω (D + Ω G) + Σ_t (−ω² a_t + iω b_t)
  // T_t) X = F, one coefficient pair per term (LogicError on a different count).
  ComplexMat Solve(double frequency, const ComplexMat& loads, double rotor_speed,
                   const std::vector<FrequencyTermCoefficients>& terms);

  Eigen::Index size() const;
  // Whether the block LU is in use, and how many frequencies it missed (solved by the general LU).
  bool block_lu() const;
  int block_fallbacks() const;

 private:
  struct Workspace;
  std::unique_ptr<Workspace> workspace_;
};

// A sweep: the excitation frequencies ω_j (rad/s) and, optionally, the rotor speed Ω_j at each
// (empty: Ω = 0 throughout; otherwise the same length as the frequencies).
struct HarmonicSweep {
  std::vector<double> frequencies;
  std::vector<double> rotor_speeds;
};

// The loads at sweep point j (n×m, the same m at every point), e.g. an imbalance m e Ω².
using HarmonicLoads = std::function<ComplexMat(Eigen::Index point, double frequency)>;
// Receives the response X at sweep point j (valid only during the call).
using HarmonicSink =
    std::function<void(Eigen::Index point, double frequency, const ComplexMat& response)>;

// Solves every point of the sweep in order and hands each response to `sink`. Throws as
// HarmonicSolver::Solve (at the first singular point), LogicError on inconsistent sweeps.
void SweepHarmonicResponse(const LinearSystem& system, const HarmonicSweep& sweep,
                           const HarmonicLoads& loads, const HarmonicSink& sink,
                           HarmonicOptions options = {});

// The same with loads that do not change along the sweep; returns X at every point.
std::vector<ComplexMat> SweepHarmonicResponse(const LinearSystem& system,
                                              const HarmonicSweep& sweep, const ComplexMat& loads,
                                              HarmonicOptions options = {});

}  // namespace drillflex::solvers
