// A random block-tridiagonal test matrix, real or complex, for the block LU tests.
#pragma once

#include <algorithm>
#include <complex>
#include <random>
#include <vector>

#include <Eigen/SparseCore>

namespace drillflex::solvers::testing {

// Every block of the structure on the blocks `starts` dense with entries uniform in [−1, 1] (real
// and imaginary parts), `shift` added to the diagonal; compressed.
template <typename Scalar>
Eigen::SparseMatrix<Scalar> RandomBlockTridiagonal(const std::vector<Eigen::Index>& starts, Scalar shift,
                                                   unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  auto draw = [&]() -> Scalar {
    if constexpr (std::is_same_v<Scalar, std::complex<double>>) {
      const double re = uniform(random);
      return Scalar(re, uniform(random));
    } else {
      return uniform(random);
    }
  };
  std::vector<Eigen::Triplet<Scalar>> entries;
  const std::size_t blocks = starts.size() - 1;
  for (std::size_t bi = 0; bi < blocks; ++bi) {
    for (std::size_t bj = bi > 0 ? bi - 1 : 0; bj < std::min(blocks, bi + 2); ++bj) {
      for (Eigen::Index i = starts[bi]; i < starts[bi + 1]; ++i) {
        for (Eigen::Index j = starts[bj]; j < starts[bj + 1]; ++j) {
          entries.emplace_back(i, j, draw() + (i == j ? shift : Scalar(0.0)));
        }
      }
    }
  }
  Eigen::SparseMatrix<Scalar> matrix(starts.back(), starts.back());
  matrix.setFromTriplets(entries.begin(), entries.end());
  matrix.makeCompressed();
  return matrix;
}

}  // namespace drillflex::solvers::testing
