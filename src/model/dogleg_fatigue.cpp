#include "model/dogleg_fatigue.hpp"

#include <algorithm>
#include <cmath>

namespace drillflex::model {
namespace {

constexpr double kPsi = 4.4482216152605 / (0.0254 * 0.0254);  // Pa

}  // namespace

double AllowableBendingStress(double tensile_stress, double yield) {
  const double t = std::max(tensile_stress, 0.0) / kPsi;  // psi
  const double yield_ksi = yield / (1000.0 * kPsi);
  double allowable = 0.0;  // psi
  if (yield_ksi < 95.0 - 1e-9) {
    allowable = 19500.0 - (10.0 / 67.0) * t - 0.6 / (670.0 * 670.0) * (t - 33500.0) * (t - 33500.0);
  } else {
    // The minimum tensile strength: X-95 105 ksi, G-105 115 ksi, S-135 (and stronger) 145 ksi.
    const double ultimate = yield_ksi < 105.0 - 1e-9 ? 105000.0 : yield_ksi < 135.0 - 1e-9 ? 115000.0 : 145000.0;
    allowable = 20000.0 * (1.0 - t / ultimate);
  }
  return std::max(allowable, 0.0) * kPsi;
}

double LubinskiFactor(double tension, double bending_stiffness, double half_joint_spacing) {
  if (!(tension > 0.0)) return 1.0;
  const double kl = std::sqrt(tension / bending_stiffness) * half_joint_spacing;
  return kl < 1e-8 ? 1.0 : kl / std::tanh(kl);
}

double DoglegBendingStress(double curvature, double youngs_modulus, double outer_diameter, double tension,
                           double bending_stiffness, double half_joint_spacing) {
  return 0.5 * youngs_modulus * outer_diameter * std::abs(curvature) *
         LubinskiFactor(tension, bending_stiffness, half_joint_spacing);
}

double MaxPermissibleCurvature(double allowable_bending_stress, double youngs_modulus, double outer_diameter,
                               double tension, double bending_stiffness, double half_joint_spacing) {
  return 2.0 * allowable_bending_stress / (youngs_modulus * outer_diameter) /
         LubinskiFactor(tension, bending_stiffness, half_joint_spacing);
}

}  // namespace drillflex::model
