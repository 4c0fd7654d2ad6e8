#include "fe/beam_element.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <array>
#include <cmath>

#include "core/types.hpp"
#include "core/dense_eigen.hpp"

namespace drillflex::fe {
namespace beam_element_test {

// A thick steel collar element (Timoshenko shear is visible): 8 in × 2.8125 in, 0.5 m long.
BeamElementProperties Collar(double length = 0.5) {
  return MakeElementProperties(HollowSection{0.2032, 0.0714375},
                               Material{"steel", 2.1e11, 0.3, 7850.0}, length);
}

using Vec12 = Eigen::Matrix<double, 12, 1>;

// Tip displacements of a one-element cantilever (node 1 clamped) under a tip load vector.
Vec12 CantileverTip(const Mat12& k, const Eigen::Matrix<double, 6, 1>& tip_load) {
  const Eigen::Matrix<double, 6, 6> k22 = k.bottomRightCorner<6, 6>();
  Vec12 d = Vec12::Zero();
  d.tail<6>() = k22.ldlt().solve(tip_load);
  return d;
}

Eigen::Matrix<double, 6, 1> Load(int dof, double value) {
  Eigen::Matrix<double, 6, 1> f = Eigen::Matrix<double, 6, 1>::Zero();
  f(dof) = value;
  return f;
}

double Rel(double value, double reference) {
  return std::abs(value - reference) / std::abs(reference);
}

TEST(BeamElement, EulerBernoulliCantileverIsExact) {
  const BeamElementProperties p = Collar(2.0);
  const Mat12 k = ElementStiffness(p, BeamTheory::kEulerBernoulli);
  const double L = p.length, EI = p.youngs_modulus * p.second_moment;
  const double P = 1.0e4, M = 3.0e3, T = 2.0e3;
  // Tip force in y: v = PL³/(3EI), θz = +PL²/(2EI) (θz = dv/dx).
  Vec12 d = CantileverTip(k, Load(1, P));
  EXPECT_LT(Rel(d(7), P * L * L * L / (3 * EI)), 1e-12);
  EXPECT_LT(Rel(d(11), P * L * L / (2 * EI)), 1e-12);
  // Tip force in z: w = PL³/(3EI), θy = −PL²/(2EI) (θy = −dw/dx).
  d = CantileverTip(k, Load(2, P));
  EXPECT_LT(Rel(d(8), P * L * L * L / (3 * EI)), 1e-12);
  EXPECT_LT(Rel(d(10), -P * L * L / (2 * EI)), 1e-12);
  // Tip moments: θ = ML/EI; v = ML²/(2EI) under Mz, w = −ML²/(2EI) under My.
  d = CantileverTip(k, Load(5, M));
  EXPECT_LT(Rel(d(11), M * L / EI), 1e-12);
  EXPECT_LT(Rel(d(7), M * L * L / (2 * EI)), 1e-12);
  d = CantileverTip(k, Load(4, M));
  EXPECT_LT(Rel(d(10), M * L / EI), 1e-12);
  EXPECT_LT(Rel(d(8), -M * L * L / (2 * EI)), 1e-12);
  // Axial PL/(EA) and torsion TL/(GJ).
  d = CantileverTip(k, Load(0, P));
  EXPECT_LT(Rel(d(6), P * L / (p.youngs_modulus * p.area)), 1e-12);
  d = CantileverTip(k, Load(3, T));
  EXPECT_LT(Rel(d(9), T * L / (p.shear_modulus * p.polar_moment)), 1e-12);
}

// bending_stiffness_factor scales EI alone: a cantilever's tip deflection under a tip force grows by
// its inverse (Euler–Bernoulli: P L³ / 3 E I), its stretch and twist under a tip force and torque
// stay, and the mass matrix is the same.
TEST(BeamElement, BendingStiffnessFactorScalesEIAlone) {
  const BeamElementProperties steel = Collar();
  BeamElementProperties soft = steel;
  soft.bending_stiffness_factor = 0.01;
  const Mat12 k = ElementStiffness(steel, BeamTheory::kEulerBernoulli);
  const Mat12 k_soft = ElementStiffness(soft, BeamTheory::kEulerBernoulli);
  const double L = steel.length, ei = steel.youngs_modulus * steel.second_moment;
  EXPECT_LT(Rel(CantileverTip(k_soft, Load(1, 1e3))(7), 1e3 * L * L * L / (3.0 * 0.01 * ei)), 1e-9);
  EXPECT_LT(Rel(CantileverTip(k_soft, Load(0, 1e3))(6), CantileverTip(k, Load(0, 1e3))(6)), 1e-12);
  EXPECT_LT(Rel(CantileverTip(k_soft, Load(3, 1e3))(9), CantileverTip(k, Load(3, 1e3))(9)), 1e-12);
  EXPECT_EQ(ElementConsistentMass(soft, BeamTheory::kEulerBernoulli), ElementConsistentMass(steel, BeamTheory::kEulerBernoulli));
}

TEST(BeamElement, TimoshenkoCantileverAddsShearDeflection) {
  const BeamElementProperties p = Collar(0.5);
  const Mat12 k = ElementStiffness(p, BeamTheory::kTimoshenko);
  const double L = p.length, EI = p.youngs_modulus * p.second_moment;
  const double kGA = p.shear_coefficient * p.shear_modulus * p.area;
  const double P = 1.0e4, M = 3.0e3;
  const double expected = P * L * L * L / (3 * EI) + P * L / kGA;
  ASSERT_GT(P * L / kGA / expected, 0.05);  // the shear part is visible in this element
  Vec12 d = CantileverTip(k, Load(1, P));
  EXPECT_LT(Rel(d(7), expected), 1e-12);
  EXPECT_LT(Rel(d(11), P * L * L / (2 * EI)), 1e-12);  // shear does not rotate the section
  d = CantileverTip(k, Load(2, P));
  EXPECT_LT(Rel(d(8), expected), 1e-12);
  EXPECT_LT(Rel(d(10), -P * L * L / (2 * EI)), 1e-12);
  // A pure end moment causes no shear.
  d = CantileverTip(k, Load(5, M));
  EXPECT_LT(Rel(d(11), M * L / EI), 1e-12);
  EXPECT_LT(Rel(d(7), M * L * L / (2 * EI)), 1e-12);
}

// The 12 × 6 rigid motions of an element from node 1 at x = 0 to node 2 at x = L.
Eigen::Matrix<double, 12, 6> RigidModes(double L) {
  Eigen::Matrix<double, 12, 6> r = Eigen::Matrix<double, 12, 6>::Zero();
  for (int node = 0; node < 2; ++node) {
    const int o = 6 * node;
    r.block<3, 3>(o, 0).setIdentity();
    r.block<3, 3>(o + 3, 3).setIdentity();
    r(o + 2, 4) = -node * L;  // rotation about y: w = −x θy
    r(o + 1, 5) = node * L;   // rotation about z: v = +x θz
  }
  return r;
}

TEST(BeamElement, StiffnessIsSymmetricAndFreeOfRigidStrain) {
  const BeamElementProperties p = Collar(0.8);
  for (BeamTheory theory : {BeamTheory::kEulerBernoulli, BeamTheory::kTimoshenko}) {
    const Mat12 k = ElementStiffness(p, theory);
    EXPECT_LT((k - k.transpose()).norm(), 1e-12 * k.norm());
    EXPECT_LT((k * RigidModes(p.length)).norm(), 1e-12 * k.norm());
    // Exactly 6 zero eigenvalues.
    const VecX eigenvalues = SymmetricEigen(k, false).values;
    EXPECT_GT(eigenvalues(6), 1e-8 * eigenvalues(11));
  }
}

// Shear-dependent interpolation (Friedman & Kosmatka 1993) of the x-y plane, ξ = x/L:
// lateral v = N·q and section rotation θz = Nθ·q for q = (v1, θz1, v2, θz2).
struct Interpolation {
  Eigen::RowVector4d v, dv, theta, dtheta;
};

Interpolation Shapes(double xi, double L, double phi) {
  const double c = 1.0 / (1.0 + phi);
  Interpolation s;
  s.v << c * (2 * xi * xi * xi - 3 * xi * xi - phi * xi + 1 + phi),
      c * L * (xi * xi * xi - (2 + phi / 2) * xi * xi + (1 + phi / 2) * xi),
      c * (-2 * xi * xi * xi + 3 * xi * xi + phi * xi),
      c * L * (xi * xi * xi - (1 - phi / 2) * xi * xi - phi / 2 * xi);
  s.dv << c * (6 * xi * xi - 6 * xi - phi) / L, c * (3 * xi * xi - (4 + phi) * xi + 1 + phi / 2),
      c * (-6 * xi * xi + 6 * xi + phi) / L, c * (3 * xi * xi - (2 - phi) * xi - phi / 2);
  s.theta << c * 6 / L * (xi * xi - xi), c * (3 * xi * xi - (4 + phi) * xi + 1 + phi),
      -c * 6 / L * (xi * xi - xi), c * (3 * xi * xi - (2 - phi) * xi);
  s.dtheta << c * 6 / (L * L) * (2 * xi - 1), c * (6 * xi - 4 - phi) / L,
      -c * 6 / (L * L) * (2 * xi - 1), c * (6 * xi - 2 + phi) / L;
  return s;
}

struct PlaneMatrices {
  Eigen::Matrix4d stiffness, translation, rotary, geometric;
};

// Five-point Gauss–Legendre quadrature (exact to degree 9) of the energy integrands.
PlaneMatrices Quadrature(const BeamElementProperties& p, double phi) {
  const std::array<double, 5> x = {-0.9061798459386640, -0.5384693101056831, 0.0,
                                   0.5384693101056831, 0.9061798459386640};
  const std::array<double, 5> w = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889,
                                   0.4786286704993665, 0.2369268850561891};
  const double L = p.length;
  const double EI = p.youngs_modulus * p.second_moment;
  const double kGA = phi > 0 ? 12 * EI / (phi * L * L) : 0.0;
  PlaneMatrices out{Eigen::Matrix4d::Zero(), Eigen::Matrix4d::Zero(), Eigen::Matrix4d::Zero(),
                    Eigen::Matrix4d::Zero()};
  for (int g = 0; g < 5; ++g) {
    const Interpolation s = Shapes(0.5 * (x[g] + 1), L, phi);
    const double dx = 0.5 * w[g] * L;
    const Eigen::RowVector4d shear = s.dv - s.theta;
    out.stiffness += dx * (EI * s.dtheta.transpose() * s.dtheta + kGA * shear.transpose() * shear);
    out.translation +=
        dx * (p.density * p.area + p.lateral_mass_per_length) * s.v.transpose() * s.v;
    out.rotary += dx * p.density * p.second_moment * s.theta.transpose() * s.theta;
    out.geometric += dx * s.dv.transpose() * s.dv;
  }
  return out;
}

Eigen::Matrix4d Block(const Mat12& m, const std::array<int, 4>& dofs) {
  Eigen::Matrix4d b;
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) b(r, c) = m(dofs[r], dofs[c]);
  }
  return b;
}

