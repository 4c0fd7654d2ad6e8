#include "fe/beam_element.hpp"

#include <array>
#include <cmath>

namespace drillflex::fe {
namespace {

using Mat4 = Eigen::Matrix4d;

// Local DOF indices of the two bending planes: (v1, θz1, v2, θz2) and (w1, θy1, w2, θy2).
constexpr std::array<int, 4> kPlaneXy = {1, 5, 7, 11};
constexpr std::array<int, 4> kPlaneXz = {2, 4, 8, 10};

// Places a bending block given for the x-y plane (θz = +v') into both planes; the x-z plane uses
// θy = −w', i.e. the same block with the rotation rows and columns negated.
void AddBendingBlock(const Mat4& block_xy, Mat12& element) {
  const Eigen::Vector4d sign(1.0, -1.0, 1.0, -1.0);
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) {
      element(kPlaneXy[r], kPlaneXy[c]) += block_xy(r, c);
      element(kPlaneXz[r], kPlaneXz[c]) += sign(r) * sign(c) * block_xy(r, c);
    }
  }
}

// 2 × 2 two-node bar block c·[1 −1; −1 1] or c·[2 1; 1 2]/… on DOF (i, i + 6).
void AddBarBlock(int dof, double diagonal, double off_diagonal, Mat12& element) {
  element(dof, dof) += diagonal;
  element(dof + 6, dof + 6) += diagonal;
  element(dof, dof + 6) += off_diagonal;
  element(dof + 6, dof) += off_diagonal;
}

// Symmetric 4 × 4 pattern shared by the rotary-inertia and geometric blocks:
// [a, b, −a, b; b, d, −b, e; −a, −b, a, −b; b, e, −b, d].
Mat4 AntisymmetricPattern(double a, double b, double d, double e) {
  Mat4 m;
  m << a, b, -a, b,   //
      b, d, -b, e,    //
      -a, -b, a, -b,  //
      b, e, -b, d;
  return m;
}

}  // namespace

BeamElementProperties MakeElementProperties(const HollowSection& section, const Material& material,
                                            double length) {
  BeamElementProperties p;
  p.length = length;
  p.area = section.area();
  p.second_moment = section.second_moment();
  p.polar_moment = section.polar_moment();
  p.youngs_modulus = material.youngs_modulus;
  p.shear_modulus = material.shear_modulus();
  p.density = material.density;
  p.shear_coefficient = section.shear_coefficient(material.poisson_ratio);
  return p;
}

double ShearParameter(const BeamElementProperties& p, BeamTheory theory) {
  if (theory == BeamTheory::kEulerBernoulli) return 0.0;
  return 12.0 * p.bending_rigidity() /
         (p.shear_coefficient * p.shear_modulus * p.area * p.length * p.length);
}

Mat12 ElementStiffness(const BeamElementProperties& p, BeamTheory theory) {
  const double L = p.length;
  const double phi = ShearParameter(p, theory);
  Mat12 k = Mat12::Zero();
  const double axial = p.youngs_modulus * p.area / L;
  const double torsion = p.shear_modulus * p.polar_moment / L;
  AddBarBlock(0, axial, -axial, k);
  AddBarBlock(3, torsion, -torsion, k);
  // Przemieniecki (1968): EI/((1+Φ)L³)·[12, 6L, −12, 6L; 6L, (4+Φ)L², −6L, (2−Φ)L²; …].
  const double c = p.bending_rigidity() / ((1.0 + phi) * L * L * L);
  Mat4 bending;
  bending << 12.0, 6.0 * L, -12.0, 6.0 * L,                         //
      6.0 * L, (4.0 + phi) * L * L, -6.0 * L, (2.0 - phi) * L * L,  //
      -12.0, -6.0 * L, 12.0, -6.0 * L,                              //
      6.0 * L, (2.0 - phi) * L * L, -6.0 * L, (4.0 + phi) * L * L;
  AddBendingBlock(c * bending, k);
  return k;
}

