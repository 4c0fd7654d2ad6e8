// One factorization and solve of a string-shaped complex dynamic matrix, the work of every
// frequency of the direct vibration sweep (solvers/harmonic.hpp): 965 blocks of 18 coordinates
// (17 370, the 3 km string of bench/vibration_bench), every block and coupling dense, three
// right-hand sides. The block LU (solvers/block_tridiagonal_lu.hpp) against Eigen's SparseLU in
// the matrix's own order (the general path). Never a timed test: build in Release and run by hand,
//   build/bench/harmonic_lu_bench
#include <benchmark/benchmark.h>

#include <Eigen/SparseLU>
#include <complex>
#include <random>
#include <vector>

#include "solvers/block_tridiagonal_lu.hpp"

namespace {

using Complex = std::complex<double>;
using ComplexSparse = Eigen::SparseMatrix<Complex>;

constexpr int kBlocks = 965, kBlockSize = 18;

std::vector<Eigen::Index> Starts() {
  std::vector<Eigen::Index> starts;
  for (int k = 0; k <= kBlocks; ++k) starts.push_back(static_cast<Eigen::Index>(k) * kBlockSize);
  return starts;
}

// Random dense blocks, the diagonal ones shifted to keep the matrix regular (a damped system).
ComplexSparse StringMatrix() {
  std::mt19937 random(3);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  std::vector<Eigen::Triplet<Complex>> entries;
  for (int bi = 0; bi < kBlocks; ++bi) {
    for (int bj = std::max(0, bi - 1); bj <= std::min(kBlocks - 1, bi + 1); ++bj) {
      for (int i = 0; i < kBlockSize; ++i) {
        for (int j = 0; j < kBlockSize; ++j) {
          const int row = bi * kBlockSize + i, col = bj * kBlockSize + j;
          entries.emplace_back(row, col, Complex(uniform(random), 0.05 * uniform(random)) + (row == col ? 8.0 : 0.0));
        }
      }
    }
  }
  ComplexSparse matrix(kBlocks * kBlockSize, kBlocks * kBlockSize);
  matrix.setFromTriplets(entries.begin(), entries.end());
  matrix.makeCompressed();
  return matrix;
}

void BM_BlockLu(benchmark::State& state) {
  const ComplexSparse matrix = StringMatrix();
  const Eigen::MatrixXcd rhs = Eigen::MatrixXcd::Random(matrix.rows(), 3);
  drillflex::solvers::BlockTridiagonalLu lu;
  if (!lu.Analyze(matrix, Starts())) {
    state.SkipWithError("not block-tridiagonal");
    return;
  }
  for (auto _ : state) {
    lu.Factorize(matrix);
    benchmark::DoNotOptimize(lu.Solve(rhs).data());
  }
}

void BM_SparseLuNaturalOrder(benchmark::State& state) {
  const ComplexSparse matrix = StringMatrix();
  const Eigen::MatrixXcd rhs = Eigen::MatrixXcd::Random(matrix.rows(), 3);
  Eigen::SparseLU<ComplexSparse, Eigen::NaturalOrdering<int>> lu;
  lu.analyzePattern(matrix);
  for (auto _ : state) {
    lu.factorize(matrix);
    Eigen::MatrixXcd x = lu.solve(rhs);
    benchmark::DoNotOptimize(x.data());
  }
}

BENCHMARK(BM_BlockLu)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SparseLuNaturalOrder)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