void ExpectPlanesMatch(const Mat12& element, const Eigen::Matrix4d& expected_xy, const char* what) {
  const std::array<int, 4> xy = {1, 5, 7, 11}, xz = {2, 4, 8, 10};
  const Eigen::Matrix4d flip = Eigen::Vector4d(1, -1, 1, -1).asDiagonal();
  const double scale = expected_xy.norm();
  EXPECT_LT((Block(element, xy) - expected_xy).norm(), 1e-13 * scale) << what;
  EXPECT_LT((Block(element, xz) - flip * expected_xy * flip).norm(), 1e-13 * scale) << what;
  // No coupling between the planes.
  for (int r : xy) {
    for (int c : xz) {
      EXPECT_EQ(element(r, c), 0.0) << what;
    }
  }
}

TEST(BeamElement, ClosedFormsMatchQuadratureOfTheInterpolation) {
  BeamElementProperties p = Collar(0.6);
  p.lateral_mass_per_length = 40.0;
  for (BeamTheory theory : {BeamTheory::kEulerBernoulli, BeamTheory::kTimoshenko}) {
    const double phi = ShearParameter(p, theory);
    if (theory == BeamTheory::kTimoshenko) {
      ASSERT_GT(phi, 0.1);
    }
    const PlaneMatrices q = Quadrature(p, phi);
    ExpectPlanesMatch(ElementStiffness(p, theory), q.stiffness, "stiffness");
    ExpectPlanesMatch(ElementConsistentMass(p, theory), q.translation + q.rotary, "mass");
    ExpectPlanesMatch(ElementGeometricStiffness(p, theory), q.geometric, "geometric");
    BeamElementProperties no_rotary = p;
    no_rotary.bending_rotary_inertia = false;
    ExpectPlanesMatch(ElementConsistentMass(no_rotary, theory), q.translation, "mass w/o rotary");
  }
}

