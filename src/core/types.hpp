// Scalar and Eigen aliases shared by every layer. SI units everywhere inside the engine.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <Eigen/SparseCore>

namespace drillflex {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
using Vec6 = Eigen::Matrix<double, 6, 1>;
using Mat6 = Eigen::Matrix<double, 6, 6>;
using VecX = Eigen::VectorXd;
using MatX = Eigen::MatrixXd;
using Quat = Eigen::Quaterniond;
using SparseMat = Eigen::SparseMatrix<double>;
using Triplet = Eigen::Triplet<double>;
// The one index type of degrees of freedom, nodes, bodies and elements, and of their counts: Eigen's
// (signed, std::ptrdiff_t), so that an index goes into a vector or a matrix as it is; a container's
// size comes in by std::ssize.
using Index = Eigen::Index;

inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kDegree = kPi / 180.0;  // one degree in radians

}  // namespace drillflex
