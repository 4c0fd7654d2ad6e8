// Dense eigen-decompositions for every layer, compiled once in dense_eigen.cpp.
//
// Eigen's eigen solvers are header templates that cost 5-20 s of compile time in each translation
// unit that instantiates them (the general solver for a 3x3 matrix alone about 20 s): calling them
// through these functions keeps that cost in one file instead of a dozen.
#pragma once

#include <complex>

#include <Eigen/Core>

#include "core/types.hpp"

namespace drillflex {

struct DenseEigenpairs {
  VecX values;        // ascending
  MatX vectors;       // the eigenvectors as columns (empty when only the values were asked for)
  bool converged = false;  // false when the QR iteration failed (Eigen::NoConvergence)
};

// A x = λ x for a symmetric A; only A's lower triangle is read. Vectors orthonormal.
DenseEigenpairs SymmetricEigen(const MatX& a, bool with_vectors = true);

// A x = λ B x for symmetric A and symmetric positive definite B (lower triangles read), by the
// Cholesky reduction B = L Lᵀ; vectors B-orthonormal (xᵀ B x = 1).
DenseEigenpairs GeneralizedSymmetricEigen(const MatX& a, const MatX& b, bool with_vectors = true);

struct GeneralEigenpairs {
  Eigen::VectorXcd values;   // in the order the real Schur form gives them
  Eigen::MatrixXcd vectors;  // columns (empty when only the values were asked for)
  bool converged = false;
};

// A x = λ x for a general real square A.
GeneralEigenpairs GeneralEigen(const MatX& a, bool with_vectors = true);

}  // namespace drillflex