TEST(BeamElement, MassesCarryTheExactRigidBodyInertia) {
  BeamElementProperties p = Collar(0.7);
  p.lateral_mass_per_length = 25.0;
  const double L = p.length;
  const double axial = p.density * p.area * L;
  const double lateral = axial + p.lateral_mass_per_length * L;
  const Eigen::Matrix<double, 12, 6> r = RigidModes(L);
  for (BeamTheory theory : {BeamTheory::kEulerBernoulli, BeamTheory::kTimoshenko}) {
    const Mat12 m = ElementConsistentMass(p, theory);
    EXPECT_LT((m - m.transpose()).norm(), 1e-14 * m.norm());
    const Eigen::Matrix<double, 6, 6> rigid = r.transpose() * m * r;
    EXPECT_LT(Rel(rigid(0, 0), axial), 1e-14);
    EXPECT_LT(Rel(rigid(1, 1), lateral), 1e-14);
    EXPECT_LT(Rel(rigid(2, 2), lateral), 1e-14);
    EXPECT_LT(Rel(rigid(3, 3), p.density * p.polar_moment * L), 1e-14);
    // Rotation about node 1 (a rigid motion the interpolation reproduces exactly):
    // ∫ μ x² dx + ρ I L = μ L³/3 + ρ I L.
    const double bending = lateral * L * L / 3.0 + p.density * p.second_moment * L;
    EXPECT_LT(Rel(rigid(4, 4), bending), 1e-13);
    EXPECT_LT(Rel(rigid(5, 5), bending), 1e-13);
    // First moment: ∫ μ x dx = μ L²/2 couples y-translation with z-rotation.
    EXPECT_LT(Rel(rigid(1, 5), lateral * L / 2.0), 1e-13);
    EXPECT_LT(Rel(rigid(2, 4), -lateral * L / 2.0), 1e-13);
  }
  const Mat12 lumped = ElementLumpedMass(p, LumpedRotaryInertia::kSectionAndSegment);
  const Eigen::Matrix<double, 6, 6> lumped_rigid = r.transpose() * lumped * r;
  EXPECT_LT(Rel(lumped_rigid(0, 0), axial), 1e-14);
  EXPECT_LT(Rel(lumped_rigid(1, 1), lateral), 1e-14);
  EXPECT_LT(Rel(lumped(4, 4), p.density * p.second_moment * L / 2 + lateral * L * L / 24.0), 1e-14);
  EXPECT_LT(Rel(ElementLumpedMass(p, LumpedRotaryInertia::kSection)(11, 11),
                p.density * p.second_moment * L / 2),
            1e-14);
}

