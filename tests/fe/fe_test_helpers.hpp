// Small dense helpers shared by the fe/ tests: DOF selection and the lowest eigenvalues of
// K x = λ M x when K is positive definite (M may be singular), via K = LLᵀ and the standard
// symmetric problem L⁻¹ M L⁻ᵀ y = (1/λ) y.
#pragma once

#include <Eigen/Cholesky>
#include <algorithm>
#include <vector>

#include "core/types.hpp"
#include "core/dense_eigen.hpp"

namespace drillflex::fe::testing {

// The DOFs of nodes [first_node, last_node] whose local index (0..5) is listed.
inline std::vector<Index> SelectDofs(Index first_node, Index last_node, const std::vector<Index>& local) {
  std::vector<Index> dofs;
  for (Index k = first_node; k <= last_node; ++k) {
    for (Index d : local) dofs.push_back(6 * k + d);
  }
  return dofs;
}

inline MatX Restrict(const MatX& matrix, const std::vector<Index>& dofs) {
  const Index n = std::ssize(dofs);
  MatX out(n, n);
  for (Index r = 0; r < n; ++r) {
    for (Index c = 0; c < n; ++c) out(r, c) = matrix(dofs[r], dofs[c]);
  }
  return out;
}

// The `count` lowest λ of K x = λ B x, K symmetric positive definite, B symmetric semi-definite.
inline VecX LowestEigenvalues(const MatX& stiffness, const MatX& b, Index count) {
  const Eigen::LLT<MatX> llt(stiffness);
  const MatX l_inv_b = llt.matrixL().solve(b);
  const MatX c = llt.matrixL().solve(l_inv_b.transpose());
  const VecX mu = SymmetricEigen(0.5 * (c + c.transpose()), false).values;  // ascending: the largest μ is the lowest λ
  VecX lambda(count);
  for (Index j = 0; j < count; ++j) lambda(j) = 1.0 / mu(mu.size() - 1 - j);
  return lambda;
}

}  // namespace drillflex::fe::testing