Mat12 ElementConsistentMass(const BeamElementProperties& p, BeamTheory theory) {
  const double L = p.length;
  const double phi = ShearParameter(p, theory);
  const double phi2 = phi * phi;
  const double s = 1.0 / ((1.0 + phi) * (1.0 + phi));
  Mat12 m = Mat12::Zero();
  const double axial = p.density * p.area * L;
  const double torsion = p.density * p.polar_moment * L;
  AddBarBlock(0, axial / 3.0, axial / 6.0, m);
  AddBarBlock(3, torsion / 3.0, torsion / 6.0, m);
  // Translational inertia, Przemieniecki (1968) (Φ = 0: ρAL/420·[156, 22L, 54, −13L; …]).
  const double m11 = 13.0 / 35.0 + 7.0 * phi / 10.0 + phi2 / 3.0;
  const double m12 = (11.0 / 210.0 + 11.0 * phi / 120.0 + phi2 / 24.0) * L;
  const double m13 = 9.0 / 70.0 + 3.0 * phi / 10.0 + phi2 / 6.0;
  const double m14 = -(13.0 / 420.0 + 3.0 * phi / 40.0 + phi2 / 24.0) * L;
  const double m22 = (1.0 / 105.0 + phi / 60.0 + phi2 / 120.0) * L * L;
  const double m24 = -(1.0 / 140.0 + phi / 60.0 + phi2 / 120.0) * L * L;
  Mat4 translation;
  translation << m11, m12, m13, m14,  //
      m12, m22, -m14, m24,            //
      m13, -m14, m11, -m12,           //
      m14, m24, -m12, m22;
  const double lateral_mass = (p.density * p.area + p.lateral_mass_per_length) * L;
  AddBendingBlock(lateral_mass * s * translation, m);
  if (p.bending_rotary_inertia) {
    // Rotary inertia, Przemieniecki (1968) (Φ = 0: ρI/(30L)·[36, 3L, −36, 3L; …]).
    const double a = 6.0 / 5.0;
    const double b = (1.0 / 10.0 - phi / 2.0) * L;
    const double d = (2.0 / 15.0 + phi / 6.0 + phi2 / 3.0) * L * L;
    const double e = (-1.0 / 30.0 - phi / 6.0 + phi2 / 6.0) * L * L;
    AddBendingBlock(p.density * p.second_moment / L * s * AntisymmetricPattern(a, b, d, e), m);
  }
  return m;
}

Mat12 ElementLumpedMass(const BeamElementProperties& p, LumpedRotaryInertia rotary) {
  const double half = 0.5 * p.length;
  const double axial_mass = p.density * p.area * half;
  const double lateral_mass = (p.density * p.area + p.lateral_mass_per_length) * half;
  const double torsion = p.density * p.polar_moment * half;
  double bending = 0.0;
  if (p.bending_rotary_inertia) bending += p.density * p.second_moment * half;
  if (rotary == LumpedRotaryInertia::kSectionAndSegment) {
    // Mass moment of the half segment about its node: ∫₀^{L/2} μ x² dx = μ (L/2)³ / 3.
    bending += (p.density * p.area + p.lateral_mass_per_length) * half * half * half / 3.0;
  }
  Eigen::Matrix<double, 6, 1> node;
  node << axial_mass, lateral_mass, lateral_mass, torsion, bending, bending;
  Mat12 m = Mat12::Zero();
  m.diagonal() << node, node;
  return m;
}

Mat12 ElementGeometricStiffness(const BeamElementProperties& p, BeamTheory theory) {
  const double L = p.length;
  const double phi = ShearParameter(p, theory);
  const double phi2 = phi * phi;
  const double s = 1.0 / ((1.0 + phi) * (1.0 + phi));
  // Przemieniecki (1968) (Φ = 0: 1/(30L)·[36, 3L, −36, 3L; 3L, 4L², −3L, −L²; …]).
  const double a = 6.0 / 5.0 + 2.0 * phi + phi2;
  const double b = L / 10.0;
  const double d = (2.0 / 15.0 + phi / 6.0 + phi2 / 12.0) * L * L;
  const double e = -(1.0 / 30.0 + phi / 6.0 + phi2 / 12.0) * L * L;
  Mat12 kg = Mat12::Zero();
  AddBendingBlock(s / L * AntisymmetricPattern(a, b, d, e), kg);
  return kg;
}