TEST(BeamElement, GeometricStiffnessIsTheStringEnergyOfARotation) {
  const BeamElementProperties p = Collar(0.9);
  const Eigen::Matrix<double, 12, 6> r = RigidModes(p.length);
  for (BeamTheory theory : {BeamTheory::kEulerBernoulli, BeamTheory::kTimoshenko}) {
    const Mat12 kg = ElementGeometricStiffness(p, theory);
    EXPECT_LT((kg - kg.transpose()).norm(), 1e-14 * kg.norm());
    const Eigen::Matrix<double, 6, 6> rigid = r.transpose() * kg * r;
    // Translations do no work; a rotation θ stores N ∫ (v')² dx / 2 = N L θ² / 2.
    EXPECT_LT((rigid.topLeftCorner<4, 4>().norm()), 1e-14 * kg.norm());
    EXPECT_LT(Rel(rigid(4, 4), p.length), 1e-14);
    EXPECT_LT(Rel(rigid(5, 5), p.length), 1e-14);
  }
}

}  // namespace beam_element_test
}  // namespace drillflex::fe

namespace drillflex::fe {
namespace beam_element_test {

// The torque's geometric stiffness of an Euler–Bernoulli element (cubic interpolation, exact for
// cubic fields): for v = x², w = x³ on [0, L], v′w″ − w′v″ = 12x² − 6x² = 6x², so dᵀ K_T d = −2L³;
// no entries on the axial and torsional DOFs; symmetric.
TEST(ElementTorqueGeometricStiffness, CubicFieldGivesTheExactIntegral) {
  BeamElementProperties p;
  p.length = 0.7;
  p.area = 1e-3;
  p.second_moment = 1e-6;
  p.polar_moment = 2e-6;
  p.youngs_modulus = 2e11;
  p.shear_modulus = 8e10;
  p.density = 7850.0;
  const Mat12 k = ElementTorqueGeometricStiffness(p, BeamTheory::kEulerBernoulli);
  const double L = p.length;
  Eigen::Matrix<double, 12, 1> d = Eigen::Matrix<double, 12, 1>::Zero();
  // Node 2: v = L², θz = v′ = 2L; w = L³, θy = −w′ = −3L² (node 1: all zero for these fields).
  d(6 + 1) = L * L;
  d(6 + 5) = 2.0 * L;
  d(6 + 2) = L * L * L;
  d(6 + 4) = -3.0 * L * L;
  EXPECT_NEAR(d.dot(k * d), -2.0 * L * L * L, 1e-12);
  EXPECT_LT((k - k.transpose()).norm(), 1e-14 * k.norm());
  for (int dof : {0, 3, 6, 9}) EXPECT_EQ(k.row(dof).norm(), 0.0);
  // A field in one plane only stores nothing (the form couples the two planes).
  Eigen::Matrix<double, 12, 1> planar = Eigen::Matrix<double, 12, 1>::Zero();
  planar(1) = 0.3;
  planar(5) = -0.2;
  planar(7) = 0.1;
  planar(11) = 0.4;
  EXPECT_NEAR(planar.dot(k * planar), 0.0, 1e-15);
}

}  // namespace beam_element_test
}  // namespace drillflex::fe
