#include "fe/body_fe_model.hpp"
#include "v1_rod.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "core/error.hpp"
#include "fe_test_helpers.hpp"

namespace drillflex::fe {
namespace body_fe_model_test {

using testing::LowestEigenvalues;
using testing::Restrict;
using testing::SelectDofs;

using fe::testing::V1Rod;

double Rel(double value, double reference) {
  return std::abs(value - reference) / std::abs(reference);
}

TEST(BodyFeModel, SizesNodesAndLumpedNodalData) {
  BodySpec spec = V1Rod(8, MassKind::kConsistent, true);
  spec.options.internal_fluid_mass_per_length = 3.0;
  spec.options.added_lateral_mass_per_length = 5.0;
  const BodyFeModel model = BuildBodyFeModel(spec);
  ASSERT_EQ(model.node_count(), 9);
  EXPECT_EQ(model.stiffness.rows(), 54);
  EXPECT_EQ(model.mass.cols(), 54);
  EXPECT_EQ(model.node_x.front(), 0.0);
  EXPECT_EQ(model.node_x.back(), 5.08);
  EXPECT_NEAR(model.node_x[4], 2.54, 1e-15);
  const double rho_a = 7800.0 * spec.section.area();
  double mass = 0, lateral = 0, torsion = 0;
  for (int k = 0; k < model.node_count(); ++k) {
    mass += model.node_mass[k];
    lateral += model.node_lateral_mass[k];
    torsion += model.node_rotary_inertia[k].x();
  }
  EXPECT_LT(Rel(mass, rho_a * 5.08), 1e-14);
  EXPECT_LT(Rel(lateral, 8.0 * 5.08), 1e-14);
  EXPECT_LT(Rel(torsion, 7800.0 * spec.section.polar_moment() * 5.08), 1e-14);
  // End nodes carry half of an element, inner nodes a whole one.
  EXPECT_LT(Rel(model.node_mass[0], rho_a * 5.08 / 16), 1e-14);
  EXPECT_LT(Rel(model.node_mass[3], rho_a * 5.08 / 8), 1e-14);
}

TEST(BodyFeModel, RigidBodyInertiaOfTheAssembledMass) {
  for (MassKind kind : {MassKind::kConsistent, MassKind::kLumped}) {
    BodySpec spec = V1Rod(10, kind, true);
    spec.options.added_lateral_mass_per_length = 4.0;
    const BodyFeModel model = BuildBodyFeModel(spec);
    const MatX r = RigidBodyFields(model.node_x);
    const MatX m(model.mass);
    const MatX rigid = r.transpose() * m * r;
    const double structural = 7800.0 * spec.section.area() * spec.length;
    const double lateral = structural + 4.0 * spec.length;
    EXPECT_LT(Rel(rigid(0, 0), structural), 1e-13);
    EXPECT_LT(Rel(rigid(1, 1), lateral), 1e-13);
    EXPECT_LT(Rel(rigid(2, 2), lateral), 1e-13);
    // First moment ∫ μ x dx = μ L²/2 (exact for both masses: nodes are evenly spaced).
    EXPECT_LT(Rel(rigid(1, 5), lateral * spec.length / 2), 1e-13);
    if (kind == MassKind::kConsistent) {
      // Second moment about the origin μ L³/3 + ρ I L: exact with the cubic interpolation.
      const double expected = lateral * spec.length * spec.length / 3.0 +
                              7800.0 * spec.section.second_moment() * spec.length;
      EXPECT_LT(Rel(rigid(5, 5), expected), 1e-13);
    } else {
      // Lumped nodal data and the lumped matrix agree entry by entry.
      for (int k = 0; k < model.node_count(); ++k) {
        EXPECT_DOUBLE_EQ(m(6 * k, 6 * k), model.node_mass[k]);
        EXPECT_DOUBLE_EQ(m(6 * k + 2, 6 * k + 2), model.node_mass[k] + model.node_lateral_mass[k]);
        EXPECT_DOUBLE_EQ(m(6 * k + 4, 6 * k + 4), model.node_rotary_inertia[k].y());
      }
    }
  }
}

// Planar (x-y) cantilever bending frequencies, root clamped: λ of K x = ω² M x.
VecX CantileverOmegaSquared(const BodySpec& spec, int count) {
  const BodyFeModel model = BuildBodyFeModel(spec);
  const std::vector<Index> dofs = SelectDofs(1, spec.element_count, {1, 5});
  return LowestEigenvalues(Restrict(MatX(model.stiffness), dofs), Restrict(MatX(model.mass), dofs),
                           count);
}

// Root of the cantilever frequency equation 1 + cos x cosh x = 0 near a tabulated β_n L, by
// Newton's method (the tables' 8 digits are not enough to see convergence from above).
double CantileverRoot(double guess) {
  double x = guess;
  for (int i = 0; i < 50; ++i) {
    const double f = 1.0 + std::cos(x) * std::cosh(x);
    const double df = -std::sin(x) * std::cosh(x) + std::cos(x) * std::sinh(x);
    x -= f / df;
  }
  return x;
}

// Euler–Bernoulli cantilever: ω_n = (β_n L)² / L² · sqrt(EI / (ρA)).
std::vector<double> ExactCantileverOmega(const BodySpec& spec) {
  std::vector<double> beta_l;
  for (double table : {1.8751041, 4.6940911, 7.8547574, 10.995541}) {
    beta_l.push_back(CantileverRoot(table));
    EXPECT_NEAR(beta_l.back(), table, 1e-6);
  }
  const double c = std::sqrt(spec.material.youngs_modulus * spec.section.second_moment() /
                             (spec.material.density * spec.section.area()));
  std::vector<double> omega;
  for (double b : beta_l) omega.push_back(b * b / (spec.length * spec.length) * c);
  return omega;
}

TEST(BodyFeModel, ConsistentMassFrequenciesConvergeFromAbove) {
  const std::vector<double> exact = ExactCantileverOmega(V1Rod(1, MassKind::kConsistent));
  std::vector<double> previous_error(4, 1.0);
  for (int elements : {4, 8, 16, 32}) {
    const VecX lambda = CantileverOmegaSquared(V1Rod(elements, MassKind::kConsistent), 4);
    for (int n = 0; n < 4; ++n) {
      const double error = std::sqrt(lambda(n)) / exact[n] - 1.0;
      // From above (Rayleigh–Ritz with conforming cubics), up to round-off.
      EXPECT_GT(error, -1e-11) << elements << " elements, mode " << n + 1;
      // Halving h divides the error by 2⁴ = 16 (cubic elements): allow 12…20 once asymptotic.
      if (elements >= 16) {
        EXPECT_GT(previous_error[n] / error, 12.0) << elements << " elements, mode " << n + 1;
        EXPECT_LT(previous_error[n] / error, 20.0) << elements << " elements, mode " << n + 1;
      }
      EXPECT_LT(error, previous_error[n]) << elements << " elements, mode " << n + 1;
      previous_error[n] = error;
      std::printf("consistent %2d elements mode %d: relative error %.3e\n", elements, n + 1, error);
    }
  }
  // 32 elements: O(h⁴) convergence leaves ~1e-5 on the fourth mode, ~1e-8 on the first.
  EXPECT_LT(previous_error[3], 1.5e-5);
  EXPECT_LT(previous_error[0], 1.5e-8);
}

TEST(BodyFeModel, LumpedMassFrequenciesConvergeToo) {
  const std::vector<double> exact = ExactCantileverOmega(V1Rod(1, MassKind::kLumped));
  std::vector<double> previous_error(4, 1.0);
  for (int elements : {8, 16, 32, 64}) {
    const VecX lambda = CantileverOmegaSquared(V1Rod(elements, MassKind::kLumped), 4);
    for (int n = 0; n < 4; ++n) {
      const double error = std::abs(std::sqrt(lambda(n)) / exact[n] - 1.0);
      // Lumped mass: O(h²), halving h divides the error by about 4.
      if (elements >= 16) {
        EXPECT_GT(previous_error[n] / error, 3.5) << elements << " elements, mode " << n + 1;
        EXPECT_LT(previous_error[n] / error, 4.5) << elements << " elements, mode " << n + 1;
      }
      EXPECT_LT(error, previous_error[n]) << elements << " elements, mode " << n + 1;
      previous_error[n] = error;
      std::printf("lumped %2d elements mode %d: relative error %.3e\n", elements, n + 1, error);
    }
  }
  // Lumped mass converges as O(h²): 64 elements still leave ~1e-3 on the fourth mode.
  EXPECT_LT(previous_error[0], 1.5e-4);
  EXPECT_LT(previous_error[3], 1.2e-3);
}

TEST(BodyFeModel, RotaryInertiaLowersBendingFrequencies) {
  const VecX rayleigh = CantileverOmegaSquared(V1Rod(32, MassKind::kConsistent, true), 4);
  const VecX euler = CantileverOmegaSquared(V1Rod(32, MassKind::kConsistent, false), 4);
  for (int n = 0; n < 4; ++n) EXPECT_LT(rayleigh(n), euler(n));
  // Rayleigh beam: the correction grows like (β_n r)², r = D/4 the radius of gyration:
  // (β₄ r)² = (10.9955 · 0.01905 / 5.08)² = 1.7e-3, and ω drops by a fraction of that.
  const double drop = 1.0 - std::sqrt(rayleigh(3) / euler(3));
  EXPECT_GT(drop, 1e-4);
  EXPECT_LT(drop, 1.7e-3);
}

// Lowest critical load P (compression) of K φ = P K_G φ on the kept DOFs (x-y plane).
double CriticalLoad(const BodySpec& spec, const std::vector<Index>& dofs) {
  const BodyFeModel model = BuildBodyFeModel(spec);
  return LowestEigenvalues(Restrict(MatX(model.stiffness), dofs),
                           Restrict(MatX(model.geometric_stiffness), dofs), 1)(0);
}

TEST(BodyFeModel, EulerBucklingLoads) {
  const BodySpec spec = V1Rod(20, MassKind::kConsistent);
  const double ei = spec.material.youngs_modulus * spec.section.second_moment();
  const double l = spec.length;
  const double pi2 = kPi * kPi;
  // Pinned-pinned (v = 0 at both ends; θz free): π² EI / L².
  std::vector<Index> pinned = SelectDofs(1, 19, {1, 5});
  pinned.insert(pinned.begin(), 5);
  pinned.push_back(6 * 20 + 5);
  EXPECT_LT(Rel(CriticalLoad(spec, pinned), pi2 * ei / (l * l)), 1e-3);
  // Clamped-free: π² EI / (4 L²).
  EXPECT_LT(Rel(CriticalLoad(spec, SelectDofs(1, 20, {1, 5})), pi2 * ei / (4 * l * l)), 1e-3);
  // Clamped-clamped: 4 π² EI / L².
  EXPECT_LT(Rel(CriticalLoad(spec, SelectDofs(1, 19, {1, 5})), 4 * pi2 * ei / (l * l)), 1e-3);
}

TEST(BodyFeModel, TimoshenkoBucklingFollowsEngesser) {
  // A short thick collar: the geometric stiffness ∫ N (v')² dx with shear flexibility gives
  // Engesser's P = P_E / (1 + P_E/(κGA)).
  BodySpec spec;
  spec.section = {0.2032, 0.0714375};
  spec.material = {"steel", 2.1e11, 0.3, 7850.0};
  spec.length = 1.2;
  spec.element_count = 20;
  spec.options.beam = BeamTheory::kTimoshenko;
  const double p_euler = kPi * kPi * 2.1e11 * spec.section.second_moment() / (1.2 * 1.2);
  const double kga =
      spec.section.shear_coefficient(0.3) * spec.material.shear_modulus() * spec.section.area();
  ASSERT_GT(p_euler / kga, 0.05);
  std::vector<Index> pinned = SelectDofs(1, 19, {1, 5});
  pinned.insert(pinned.begin(), 5);
  pinned.push_back(6 * 20 + 5);
  EXPECT_LT(Rel(CriticalLoad(spec, pinned), p_euler / (1 + p_euler / kga)), 1e-3);
}

TEST(BodyFeModel, LargeMeshIsCheapToBuild) {
  const BodyFeModel model = BuildBodyFeModel(V1Rod(1000, MassKind::kConsistent));
  EXPECT_EQ(model.dof_count(), 6006);
  // Banded: at most 12 × 12 coupling per element pair, far from dense.
  EXPECT_LT(model.stiffness.nonZeros(), 1000 * 144);
  const MatX r = RigidBodyFields(model.node_x);
  const VecX ones = r.col(1);
  EXPECT_LT(Rel(ones.dot(model.mass * ones),
                7800.0 * BodySpec{V1Rod(1, MassKind::kLumped)}.section.area() * 5.08),
            1e-12);
  EXPECT_LT((model.stiffness * r).norm(), 1e-6 * model.stiffness.norm());
}

TEST(BodyFeModel, RejectsBadInput) {
  BodySpec spec = V1Rod(0, MassKind::kConsistent);
  EXPECT_THROW(BuildBodyFeModel(spec), InputError);
  spec = V1Rod(4, MassKind::kConsistent);
  spec.length = -1.0;
  EXPECT_THROW(BuildBodyFeModel(spec), InputError);
  spec = V1Rod(4, MassKind::kConsistent);
  spec.options.added_lateral_mass_per_length = -1.0;
  EXPECT_THROW(BuildBodyFeModel(spec), InputError);
}

}  // namespace body_fe_model_test
}  // namespace drillflex::fe
