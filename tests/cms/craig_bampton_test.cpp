#include "cms/craig_bampton.hpp"
#include "../fe/v1_rod.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <cstdio>
#include <vector>

#include "../fe/fe_test_helpers.hpp"
#include "core/error.hpp"
#include "fe/body_fe_model.hpp"

namespace drillflex::cms {
namespace craig_bampton_test {

using fe::testing::LowestEigenvalues;
using fe::testing::Restrict;
using fe::testing::SelectDofs;

using fe::testing::V1Rod;

// λ = ω sqrt(m L⁴ / EI) of the V1 rod, m = ρA.
double Dimensionless(double omega, const fe::BodySpec& spec) {
  const double m = spec.material.density * spec.section.area();
  const double ei = spec.material.youngs_modulus * spec.section.second_moment();
  return omega * std::sqrt(m * std::pow(spec.length, 4) / ei);
}

double Rel(double value, double reference) {
  return std::abs(value - reference) / std::abs(reference);
}

// validation.md V1: one cantilever body (root clamped, the free tip the only interface) with k
// fixed-interface modes; frequencies converge from above; with a fine mesh, 2 modes give
// λ₁ ≈ 3.516221, λ₂ ≈ 22.05853 (exact 3.516015, 22.03449).
TEST(CraigBampton, V1CantileverConvergesFromAbove) {
  const fe::BodySpec spec = V1Rod(100);
  const fe::BodyFeModel model = fe::BuildBodyFeModel(spec);
  // Planar (x-y) model with the root node removed; the tip (v, θz) is the last two DOFs.
  const std::vector<Index> dofs = SelectDofs(1, 100, {1, 5});
  const MatX k = Restrict(MatX(model.stiffness), dofs), m = Restrict(MatX(model.mass), dofs);
  const int n = static_cast<int>(dofs.size());
  const std::vector<double> exact = {3.516015, 22.03449, 61.69721, 120.9019};
  std::vector<double> previous = {1e9, 1e9, 1e9, 1e9};
  for (int modes = 1; modes <= 6; ++modes) {
    const CraigBamptonBasis basis =
        BuildCraigBamptonBasis(k.sparseView(), m.sparseView(), {n - 2, n - 1}, modes);
    const int count = std::min(4, modes + 2);
    const VecX lambda = LowestEigenvalues(basis.reduced_stiffness, basis.reduced_mass, count);
    for (int j = 0; j < count; ++j) {
      const double value = Dimensionless(std::sqrt(lambda(j)), spec);
      EXPECT_GT(value, exact[j] * (1 - 1e-7)) << modes << " modes, frequency " << j + 1;
      EXPECT_LE(value, previous[j] * (1 + 1e-12)) << modes << " modes, frequency " << j + 1;
      previous[j] = value;
      std::printf("CB %d modes: lambda_%d = %.7f (exact %.7f)\n", modes, j + 1, value, exact[j]);
    }
    if (modes == 2) {
      EXPECT_LT(Rel(Dimensionless(std::sqrt(lambda(0)), spec), 3.516221), 3e-7);
      EXPECT_LT(Rel(Dimensionless(std::sqrt(lambda(1)), spec), 22.05853), 3e-7);
    }
  }
  // Six modes: about 1e-6 on the first, 3e-5 on the second (CB convergence is algebraic).
  EXPECT_LT(Rel(previous[0], exact[0]), 3e-6);
  EXPECT_LT(Rel(previous[1], exact[1]), 6e-5);
}

// The same in 3-D: a round section has equal y and z bending, so 4 fixed-interface modes are two
// planar modes per plane, and the pair is kept whole.
TEST(CraigBampton, DegeneratePairsAreKept) {
  const fe::BodySpec spec = V1Rod(40);
  const fe::BodyFeModel model = fe::BuildBodyFeModel(spec);
  const std::vector<Index> dofs = SelectDofs(1, 40, {0, 1, 2, 3, 4, 5});
  const MatX k = Restrict(MatX(model.stiffness), dofs), m = Restrict(MatX(model.mass), dofs);
  const int n = static_cast<int>(dofs.size());
  std::vector<Index> tip;
  for (int d = n - 6; d < n; ++d) tip.push_back(d);
  const CraigBamptonBasis basis = BuildCraigBamptonBasis(k.sparseView(), m.sparseView(), tip, 4);
  // Fixed-interface eigenvalues come in equal pairs.
  EXPECT_LT(Rel(basis.fixed_interface_eigenvalues(1), basis.fixed_interface_eigenvalues(0)), 1e-9);
  EXPECT_LT(Rel(basis.fixed_interface_eigenvalues(3), basis.fixed_interface_eigenvalues(2)), 1e-9);
  const VecX lambda = LowestEigenvalues(basis.reduced_stiffness, basis.reduced_mass, 4);
  for (int j : {0, 1}) EXPECT_LT(Rel(Dimensionless(std::sqrt(lambda(j)), spec), 3.516221), 3e-7);
  for (int j : {2, 3}) EXPECT_LT(Rel(Dimensionless(std::sqrt(lambda(j)), spec), 22.05853), 3e-7);
}

// A count that would cut an equal pair keeps both modes of it: asking 3 modes of the V1 rod (first
// bending pair, then the second) gives 4, a body bending alike in y and z, whose modes a turn
// about the axis maps onto themselves (J² = −P_⊥); a count that ends a pair is kept as asked.
TEST(CraigBampton, ACountCuttingAPairKeepsTheWholePair) {
  const fe::BodyFeModel model = fe::BuildBodyFeModel(V1Rod(10));
  for (const auto& [asked, kept] : {std::pair{1, 2}, std::pair{2, 2}, std::pair{3, 4}, std::pair{4, 4}}) {
    const ReducedBody body = Reduce(model, asked, 0.0);
    EXPECT_EQ(body.fixed_interface_mode_count, kept) << asked;
    EXPECT_EQ(body.flexible_count, 6 + kept) << asked;
    const MatX& j = body.twist_generator;
    EXPECT_LT((j * j + body.transverse_projection).norm(), 1e-9 * body.transverse_projection.norm()) << asked;
  }
}

// Solves K u = f with node 0 clamped (full FE model).
VecX ClampedStatic(const fe::BodyFeModel& model, const VecX& load) {
  const std::vector<Index> free = SelectDofs(1, model.node_count() - 1, {0, 1, 2, 3, 4, 5});
  const MatX k = Restrict(MatX(model.stiffness), free);
  VecX f(free.size());
  for (std::size_t i = 0; i < free.size(); ++i) f(i) = load(free[i]);
  const VecX u_free = k.ldlt().solve(f);
  VecX u = VecX::Zero(model.dof_count());
  for (std::size_t i = 0; i < free.size(); ++i) u(free[i]) = u_free(i);
  return u;
}

TEST(CraigBampton, ConstraintModesMakeEndLoadStaticsExact) {
  const fe::BodyFeModel model = fe::BuildBodyFeModel(V1Rod(10));
  std::vector<Index> boundary = SelectDofs(0, 0, {0, 1, 2, 3, 4, 5});
  for (int d = 60; d < 66; ++d) boundary.push_back(d);
  const CraigBamptonBasis basis = BuildCraigBamptonBasis(model.stiffness, model.mass, boundary, 4);
  VecX load = VecX::Zero(66);
  load.tail<6>() << 3.0e4, 1.0e3, -2.0e3, 500.0, 800.0, -300.0;  // tip forces and moments
  const VecX u_fe = ClampedStatic(model, load);
  // Reduced: the first 6 coordinates (node 0) clamped, the rest free.
  const int nc = static_cast<int>(basis.reduced_stiffness.cols());
  const MatX k_free = basis.reduced_stiffness.bottomRightCorner(nc - 6, nc - 6);
  const VecX f_free = (basis.transformation.transpose() * load).tail(nc - 6);
  VecX c = VecX::Zero(nc);
  c.tail(nc - 6) = k_free.ldlt().solve(f_free);
  const VecX u_cb = basis.transformation * c;
  EXPECT_LT((u_cb - u_fe).norm(), 1e-10 * u_fe.norm());
  // The same span is carried by the final floating-frame basis [R U].
  const ReducedBody body = Reduce(model, 4, 0.0);
  MatX ru(66, 6 + body.flexible_count);
  ru << fe::RigidBodyFields(model.node_x), body.mode_shapes;
  const VecX fit = ru.colPivHouseholderQr().solve(u_fe);
  EXPECT_LT((ru * fit - u_fe).norm(), 1e-9 * u_fe.norm());
  // A load at an interior node is not exact with 4 modes (the check above can fail).
  VecX mid_load = VecX::Zero(66);
  mid_load(6 * 5 + 1) = 1.0e3;
  const VecX u_mid = ClampedStatic(model, mid_load);
  const VecX mid_fit = ru.colPivHouseholderQr().solve(u_mid);
  EXPECT_GT((ru * mid_fit - u_mid).norm(), 1e-6 * u_mid.norm());
}

// modes_per_body: 0 (found by fuzz/case_file: Eigen's row() of the empty mode matrix offset a null
// pointer, undefined behaviour): the basis is the constraint modes alone, still exact for end loads.
TEST(CraigBampton, NoFixedInterfaceModesLeavesTheConstraintModes) {
  const fe::BodyFeModel model = fe::BuildBodyFeModel(V1Rod(10));
  std::vector<Index> boundary = SelectDofs(0, 0, {0, 1, 2, 3, 4, 5});
  for (int d = 60; d < 66; ++d) boundary.push_back(d);
  const CraigBamptonBasis basis = BuildCraigBamptonBasis(model.stiffness, model.mass, boundary, 0);
  ASSERT_EQ(basis.transformation.cols(), 12);
  VecX load = VecX::Zero(66);
  load.tail<6>() << 3.0e4, 1.0e3, -2.0e3, 500.0, 800.0, -300.0;
  const VecX u_fe = ClampedStatic(model, load);
  const MatX k_free = basis.reduced_stiffness.bottomRightCorner(6, 6);
  VecX c = VecX::Zero(12);
  c.tail(6) = k_free.ldlt().solve((basis.transformation.transpose() * load).tail(6));
  EXPECT_LT((basis.transformation * c - u_fe).norm(), 1e-10 * u_fe.norm());
  EXPECT_EQ(Reduce(model, 0, 0.0).flexible_count, 6);
}

// The reduced basis carries buckling: pinned-pinned Euler load π² EI / L² from
// K̄ φ = P K̄_G φ, K̄_G = Tᵀ K_G T, approached from above as modes are added (validation.md V2).
TEST(CraigBampton, ReducedBasisBucklesAtTheEulerLoad) {
  const fe::BodySpec spec = V1Rod(10);
  const fe::BodyFeModel model = fe::BuildBodyFeModel(spec);
  const double euler = kPi * kPi * spec.material.youngs_modulus * spec.section.second_moment() /
                       (spec.length * spec.length);
  std::vector<Index> boundary = SelectDofs(0, 0, {0, 1, 2, 3, 4, 5});
  for (int d = 60; d < 66; ++d) boundary.push_back(d);
  double previous = 1e300;
  for (int modes : {2, 6, 10}) {
    const CraigBamptonBasis basis =
        BuildCraigBamptonBasis(model.stiffness, model.mass, boundary, modes);
    const MatX kg =
        basis.transformation.transpose() * (model.geometric_stiffness * basis.transformation);
    // Pinned at node 0 (u, v, w, θx held) and at node 10 (v, w held): keep the other coordinates.
    std::vector<Index> kept = {4, 5, 6, 9, 10, 11};
    for (int j = 0; j < modes; ++j) kept.push_back(12 + j);
    const double p =
        LowestEigenvalues(Restrict(basis.reduced_stiffness, kept), Restrict(kg, kept), 1)(0);
    EXPECT_GT(p, euler * (1 - 1e-9)) << modes;
    EXPECT_LE(p, previous * (1 + 1e-12)) << modes;
    previous = p;
    std::printf("pinned-pinned buckling, H = %d: P/P_E - 1 = %.2e\n", modes, p / euler - 1);
  }
  EXPECT_LT(previous / euler - 1, 1e-4);
}

TEST(CraigBampton, ReducedBodyRemovesExactlyTheRigidMotion) {
  for (fe::MassKind kind : {fe::MassKind::kConsistent, fe::MassKind::kLumped}) {
    const fe::BodyFeModel model = fe::BuildBodyFeModel(V1Rod(10, kind, true));
    const ReducedBody body = Reduce(model, 12, 0.02);
    ASSERT_EQ(body.flexible_count, 18);
    const MatX& u = body.mode_shapes;
    const MatX k(model.stiffness), m(model.mass);
    const int nf = body.flexible_count;
    EXPECT_LT((u.transpose() * m * u - MatX::Identity(nf, nf)).norm(), 1e-10);
    EXPECT_LT((body.modal_mass - MatX::Identity(nf, nf)).norm(), 1e-10);
    const MatX kff = u.transpose() * k * u;
    EXPECT_LT((kff - body.modal_stiffness).norm(), 1e-9 * body.modal_stiffness.norm());
    // M-orthogonal to the 6 rigid fields (Tisserand frame), relative to √(rigid inertia).
    const MatX r = fe::RigidBodyFields(model.node_x);
    const MatX coupling = r.transpose() * m * u;
    for (int i = 0; i < 6; ++i) {
      EXPECT_LT(coupling.row(i).norm(), 1e-10 * std::sqrt(body.rigid_mass(i, i))) << i;
    }
    EXPECT_LT((coupling - body.rigid_flexible_mass).norm(), 1e-12 * body.rigid_mass.norm());
    // Frequencies ascending and positive; damping 2ζω.
    for (int j = 0; j < nf; ++j) {
      EXPECT_GT(body.natural_frequencies(j), 0.0);
      if (j > 0) {
        EXPECT_GE(body.natural_frequencies(j), body.natural_frequencies(j - 1));
      }
      EXPECT_NEAR(body.modal_damping(j, j), 0.04 * body.natural_frequencies(j),
                  1e-12 * body.natural_frequencies(j));
    }
    const MatX kg(model.geometric_stiffness);
    EXPECT_LT((u.transpose() * kg * u - body.modal_geometric_stiffness).norm(),
              1e-12 * body.modal_geometric_stiffness.norm());
  }
}

// Free-free Euler–Bernoulli beam: roots of cos x cosh x = 1 (β₁L = 4.7300408, …), by Newton.
double FreeFreeRoot(double guess) {
  double x = guess;
  for (int i = 0; i < 50; ++i) {
    const double f = std::cos(x) * std::cosh(x) - 1.0;
    x -= f / (-std::sin(x) * std::cosh(x) + std::cos(x) * std::sinh(x));
  }
  return x;
}

TEST(CraigBampton, FreeFreeFrequenciesFromAbove) {
  // 20 elements, H = 8 and 12 (4 and 6 bending modes per plane). The free-free reduced body's
  // elastic ω converge to the Euler–Bernoulli values from above (Rayleigh–Ritz on a consistent
  // mesh); an independent planar Craig–Bampton gives the same numbers.
  const fe::BodySpec spec = V1Rod(20);
  const fe::BodyFeModel model = fe::BuildBodyFeModel(spec);
  const std::vector<double> tables = {4.7300408, 7.8532046, 10.9956078};
  const std::vector<double> bound_h12 = {1.5e-4, 5e-4, 2e-3};
  std::vector<double> error_h8(3);
  for (int modes : {8, 12}) {
    const ReducedBody body = Reduce(model, modes, 0.0);
    for (int n = 0; n < 3; ++n) {
      const double beta_l = FreeFreeRoot(tables[n]);
      ASSERT_NEAR(beta_l, tables[n], 1e-6);
      const double exact = beta_l * beta_l;  // λ = (βL)²
      // Bending comes in y/z pairs: modes 2n and 2n+1.
      for (int j : {2 * n, 2 * n + 1}) {
        const double value = Dimensionless(body.natural_frequencies(j), spec);
        const double error = value / exact - 1.0;
        EXPECT_GT(error, -1e-9) << "H = " << modes << ", mode " << j;
        if (modes == 8) error_h8[n] = error;
        if (modes == 12) {
          EXPECT_LT(error, bound_h12[n]) << "mode " << j;
          EXPECT_LT(error, 0.5 * error_h8[n]) << "mode " << j;
        }
        std::printf("free-free H=%d mode %d: lambda = %.7f, exact %.7f, error %.2e\n", modes, j,
                    value, exact, error);
      }
    }
  }
}

TEST(CraigBampton, PairsAreAlignedWithTheBendingPlanes) {
  const ReducedBody body = Reduce(fe::BuildBodyFeModel(V1Rod(10)), 12, 0.0);
  for (int j : {0, 2}) {  // the first two bending pairs
    double v_first = 0, w_first = 0, v_second = 0, w_second = 0;
    for (int k = 0; k < body.node_count(); ++k) {
      v_first += std::pow(body.node_translation_modes[k](1, j), 2);
      w_first += std::pow(body.node_translation_modes[k](2, j), 2);
      v_second += std::pow(body.node_translation_modes[k](1, j + 1), 2);
      w_second += std::pow(body.node_translation_modes[k](2, j + 1), 2);
    }
    EXPECT_LT(w_first, 1e-20 * v_first) << j;
    EXPECT_LT(v_second, 1e-20 * w_second) << j;
  }
}

TEST(CraigBampton, MoreInterfaceNodes) {
  const fe::BodyFeModel model = fe::BuildBodyFeModel(V1Rod(10));
  ReductionOptions options;
  options.modes_per_body = 6;
  options.interface_nodes = {10, 0, 5};
  const ReducedBody body = Reduce(model, options);
  // The two equal spans between the interface nodes have equal fixed-interface modes, each bending
  // one fourfold (y and z, either span): the 6 asked are completed to 8.
  EXPECT_EQ(body.fixed_interface_mode_count, 8);
  EXPECT_EQ(body.flexible_count, 3 * 6 - 6 + 8);
  EXPECT_EQ(body.interface_nodes, (std::vector<Index>{0, 5, 10}));
  const MatX m(model.mass);
  EXPECT_LT((body.mode_shapes.transpose() * m * body.mode_shapes - MatX::Identity(20, 20)).norm(),
            1e-10);
}

TEST(CraigBampton, TimoshenkoLumpedWithoutRotaryInertiaStillReduces) {
  // A lumped mass without bending rotary inertia is singular: the stiffness-Cholesky eigen form
  // copes. Timoshenko thick collar.
  fe::BodySpec spec = V1Rod(10, fe::MassKind::kLumped, false);
  spec.section = {0.2032, 0.0714375};
  spec.length = 2.0;
  spec.options.beam = fe::BeamTheory::kTimoshenko;
  const ReducedBody body = Reduce(fe::BuildBodyFeModel(spec), 8, 0.0);
  EXPECT_EQ(body.flexible_count, 14);
  EXPECT_LT((body.modal_mass - MatX::Identity(14, 14)).norm(), 1e-10);
}

TEST(CraigBampton, RejectsBadInputAndBrokenModels) {
  const fe::BodyFeModel model = fe::BuildBodyFeModel(V1Rod(4));
  EXPECT_THROW(Reduce(model, 19, 0.0), InputError);  // only 3 × 6 = 18 internal DOFs
  EXPECT_NO_THROW(Reduce(model, 18, 0.0));
  EXPECT_THROW(Reduce(model, -1, 0.0), InputError);
  EXPECT_THROW(Reduce(model, 4, -0.1), InputError);
  ReductionOptions options;
  options.interface_nodes = {0, 7};
  EXPECT_THROW(Reduce(model, options), InputError);
  // A grounding spring: the rigid motions store energy.
  fe::BodyFeModel grounded = model;
  grounded.stiffness.coeffRef(6 * 4 + 2, 6 * 4 + 2) += 1.0e6;  // w of the last node
  EXPECT_THROW(Reduce(grounded, 4, 0.0), LogicError);
  // No torsional stiffness at all: the interior twists freely (a mechanism).
  fe::BodyFeModel loose = model;
  for (int k = 0; k < loose.node_count(); ++k) {
    for (int j = 0; j < loose.node_count(); ++j) {
      loose.stiffness.coeffRef(6 * k + 3, 6 * j + 3) = 0.0;
    }
  }
  EXPECT_THROW(Reduce(loose, 4, 0.0), LogicError);
}

}  // namespace craig_bampton_test
}  // namespace drillflex::cms
