#include "analyses/tendency_sensitivity.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

#include "core/error.hpp"

namespace drillflex::analyses {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInch = 0.0254;

// The tendency of `input` from the base's steady curvature, added to `curve` at `value`.
void AddPoint(const model::ModelInput& input, const ModelFactory& build, const StaticSettings& statics,
              const TendencySettings& settings, const TendencyResult& base, double value, TendencyCurve& curve) {
  curve.values.push_back(value);
  try {
    const TendencyResult result = RunTendency(input, build, statics, settings, base.curvature);
    curve.build_rate.push_back(result.build_rate);
    curve.turn_rate.push_back(result.turn_rate);
  } catch (const SolverError&) {
    curve.build_rate.push_back(kNaN);
    curve.turn_rate.push_back(kNaN);
  }
}

// A straight path through the case's bit point at inclination `inclination` and the bit's azimuth:
// the tendency's hole reads only the bit's point and direction (ConstantCurvatureHole).
well::Trajectory PathAtInclination(const well::Trajectory& path, double bit_md, double inclination) {
  const double azimuth = path.Azimuth(bit_md);
  const Vec3 tangent = well::TangentFromAngles(inclination, azimuth);
  const double end = bit_md + 100.0;
  return well::Trajectory({{0.0, inclination, azimuth}, {end, inclination, azimuth}},
                          path.Position(bit_md) - bit_md * tangent);
}

}  // namespace

TendencySensitivities ComputeTendencySensitivities(const model::ModelInput& input, const ModelFactory& build,
                                                   const StaticSettings& statics, const TendencySettings& settings,
                                                   const TendencyResult& base) {
  TendencySensitivities sensitivities;
  const auto base_point = [&](TendencyCurve& curve, double value) {
    curve.values.push_back(value);
    curve.build_rate.push_back(base.build_rate);
    curve.turn_rate.push_back(base.turn_rate);
  };
  for (const double factor : {0.5, 0.75, 1.0, 1.25, 1.5}) {
    const double wob = factor * input.operation.weight_on_bit;
    if (factor == 1.0) {
      base_point(sensitivities.weight_on_bit, wob);
      continue;
    }
    model::ModelInput varied = input;
    varied.operation.weight_on_bit = wob;
    AddPoint(varied, build, statics, settings, base, wob, sensitivities.weight_on_bit);
  }
  const double inclination = input.well->trajectory.Inclination(input.bit_md);
  for (const double change : {-10.0, -5.0, 0.0, 5.0, 10.0}) {
    const double value = inclination + change * kDegree;
    if (change == 0.0) {
      base_point(sensitivities.inclination, value);
      continue;
    }
    if (value < 0.0 || value > 0.5 * kPi + 1e-12) continue;
    model::ModelInput varied = input;
    varied.well = std::make_shared<const model::Wellbore>(
        model::Wellbore{PathAtInclination(input.well->trajectory, input.bit_md, value), input.well->hole});
    AddPoint(varied, build, statics, settings, base, value, sensitivities.inclination);
  }
  for (const double sixteenths : {0.0, 1.0, 2.0}) {
    const double reduction = sixteenths / 16.0 * kInch;
    if (sixteenths == 0.0) {
      base_point(sensitivities.gauge_reduction, reduction);
      continue;
    }
    model::ModelInput varied = input;
    bool any = false;
    for (model::Component& component : varied.string.components) {
      if (!component.blade_diameter) continue;
      component.blade_diameter = std::max(*component.blade_diameter - reduction, component.outer_diameter);
      any = true;
    }
    if (!any) break;
    AddPoint(varied, build, statics, settings, base, reduction, sensitivities.gauge_reduction);
  }
  return sensitivities;
}

}  // namespace drillflex::analyses
