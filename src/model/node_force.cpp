// Generalized force of a motion-dependent nodal force and moment (see node_force.hpp for the
// formulas). With the body-frame node Jacobian
//   N_b = [Aᵀ, −ũ_k, Φ_k; 0, I, Ψ_k]   (6 × n; [L_k; G_k] = diag(A, A) N_b)
// and the body-frame derivatives X' = Aᵀ X A stacked as C'_r = [F'_r; M'_r] (6 × 3), etc.:
//   Bᵀ ∂(F, M)/∂q = N_bᵀ (C'_r N_b,top + [0 | −C'_v skew(ω × u_k + Φη̇) − C'_w skew(ω + Ψη̇) | C'_v ω̃ Φ]),
//   Bᵀ ∂(F, M)/∂v = N_bᵀ (C'_v N_b,top + C'_w N_b,bot).
// Every block is a product of an n × 3 factor N_bᵀ C' with a 3 × m right factor, so the modal
// columns cost 3 n n_f (stiffness) and 6 n n_f (damping) multiply-adds, computed column by column
// of the result (contiguous, vectorized). AddPointForce needs one left factor less for the damping
// (L_ℓᵀ only: 3 n² multiply-adds).
#include "model/node_force.hpp"

#include "core/so3.hpp"

namespace drillflex::model {
namespace {

using so3::Skew;
using Factor = Eigen::Matrix<double, Eigen::Dynamic, 3>;  // n × 3

// Per-thread scratch (sized once, then reused: no allocation per evaluation; thread-local, so
// concurrent evaluations do not share it).
struct Scratch {
  Eigen::Matrix<double, Eigen::Dynamic, 6> jacobian_t;  // N_bᵀ
  Factor position, velocity, angular_velocity, work;
  Factor bottom, lever;                                 // AddPointForce's Ψᵀ and L_ℓᵀ
  cms::Matrix3X right_full;                             // 3 × n
};

Scratch& ThreadScratch(Index size) {
  thread_local Scratch scratch;
  scratch.jacobian_t.resize(size, 6);
  for (Factor* f : {&scratch.position, &scratch.velocity, &scratch.angular_velocity, &scratch.work, &scratch.lever}) {
    f->resize(size, 3);
  }
  scratch.right_full.resize(3, size);
  return scratch;
}

// N_bᵀ: rows δr = [A, 0], δθ = [ũ_k, I], δη = [Φ_kᵀ, Ψ_kᵀ].
void FillJacobianTranspose(const Mat3& A, const Mat3& skew_offset, const cms::Matrix3X& phi, const cms::Matrix3X& psi,
                           Eigen::Matrix<double, Eigen::Dynamic, 6>& jt) {
  const Index nf = phi.cols();
  jt.block<3, 3>(0, 0) = A;
  jt.block<3, 3>(0, 3).setZero();
  jt.block<3, 3>(3, 0) = skew_offset;
  jt.block<3, 3>(3, 3).setIdentity();
  jt.block(6, 0, nf, 3) = phi.transpose();
  jt.block(6, 3, nf, 3) = psi.transpose();
}

// N_bᵀ [X'_F; X'_M] for a pair of global 3 × 3 blocks (X' = Aᵀ X A).
void FillFactor(const Mat3& A, const Eigen::Matrix<double, Eigen::Dynamic, 6>& jt, const Mat3& force_block,
                const Mat3& moment_block, Factor& factor) {
  Eigen::Matrix<double, 6, 3> body;
  body.topRows<3>().noalias() = A.transpose() * force_block * A;
  body.bottomRows<3>().noalias() = A.transpose() * moment_block * A;
  factor.noalias() = jt.lazyProduct(body);
}

// out(r0.., c0..) −= a b for a (rows × 3, contiguous columns) and b (3 × m): one pass over each
// destination column (contiguous), the three columns of a combined; plain loops that the compiler
// vectorizes (Eigen's small dynamic products are several times slower here).
template <typename Right>
void SubtractProduct(MatX& out, Index r0, Index c0, const Factor& a, const Right& b) {
  const Eigen::Index rows = a.rows(), ld = out.outerStride();
  const double* __restrict a0 = a.data();
  const double* __restrict a1 = a0 + rows;
  const double* __restrict a2 = a1 + rows;
  for (Eigen::Index j = 0; j < b.cols(); ++j) {
    double* __restrict d = out.data() + r0 + (c0 + j) * ld;
    const double b0 = b(0, j), b1 = b(1, j), b2 = b(2, j);
    for (Eigen::Index i = 0; i < rows; ++i) d[i] -= a0[i] * b0 + a1[i] * b1 + a2[i] * b2;
  }
}

// out = a b or (Accumulate) out += a b, a and out n × 3, b 3 × 3 (plain vectorizable
// loops: Eigen sends these shapes to its general product, whose setup dominates at this size).
template <bool Accumulate>
void MultiplyFactor(const Factor& a, const Mat3& b, Factor& out) {
  const Eigen::Index rows = a.rows();
  const double* __restrict a0 = a.data();
  const double* __restrict a1 = a0 + rows;
  const double* __restrict a2 = a1 + rows;
  for (Index j = 0; j < 3; ++j) {
    double* __restrict d = out.data() + j * rows;
    const double b0 = b(0, j), b1 = b(1, j), b2 = b(2, j);
    for (Eigen::Index i = 0; i < rows; ++i) {
      const double product = a0[i] * b0 + a1[i] * b1 + a2[i] * b2;
      d[i] = Accumulate ? d[i] + product : product;
    }
  }
}

// The modal rows of out (its last modes.rows() rows) += scale · modes · b (modes n_f × 3).
void AddModalRows(const Factor& modes, const Mat3& b, double scale, Factor& out) {
  const Eigen::Index nf = modes.rows();
  for (Index j = 0; j < 3; ++j) {
    out.col(j).tail(nf) += scale * (modes.col(0) * b(0, j) + modes.col(1) * b(1, j) + modes.col(2) * b(2, j));
  }
}

}  // namespace

void AddNodeForce(const Body& body, const BodyPose& pose, Index node, const NodeMotion& motion, const Vec3& force,
                  const Vec3& moment, const NodeForceJacobian* jacobian, bool with_matrices,
                  ElementContribution& out, Index offset) {
  const Index nf = body.flexible_count;
  const auto& phi = body.reduced->node_translation_modes[node];
  const auto& psi = body.reduced->node_rotation_modes[node];
  const Vec3 force_body = pose.A.transpose() * force;
  const Vec3 moment_body = pose.A.transpose() * moment;
  // −Q = −[F; u_k × AᵀF + AᵀM; Φ_kᵀ AᵀF + Ψ_kᵀ AᵀM].
  out.force.segment<3>(offset) -= force;
  out.force.segment<3>(offset + 3) -= motion.offset.cross(force_body) + moment_body;
  out.force.segment(offset + 6, nf).noalias() -= phi.transpose() * force_body;
  out.force.segment(offset + 6, nf).noalias() -= psi.transpose() * moment_body;
  if (!with_matrices) return;
  const Index n = body.velocity_count();
  const Mat3& A = pose.A;
  const Mat3 skew_offset = Skew(motion.offset);
  const Mat3 skew_force = Skew(force_body), skew_moment = Skew(moment_body);
  auto K = out.stiffness.block(offset, offset, n, n);
  if (jacobian == nullptr) {
    // Geometric part only (δ(AᵀF) = skew(AᵀF) δθ, δu_k = Φ_k δη), as in model/nodal_loads.cpp.
    K.block<3, 3>(3, 3) -= skew_offset * skew_force + skew_moment;
    K.block(3, 6, 3, nf).noalias() += skew_force * phi;
    K.block(6, 3, nf, 3).noalias() -= phi.transpose() * skew_force;
    K.block(6, 3, nf, 3).noalias() -= psi.transpose() * skew_moment;
    return;
  }
  const NodeForceJacobian& J = *jacobian;
  Scratch& s = ThreadScratch(n);
  FillJacobianTranspose(A, skew_offset, phi, psi, s.jacobian_t);
  FillFactor(A, s.jacobian_t, J.force_position, J.moment_position, s.position);
  FillFactor(A, s.jacobian_t, J.force_velocity, J.moment_velocity, s.velocity);
  FillFactor(A, s.jacobian_t, J.force_angular_velocity, J.moment_angular_velocity, s.angular_velocity);
  // Stiffness. δr columns: N_bᵀ C'_r Aᵀ.
  K.leftCols<3>().noalias() -= s.position.lazyProduct(A.transpose());
  // δθ columns: −N_bᵀ (C'_r ũ + C'_v skew(ω × u_k + Φη̇) + C'_w skew(ω + Ψη̇)), plus the geometric part.
  s.work.noalias() = s.position.lazyProduct(skew_offset);
  s.work.noalias() += s.velocity.lazyProduct(Skew(motion.relative_velocity));
  s.work.noalias() += s.angular_velocity.lazyProduct(Skew(motion.node_rate));
  K.middleCols<3>(3) += s.work;
  K.block<3, 3>(3, 3) -= skew_offset * skew_force + skew_moment;
  K.block(6, 3, nf, 3).noalias() -= s.jacobian_t.bottomRows(nf).leftCols<3>().lazyProduct(skew_force);
  K.block(6, 3, nf, 3).noalias() -= s.jacobian_t.bottomRows(nf).rightCols<3>().lazyProduct(skew_moment);
  // δη columns: N_bᵀ (C'_r + C'_v ω̃) Φ, plus the geometric −skew(AᵀF) Φ in the δθ rows.
  s.work.noalias() = s.velocity.lazyProduct(Skew(motion.body_rate));
  s.work += s.position;
  SubtractProduct(out.stiffness, offset, offset + 6, s.work, phi);
  K.block(3, 6, 3, nf).noalias() += skew_force * phi;
  // Damping: N_bᵀ C'_v [Aᵀ, −ũ, Φ] + N_bᵀ C'_w [0, I, Ψ].
  auto D = out.damping.block(offset, offset, n, n);
  D.leftCols<3>().noalias() -= s.velocity.lazyProduct(A.transpose());
  D.middleCols<3>(3).noalias() += s.velocity.lazyProduct(skew_offset);
  D.middleCols<3>(3) -= s.angular_velocity;
  SubtractProduct(out.damping, offset, offset + 6, s.velocity, phi);
  SubtractProduct(out.damping, offset, offset + 6, s.angular_velocity, psi);
}

namespace {

// The matrices of AddPointForce (formulas in node_force.hpp; body-frame factors as above).
void SubtractPointForceMatrices(const Body& body, const BodyPose& pose, Index node, const NodeMotion& motion,
                                const Vec3& f, const Vec3& l, const PointForceJacobian& J, ElementContribution& out,
                                Index o) {
  const Index nf = body.flexible_count;
  const auto& phi = body.reduced->node_translation_modes[node];
  const auto& psi = body.reduced->node_rotation_modes[node];
  const Mat3& A = pose.A;
  const Mat3 At = A.transpose();
  const Mat3 su = Skew(motion.offset), sl = Skew(l), sf = Skew(f), sm = Skew(l.cross(f));
  Scratch& s = ThreadScratch(body.velocity_count());
  // Left factors (n × 3): the lever point's L_ℓᵀ = N_b,topᵀ + N_b,botᵀ ℓ̃ = [A; ũ + ℓ̃; Φᵀ + Ψᵀ ℓ̃]
  // (ℓ in the body frame), with N_b,topᵀ = [A; ũ; Φᵀ] and N_b,botᵀ = [0; I; Ψᵀ] (Ψᵀ kept n_f × 3).
  Factor &lt = s.lever, &psi_t = s.bottom;
  psi_t.resize(nf, 3);
  psi_t = psi.transpose();
  lt.topRows<3>() = A;
  lt.middleRows<3>(3) = su + sl;
  lt.bottomRows(nf) = phi.transpose();
  AddModalRows(psi_t, sl, 1.0, lt);
  const Mat3 fx = At * J.force_position * A, fv = At * J.force_velocity * A;
  const Mat3 fw = At * J.force_angular_velocity * A;
  const Mat3 w = sf * (At * J.lever_position * A);  // skew(AᵀF) ∂ℓ'/∂x' (body frame)
  // Stiffness −P N_b,top − L_ℓᵀ E − H, with P = L_ℓᵀ F'_r − N_b,botᵀ W (W: the lever's motion),
  // E = [0 | −F'_v skew(ω × u_k + Φη̇) − F'_w skew(ω + Ψη̇) | F'_v ω̃ Φ] and the geometric part
  // H[:, δθ] = N_b,topᵀ skew(f) + N_b,botᵀ skew(m) − [A skew(f); 0; 0]
  //          = L_ℓᵀ skew(f) + N_b,botᵀ (skew(m) − ℓ̃ skew(f)) − [A skew(f); 0; 0],
  // H[δθ, δη] = −skew(f) Φ.
  Factor& P = s.position;
  MultiplyFactor<false>(lt, fx, P);
  P.middleRows<3>(3) -= w;
  AddModalRows(psi_t, w, -1.0, P);
  SubtractProduct(out.stiffness, o, o, P, At);
  Mat3 lever_theta = sf;
  if (!motion.relative_velocity.isZero(0.0) || !motion.node_rate.isZero(0.0)) {
    lever_theta -= fv * Skew(motion.relative_velocity) + fw * Skew(motion.node_rate);
  }
  SubtractProduct(out.stiffness, o, o + 3, P, Mat3(-su));
  SubtractProduct(out.stiffness, o, o + 3, lt, lever_theta);
  const Mat3 rotation_theta = sm - sl * sf;
  out.stiffness.block<3, 3>(o + 3, o + 3) -= rotation_theta;
  out.stiffness.block(o + 6, o + 3, nf, 3).noalias() -= psi_t * rotation_theta;
  out.stiffness.block<3, 3>(o, o + 3).noalias() += A * sf;
  const Factor* modal_left = &P;
  if (!motion.body_rate.isZero(0.0)) {
    s.work = P;
    MultiplyFactor<true>(lt, fv * Skew(motion.body_rate), s.work);
    modal_left = &s.work;
  }
  SubtractProduct(out.stiffness, o, o + 6, *modal_left, phi);
  out.stiffness.block(o + 3, o + 6, 3, nf).noalias() += sf * phi;
  // Damping −L_ℓᵀ (F'_v N_b,top + F'_w N_b,bot) = −L_ℓᵀ [F'_v Aᵀ, F'_w − F'_v ũ, F'_v Φ + F'_w Ψ].
  s.right_full.leftCols<3>().noalias() = fv * At;
  s.right_full.middleCols<3>(3).noalias() = fw - fv * su;
  s.right_full.rightCols(nf).noalias() = fv * phi;
  s.right_full.rightCols(nf).noalias() += fw * psi;
  SubtractProduct(out.damping, o, o, lt, s.right_full);
}

}  // namespace

void AddPointForce(const Body& body, const BodyPose& pose, Index node, const NodeMotion& motion, const Vec3& force,
                   const Vec3& lever, const PointForceJacobian* jacobian, bool with_matrices,
                   ElementContribution& out, Index offset) {
  if (jacobian == nullptr) {
    AddNodeForce(body, pose, node, motion, force, lever.cross(force), nullptr, with_matrices, out, offset);
    return;
  }
  const Index nf = body.flexible_count;
  const auto& phi = body.reduced->node_translation_modes[node];
  const auto& psi = body.reduced->node_rotation_modes[node];
  const Vec3 f = pose.A.transpose() * force, l = pose.A.transpose() * lever;
  // −Q = −L_ℓᵀ F = −[F; (u_k + ℓ) × AᵀF; Φᵀ AᵀF + Ψᵀ (ℓ × AᵀF)] (ℓ in the body frame).
  out.force.segment<3>(offset) -= force;
  out.force.segment<3>(offset + 3) -= (motion.offset + l).cross(f);
  out.force.segment(offset + 6, nf).noalias() -= phi.transpose() * f;
  out.force.segment(offset + 6, nf).noalias() -= psi.transpose() * l.cross(f);
  if (with_matrices) SubtractPointForceMatrices(body, pose, node, motion, f, l, *jacobian, out, offset);
}

}  // namespace drillflex::model