namespace {

// The shear-dependent lateral interpolation of the x-y plane (Friedman & Kosmatka 1993), DOFs
// (v1, θz1, v2, θz2): first and second derivatives in x at ξ = x/L.
struct LateralShapeDerivatives {
  Eigen::Vector4d first, second;
};
LateralShapeDerivatives LateralShapes(double xi, double L, double phi) {
  const double c = 1.0 / (1.0 + phi);
  LateralShapeDerivatives d;
  // N1 = c(2ξ³ − 3ξ² − Φξ + 1 + Φ), N2 = cL(ξ³ − (2 + Φ/2)ξ² + (1 + Φ/2)ξ),
  // N3 = c(−2ξ³ + 3ξ² + Φξ),        N4 = cL(ξ³ − (1 − Φ/2)ξ² − (Φ/2)ξ); d/dx = (1/L) d/dξ.
  d.first << c * (6.0 * xi * xi - 6.0 * xi - phi) / L,               //
      c * (3.0 * xi * xi - 2.0 * (2.0 + 0.5 * phi) * xi + 1.0 + 0.5 * phi),  //
      c * (-6.0 * xi * xi + 6.0 * xi + phi) / L,                      //
      c * (3.0 * xi * xi - 2.0 * (1.0 - 0.5 * phi) * xi - 0.5 * phi);
  d.second << c * (12.0 * xi - 6.0) / (L * L),             //
      c * (6.0 * xi - 2.0 * (2.0 + 0.5 * phi)) / L,             //
      c * (-12.0 * xi + 6.0) / (L * L),                         //
      c * (6.0 * xi - 2.0 * (1.0 - 0.5 * phi)) / L;
  return d;
}

}  // namespace

Mat12 ElementTorqueGeometricStiffness(const BeamElementProperties& p, BeamTheory theory) {
  const double L = p.length;
  const double phi = ShearParameter(p, theory);
  // v = N·(v1, θz1, v2, θz2), w = N·(w1, −θy1, w2, −θy2) (θy = −w′): the x-z plane's DOFs enter
  // with the rotation signs flipped.
  const Eigen::Vector4d sign(1.0, -1.0, 1.0, -1.0);
  // C_ab = ∫ (N_a′ N_b″ − N_b′ N_a″) dx, antisymmetric; Q = Σ v_a w_b C_ab.
  Mat4 coupling = Mat4::Zero();
  const double root = std::sqrt(0.6);
  const std::array<double, 3> points = {0.5 * (1.0 - root), 0.5, 0.5 * (1.0 + root)};
  const std::array<double, 3> weights = {5.0 / 18.0, 8.0 / 18.0, 5.0 / 18.0};
  for (int g = 0; g < 3; ++g) {
    const LateralShapeDerivatives d = LateralShapes(points[g], L, phi);
    coupling += weights[g] * L * (d.first * d.second.transpose() - d.second * d.first.transpose());
  }
  // dᵀ K d = −Q: the symmetric matrix puts −½ C_ab (with the x-z signs) on (v_a, w_b) and (w_b, v_a).
  Mat12 k = Mat12::Zero();
  for (int a = 0; a < 4; ++a) {
    for (int b = 0; b < 4; ++b) {
      const double value = -0.5 * sign(b) * coupling(a, b);
      k(kPlaneXy[a], kPlaneXz[b]) += value;
      k(kPlaneXz[b], kPlaneXy[a]) += value;
    }
  }
  return k;
}

}  // namespace drillflex::fe
