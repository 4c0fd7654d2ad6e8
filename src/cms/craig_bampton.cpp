#include "cms/craig_bampton.hpp"

#include <Eigen/Cholesky>
#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <string>

#include "core/dense_eigen.hpp"
#include "core/error.hpp"

namespace drillflex::cms {
namespace {

// Eigenpairs of K x = λ M x (K positive definite): λ ascending, x mass-normalised (xᵀ M x = 1).
struct Eigenpairs {
  VecX eigenvalues;
  MatX vectors;
};

// Cholesky factor of a stiffness that must be positive definite; `what` names it in errors.
Eigen::LLT<MatX> FactorStiffness(const MatX& stiffness, const char* what) {
  Eigen::LLT<MatX> llt(stiffness);
  if (llt.info() != Eigen::Success) {
    std::string message = "Craig-Bampton: the stiffness of the ";
    message.append(what).append(" is not positive definite (an unrestrained motion)");
    throw LogicError(message);
  }
  return llt;
}

// The (up to) `count` lowest eigenpairs of K x = λ M x from K = LLᵀ (the stiffness-Cholesky form
// of the header). Stops early at massless modes (1/λ ≤ 1e-14 of the largest): the caller checks
// that it got what it needs.
Eigenpairs LowestModes(const Eigen::LLT<MatX>& llt, const MatX& mass, Index count) {
  const MatX l_inv_m = llt.matrixL().solve(mass);
  MatX c = llt.matrixL().solve(l_inv_m.transpose());
  c = 0.5 * (c + c.transpose());
  const DenseEigenpairs solver = SymmetricEigen(c);
  const VecX& mu = solver.values;  // ascending: the largest μ = 1/λ is the lowest λ
  const Index n = mu.size();
  const double mu_max = n > 0 ? mu(n - 1) : 0.0;
  Index massive = 0;
  while (massive < std::min(count, n) && mu(n - 1 - massive) > 1e-14 * mu_max) ++massive;
  Eigenpairs out{VecX(massive), MatX(mass.rows(), massive)};
  for (Index j = 0; j < massive; ++j) {
    const double m = mu(n - 1 - j);
    out.eigenvalues(j) = 1.0 / m;
    // x = L⁻ᵀ y has xᵀ K x = 1 and xᵀ M x = μ: divide by sqrt(μ).
    out.vectors.col(j) = llt.matrixU().solve(solver.vectors.col(n - 1 - j)) / std::sqrt(m);
  }
  return out;
}

void ThrowMassless(const char* what) {
  std::string message = "Craig-Bampton: a kept mode of the ";
  message.append(what).append(" has no mass");
  throw LogicError(message);
}

MatX Submatrix(const MatX& a, const std::vector<Index>& index) {
  const Index n = std::ssize(index);
  MatX out(n, n);
  for (Index c = 0; c < n; ++c) {
    for (Index r = 0; r < n; ++r) out(r, c) = a(index[r], index[c]);
  }
  return out;
}

// Groups of DOFs coupled through K or M: the connected components of their coupling graph (a
// straight beam splits into axial, torsion and the two bending planes). Solving each group alone
// is exact and about ten times cheaper than one dense eigenproblem.
std::vector<std::vector<Index>> CoupledGroups(const MatX& k, const MatX& m) {
  const Index n = k.rows();
  std::vector<Index> parent(n);
  for (Index i = 0; i < n; ++i) parent[i] = i;
  const auto root = [&](Index i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  for (Index c = 0; c < n; ++c) {
    for (Index r = 0; r < c; ++r) {
      if (k(r, c) != 0.0 || m(r, c) != 0.0) parent[root(r)] = root(c);
    }
  }
  std::vector<std::vector<Index>> groups;
  std::vector<Index> group_of_root(n, -1);
  for (Index i = 0; i < n; ++i) {
    Index& g = group_of_root[root(i)];
    if (g < 0) {
      g = std::ssize(groups);
      groups.emplace_back();
    }
    groups[g].push_back(i);
  }
  return groups;
}

// The `count` lowest eigenpairs of K x = λ M x over all coupled groups (ties keep group order,
// so the equal y/z bending pairs stay adjacent), and the partner of a multiple eigenvalue the count
// would cut (eigenvalues within 1e-8 of each other): a body's y and z bending modes come in equal
// pairs, and keeping one of a pair makes the body stiffer in one plane than in the other (the MWD
// of the bundled example, 6 modes asked: 865.4 and 868.0 rad/s instead of a pair) and its modes
// not closed under a turn about its axis (cms::ReducedBody::twist_generator). Throws LogicError on
// a non-positive-definite K or a massless kept mode.
Eigenpairs LowestModesByGroups(const MatX& k, const MatX& m, Index count, const char* what) {
  const std::vector<std::vector<Index>> groups = CoupledGroups(k, m);
  std::vector<Eigenpairs> solved;
  struct Candidate {
    double eigenvalue;
    Index group, index;
  };
  std::vector<Candidate> candidates;
  for (Index g = 0; g < std::ssize(groups); ++g) {
    const Eigen::LLT<MatX> llt = FactorStiffness(Submatrix(k, groups[g]), what);
    solved.push_back(LowestModes(llt, Submatrix(m, groups[g]), count));
    for (Index j = 0; j < solved.back().eigenvalues.size(); ++j) {
      candidates.push_back({solved.back().eigenvalues(j), g, j});
    }
  }
  if (std::ssize(candidates) < count) ThrowMassless(what);
  std::stable_sort(
      candidates.begin(), candidates.end(),
      [](const Candidate& a, const Candidate& b) { return a.eigenvalue < b.eigenvalue; });
  while (count > 0 && count < std::ssize(candidates) &&
         candidates[count].eigenvalue - candidates[count - 1].eigenvalue <= 1e-8 * candidates[count].eigenvalue) {
    ++count;
  }
  Eigenpairs out{VecX(count), MatX::Zero(k.rows(), count)};
  for (Index j = 0; j < count; ++j) {
    const Candidate& pick = candidates[j];
    out.eigenvalues(j) = pick.eigenvalue;
    const std::vector<Index>& rows = groups[pick.group];
    for (Index r = 0; r < std::ssize(rows); ++r) {
      out.vectors(rows[r], j) = solved[pick.group].vectors(r, pick.index);
    }
  }
  return out;
}

void CheckBoundary(Index dof_count, const std::vector<Index>& boundary) {
  std::vector<Index> sorted = boundary;
  std::sort(sorted.begin(), sorted.end());
  if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) {
    throw LogicError("Craig-Bampton: a boundary DOF is listed twice");
  }
  if (!sorted.empty() && (sorted.front() < 0 || sorted.back() >= dof_count)) {
    throw LogicError("Craig-Bampton: a boundary DOF is out of range");
  }
}

// Dense block A(rows, cols) of a sparse matrix.
MatX DenseBlock(const SparseMat& a, const std::vector<Index>& rows, const std::vector<Index>& cols) {
  std::vector<Index> row_position(a.rows(), -1);
  for (Index r = 0; r < std::ssize(rows); ++r) row_position[rows[r]] = r;
  MatX block = MatX::Zero(std::ssize(rows), std::ssize(cols));
  for (Index c = 0; c < std::ssize(cols); ++c) {
    for (SparseMat::InnerIterator it(a, cols[c]); it; ++it) {
      const Index r = row_position[it.row()];
      if (r >= 0) block(r, c) = it.value();
    }
  }
  return block;
}

// Rotates every pair of equal eigenvalues (round-section y/z bending) so that the first member
// has the most lateral-v content and the second the least: planar modes for a planar pair. Then
// fixes each mode's sign so its largest entry of U is positive. Keeps M- and K-orthonormality.
void AlignModes(const VecX& eigenvalues, MatX& x, MatX& u) {
  const Index n = eigenvalues.size();
  for (Index j = 0; j + 1 < n; ++j) {
    const bool pair = std::abs(eigenvalues(j + 1) - eigenvalues(j)) <= 1e-7 * eigenvalues(j + 1);
    const bool triple =
        j + 2 < n && std::abs(eigenvalues(j + 2) - eigenvalues(j)) <= 1e-7 * eigenvalues(j + 2);
    if (!pair || triple) continue;
    MatX v(u.rows() / 6, 2);  // the v (y) displacement of every node in both modes
    for (Index k = 0; k < v.rows(); ++k) v.row(k) = u.block(6 * k + 1, j, 1, 2);
    const DenseEigenpairs split = SymmetricEigen(v.transpose() * v);
    Eigen::Matrix2d rotation;  // columns: most v-content first
    rotation << split.vectors.col(1), split.vectors.col(0);
    x.middleCols(j, 2) = x.middleCols(j, 2) * rotation;
    u.middleCols(j, 2) = u.middleCols(j, 2) * rotation;
    ++j;
  }
  for (Index j = 0; j < n; ++j) {
    Eigen::Index largest = 0;
    u.col(j).cwiseAbs().maxCoeff(&largest);
    if (u(largest, j) < 0.0) {
      u.col(j) = -u.col(j);
      x.col(j) = -x.col(j);
    }
  }
}

}  // namespace

CraigBamptonBasis BuildCraigBamptonBasis(const SparseMat& stiffness, const SparseMat& mass,
                                         const std::vector<Index>& boundary_dofs, Index mode_count) {
  const Index n = stiffness.rows();
  CheckBoundary(n, boundary_dofs);
  CraigBamptonBasis basis;
  basis.boundary_dofs = boundary_dofs;
  std::vector<bool> is_boundary(n, false);
  for (Index d : boundary_dofs) is_boundary[d] = true;
  for (Index d = 0; d < n; ++d) {
    if (!is_boundary[d]) basis.internal_dofs.push_back(d);
  }
  const Index nb = std::ssize(boundary_dofs);
  const Index ni = std::ssize(basis.internal_dofs);
  if (mode_count < 0 || mode_count > ni) {
    std::string message = "needs 0 <= modes <= ";
    message.append(std::to_string(ni))
        .append(" (the internal DOF count), got ")
        .append(std::to_string(mode_count));
    throw InputError({}, "modes_per_body", message);
  }

  const MatX k_ii = DenseBlock(stiffness, basis.internal_dofs, basis.internal_dofs);
  const MatX m_ii = DenseBlock(mass, basis.internal_dofs, basis.internal_dofs);
  const MatX k_ib = DenseBlock(stiffness, basis.internal_dofs, boundary_dofs);
  // Step 3: fixed-interface normal modes K_ii φ = ω² M_ii φ, the H lowest.
  const char* interior = "interior (interface held)";
  const Eigen::LLT<MatX> k_ii_llt = FactorStiffness(k_ii, interior);
  const Eigenpairs fixed = LowestModesByGroups(k_ii, m_ii, mode_count, interior);
  mode_count = fixed.eigenvalues.size();  // a cut pair completed
  basis.fixed_interface_eigenvalues = fixed.eigenvalues;
  // Step 4: constraint modes Ψ_ib = −K_ii⁻¹ K_ib.
  const MatX psi = -k_ii_llt.solve(k_ib);

  // Step 5: T = [[I, 0], [Ψ_ib, Φ_ik]] in the model's DOF order.
  basis.transformation = MatX::Zero(n, nb + mode_count);
  for (Index j = 0; j < nb; ++j) basis.transformation(boundary_dofs[j], j) = 1.0;
  for (Index i = 0; i < ni; ++i) {
    const Index row = basis.internal_dofs[i];
    basis.transformation.row(row).head(nb) = psi.row(i);
    // No modes (modes_per_body: 0): row() of the empty mode matrix would offset a null pointer.
    if (mode_count > 0) basis.transformation.row(row).tail(mode_count) = fixed.vectors.row(i);
  }
  const MatX kt = stiffness * basis.transformation;
  const MatX mt = mass * basis.transformation;
  basis.reduced_stiffness = basis.transformation.transpose() * kt;
  basis.reduced_mass = basis.transformation.transpose() * mt;
  basis.reduced_stiffness =
      0.5 * (basis.reduced_stiffness + basis.reduced_stiffness.transpose()).eval();
  basis.reduced_mass = 0.5 * (basis.reduced_mass + basis.reduced_mass.transpose()).eval();
  return basis;
}

namespace {

std::vector<Index> InterfaceNodes(const fe::BodyFeModel& model, const ReductionOptions& options) {
  std::vector<Index> nodes = options.interface_nodes;
  if (nodes.empty()) nodes = {0, model.node_count() - 1};
  std::sort(nodes.begin(), nodes.end());
  const bool duplicate = std::adjacent_find(nodes.begin(), nodes.end()) != nodes.end();
  if (duplicate || nodes.front() < 0 || nodes.back() >= model.node_count()) {
    throw InputError({}, "interface_nodes", "interface nodes must be distinct nodes of the body");
  }
  return nodes;
}

// Step 6: the elastic eigenpairs of K̄ x = λ M̄ x in the M̄-orthogonal complement of the rigid
// fields, X mass-normalised. Throws LogicError unless there are exactly six zero-energy modes.
Eigenpairs ElasticModes(const CraigBamptonBasis& basis, const MatX& rigid_fields) {
  const Index nc = basis.reduced_mass.rows();
  const Index nb = std::ssize(basis.boundary_dofs);
  MatX rigid = MatX::Zero(nc, 6);  // boundary rows of R, zero modal rows
  for (Index j = 0; j < nb; ++j) rigid.row(j) = rigid_fields.row(basis.boundary_dofs[j]);
  const double k_norm = basis.reduced_stiffness.norm();
  for (Index c = 0; c < 6; ++c) {
    if ((basis.reduced_stiffness * rigid.col(c)).norm() > 1e-9 * k_norm * rigid.col(c).norm()) {
      throw LogicError(
          "Craig-Bampton: a rigid-body motion stores strain energy (fewer than 6 zero modes)");
    }
  }
  // Z: an orthonormal basis of {z : zᵀ M̄ R̄ = 0}, the last nc − 6 columns of the full Q of M̄ R̄.
  const Eigen::HouseholderQR<MatX> qr(basis.reduced_mass * rigid);
  const MatX z = (qr.householderQ() * MatX::Identity(nc, nc)).rightCols(nc - 6);
  const MatX k_z = z.transpose() * basis.reduced_stiffness * z;
  const MatX m_z = z.transpose() * basis.reduced_mass * z;
  const char* what = "body without its rigid motion";
  const Eigen::LLT<MatX> k_z_llt = FactorStiffness(0.5 * (k_z + k_z.transpose()), what);
  Eigenpairs modes = LowestModes(k_z_llt, 0.5 * (m_z + m_z.transpose()), nc - 6);
  if (modes.eigenvalues.size() < nc - 6) ThrowMassless(what);
  if (nc > 6 && !(modes.eigenvalues(0) > 1e-12 * modes.eigenvalues(nc - 7))) {
    throw LogicError("Craig-Bampton: more than 6 zero-energy modes (a mechanism in the body)");
  }
  modes.vectors = z * modes.vectors;
  return modes;
}

// Step 7: the per-node data of the floating-frame node sum.
void FillNodeData(const fe::BodyFeModel& model, const MatX& u, ReducedBody& body) {
  for (Index k = 0; k < model.node_count(); ++k) {
    body.node_positions.emplace_back(model.node_x[k], 0.0, 0.0);
    body.node_mass.push_back(model.node_mass[k]);
    body.node_lateral_mass.push_back(model.node_lateral_mass[k]);
    body.node_rotary_inertia.push_back(model.node_rotary_inertia[k].asDiagonal());
    body.node_translation_modes.push_back(u.middleRows<3>(fe::kDofPerNode * k));
    body.node_rotation_modes.push_back(u.middleRows<3>(fe::kDofPerNode * k + 3));
  }
}

// The structural continuum: m = ρAL, centre L/2, I_c = diag(ρJL, ρIL + mL²/12, same).
void FillStructuralInertia(const fe::BodySpec& spec, ReducedBody& body) {
  const double rho = spec.material.density, l = spec.length;
  body.total_mass = rho * spec.section.area() * l;
  body.center_of_mass = Vec3(0.5 * l, 0.0, 0.0);
  const double bending = rho * spec.section.second_moment() * l + body.total_mass * l * l / 12.0;
  body.inertia_about_center =
      Vec3(rho * spec.section.polar_moment() * l, bending, bending).asDiagonal();
}

}  // namespace

ReducedBody Reduce(const fe::BodyFeModel& model, const ReductionOptions& options) {
  if (!(options.structural_damping >= 0.0)) {
    throw InputError({}, "structural_damping", "the structural damping ratio must not be negative");
  }
  const std::vector<Index> nodes = InterfaceNodes(model, options);
  std::vector<Index> boundary;
  for (Index node : nodes) {
    for (Index d = 0; d < fe::kDofPerNode; ++d) boundary.push_back(fe::kDofPerNode * node + d);
  }
  const CraigBamptonBasis basis =
      BuildCraigBamptonBasis(model.stiffness, model.mass, boundary, options.modes_per_body);
  const MatX rigid_fields = fe::RigidBodyFields(model.node_x);
  Eigenpairs elastic = ElasticModes(basis, rigid_fields);
  MatX u = basis.transformation * elastic.vectors;  // step 6: U = T X
  AlignModes(elastic.eigenvalues, elastic.vectors, u);

  ReducedBody body;
  body.spec = model.spec;
  body.length = model.spec.length;
  body.fixed_interface_mode_count = basis.fixed_interface_eigenvalues.size();
  body.flexible_count = u.cols();
  body.interface_nodes = nodes;
  body.structural_damping = options.structural_damping;
  FillNodeData(model, u, body);
  FillStructuralInertia(model.spec, body);
  const VecX& lambda = elastic.eigenvalues;
  body.natural_frequencies = lambda.cwiseSqrt();
  body.modal_stiffness = lambda.asDiagonal();
  body.modal_damping = (2.0 * options.structural_damping * body.natural_frequencies).asDiagonal();
  const MatX mu = model.mass * u;
  body.modal_mass = u.transpose() * mu;
  body.modal_mass = 0.5 * (body.modal_mass + body.modal_mass.transpose()).eval();
  body.modal_geometric_stiffness = u.transpose() * (model.geometric_stiffness * u);
  body.modal_geometric_stiffness =
      0.5 * (body.modal_geometric_stiffness + body.modal_geometric_stiffness.transpose()).eval();
  body.modal_torque_geometric_stiffness = u.transpose() * (model.torque_geometric_stiffness * u);
  body.modal_torque_geometric_stiffness =
      0.5 * (body.modal_torque_geometric_stiffness + body.modal_torque_geometric_stiffness.transpose()).eval();
  const Index elements = model.node_count() - 1;
  body.element_modal_geometric_stiffness.reserve(elements);
  for (Index e = 0; e < elements; ++e) {
    const auto rows = u.middleRows(fe::kDofPerNode * e, 2 * fe::kDofPerNode);
    const MatX modal = rows.transpose() * model.element_geometric_stiffness * rows;
    body.element_modal_geometric_stiffness.push_back(0.5 * (modal + modal.transpose()));
  }
  // The turn about x (ReducedBody::twist_generator): S and E_⊥ act on each node's (u, v, w) and
  // (θx, θy, θz) alike.
  MatX turned = MatX::Zero(u.rows(), u.cols()), across = MatX::Zero(u.rows(), u.cols());
  for (Eigen::Index node = 0; node < u.rows() / fe::kDofPerNode; ++node) {
    for (const Eigen::Index first : {fe::kDofPerNode * node, fe::kDofPerNode * node + 3}) {
      turned.row(first + 1) = -u.row(first + 2);  // e_x × (a, b, c) = (0, −c, b)
      turned.row(first + 2) = u.row(first + 1);
      across.row(first + 1) = u.row(first + 1);
      across.row(first + 2) = u.row(first + 2);
    }
  }
  body.twist_generator = mu.transpose() * turned;
  body.transverse_projection = mu.transpose() * across;
  body.rigid_mass = rigid_fields.transpose() * (model.mass * rigid_fields);
  body.rigid_flexible_mass = rigid_fields.transpose() * mu;
  body.mode_shapes = std::move(u);
  return body;
}

ReducedBody Reduce(const fe::BodyFeModel& model, Index modes_per_body, double structural_damping) {
  ReductionOptions options;
  options.modes_per_body = modes_per_body;
  options.structural_damping = structural_damping;
  return Reduce(model, options);
}

}  // namespace drillflex::cms
