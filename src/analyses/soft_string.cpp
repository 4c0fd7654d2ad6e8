#include "analyses/soft_string.hpp"

#include <algorithm>
#include <cmath>
#include <functional>

#include <fmt/format.h>

#include "core/error.hpp"
#include "model/hole_friction.hpp"
#include "well/hole.hpp"

namespace drillflex::analyses {
namespace {

// Below this sine of its inclination an element end counts as vertical: its azimuth is undefined.
constexpr double kVerticalSine = 1e-9;
// Cuts closer together than this (m) are one (a component boundary on a survey station).
constexpr double kCutMergeLength = 1e-9;

void CheckWellAndString(const model::ModelInput& input) {
  if (!input.well) throw InputError({}, "well", "the soft-string torque and drag needs a well (a survey)");
  if (input.string.components.empty()) throw InputError({}, "string", "the string has no components");
  const double start = input.well->trajectory.start_md();
  if (!std::isfinite(input.bit_md) || !(input.bit_md > start)) {
    throw InputError({}, "well.bit_md",
                     fmt::format("the bit MD ({:.6g} m) must lie below the survey's first station ({:.6g} m)",
                                 input.bit_md, start));
  }
  const auto& components = input.string.components;
  for (Index i = 0; i < std::ssize(components); ++i) {
    const model::Component& component = components[i];
    if (input.materials.count(component.material) == 0) {
      throw InputError({"", component.source_line, 0}, fmt::format("string[{}].material", i),
                       fmt::format("no material '{}' in the case", component.material));
    }
    if (!(component.length > 0.0) || !std::isfinite(component.length) || component.count < 1) {
      throw LogicError(fmt::format("ComputeSoftString: string[{}] has no length (the case reader checks it)", i));
    }
  }
}

void CheckOperation(const SoftStringOperation& operation) {
  const auto friction = [](double mu) { return std::isfinite(mu) && mu >= 0.0; };
  const bool cased_ok = !operation.cased_friction ||
                        (friction(operation.cased_friction->axial) && friction(operation.cased_friction->tangential));
  if (!friction(operation.axial_friction) || !friction(operation.tangential_friction) || !cased_ok) {
    throw LogicError(fmt::format("ComputeSoftString: friction factors must be finite and non-negative "
                                 "(axial {}, tangential {})",
                                 operation.axial_friction, operation.tangential_friction));
  }
  if (!std::isfinite(operation.weight_on_bit) || !std::isfinite(operation.torque_on_bit)) {
    throw LogicError("ComputeSoftString: the WOB and TOB must be finite");
  }
}

// The element ends' MDs from the bit up to the surface (the trajectory's start MD): the bit, every
// component boundary and every survey station between, the surface.
std::vector<double> CutMds(const model::ModelInput& input, double max_element_length) {
  const double surface = input.well->trajectory.start_md();
  const double bit = input.bit_md;
  const auto inside = [&](double md) { return md > surface + kCutMergeLength && md < bit - kCutMergeLength; };
  std::vector<double> interior;
  double md = bit;
  for (const model::Component& component : input.string.components) {
    md -= component.length * component.count;
    if (inside(md)) interior.push_back(md);
  }
  for (const well::SurveyStation& station : input.well->trajectory.stations()) {
    if (inside(station.md)) interior.push_back(station.md);
  }
  for (const well::HoleSection& section : input.well->hole.sections()) {
    if (section.to_md && inside(*section.to_md)) interior.push_back(*section.to_md);
  }
  std::sort(interior.begin(), interior.end(), std::greater<>());
  std::vector<double> cuts{bit};
  for (double cut : interior) {
    if (cuts.back() - cut > kCutMergeLength) cuts.push_back(cut);
  }
  cuts.push_back(surface);
  if (!(max_element_length > 0.0)) return cuts;
  std::vector<double> split{cuts.front()};
  for (std::size_t i = 1; i < cuts.size(); ++i) {
    const double length = cuts[i - 1] - cuts[i];
    const Index pieces = std::max<Index>(1, std::lround(std::ceil(length / max_element_length - 1e-9)));
    for (Index k = 1; k < pieces; ++k) split.push_back(cuts[i - 1] - length * k / pieces);
    split.push_back(cuts[i]);
  }
  return split;
}

// The component at a distance s (m) from the bit (an element's middle, never on a boundary); above
// the string's top, the top component continued to the surface.
const model::Component& ComponentAtMiddle(const model::StringConfig& string, double s) {
  double top = 0.0;
  for (const model::Component& component : string.components) {
    top += component.length * component.count;
    if (s < top) return component;
  }
  return string.components.back();
}

struct EndAngles {
  double inclination = 0.0;  // rad
  double azimuth = 0.0;      // rad
};

EndAngles AnglesAt(const well::Trajectory& trajectory, double md) {
  return {trajectory.Inclination(md), trajectory.Azimuth(md)};
}

// The wall's normal force on an element, N (Johancsik et al., SPE 11380):
//   N = √( (T ΔA sin Ī)² + (T ΔI + W sin Ī)² ),
// T the tension at its lower end, W its buoyed weight, ΔI and ΔA the changes from its lower to its
// upper end (soft_string.hpp: with them, tension pulls the string to the inside of a bend). A vertical
// end takes the azimuth of the other end (the minimum-curvature arc's plane).
double ComputeElementNormalForce(double tension, double weight, EndAngles lower, EndAngles upper) {
  const bool lower_vertical = std::sin(lower.inclination) < kVerticalSine;
  const bool upper_vertical = std::sin(upper.inclination) < kVerticalSine;
  if (lower_vertical) lower.azimuth = upper.azimuth;
  if (upper_vertical) upper.azimuth = lower.azimuth;
  const double mean_sine = std::sin(0.5 * (lower.inclination + upper.inclination));
  const double inclination_change = upper.inclination - lower.inclination;
  const double azimuth_change = std::remainder(upper.azimuth - lower.azimuth, 2.0 * kPi);  // in [−π, π]
  return std::hypot(tension * azimuth_change * mean_sine, tension * inclination_change + weight * mean_sine);
}

// The element's tension gain, N (SPE 11380): ΔT = W cos Ī + μ_a N pulling out, − μ_a N
// running in (the friction opposes the sliding), W cos Ī rotating (the friction acts around the string).
double ComputeTensionChange(double weight, double mean_inclination, double normal_force,
                            const SoftStringOperation& operation, const model::WallFriction& friction) {
  const double weight_along = weight * std::cos(mean_inclination);
  switch (operation.motion) {
    case SoftStringMotion::PickUp: return weight_along + friction.axial * normal_force;
    case SoftStringMotion::SlackOff: return weight_along - friction.axial * normal_force;
    case SoftStringMotion::Rotating: return weight_along;
  }
  throw LogicError("ComputeTensionChange: unknown motion");
}

// The element's torque gain, N·m (SPE 11380): ΔM = μ_t N r rotating, r the contact radius
// (tool joint, blade or body); none sliding without rotation.
double ComputeTorqueChange(double normal_force, const model::Component& component,
                           const SoftStringOperation& operation, const model::WallFriction& friction) {
  if (operation.motion != SoftStringMotion::Rotating) return 0.0;
  return friction.tangential * normal_force * 0.5 * model::ContactDiameter(component);
}

// The coefficients at `md` (an element's middle): the operation's open-hole ones, in cased hole its
// cased ones or the section's own.
model::WallFriction FrictionAt(const model::ModelInput& input, const well::HoleProfile& hole,
                               const SoftStringOperation& operation, double md) {
  const model::HoleFriction built = model::HoleFrictionAt(hole, input.settings.contact, md);
  if (!built.cased) return {operation.axial_friction, operation.tangential_friction};
  return operation.cased_friction.value_or(built.friction);
}

}  // namespace

SoftStringResult ComputeSoftString(const model::ModelInput& input, const SoftStringOperation& operation) {
  CheckWellAndString(input);
  CheckOperation(operation);
  const well::Trajectory& trajectory = input.well->trajectory;
  const std::vector<double> cuts = CutMds(input, operation.max_element_length);
  const well::HoleProfile& hole = input.well->hole;  // the sections' friction, looked up at every element
  SoftStringResult result;
  result.stations.reserve(cuts.size());
  // At the bit the rock pushes up with the WOB and resists the rotation with the TOB.
  result.stations.push_back({0.0, input.bit_md, -operation.weight_on_bit, operation.torque_on_bit, 0.0});
  EndAngles lower = AnglesAt(trajectory, cuts.front());
  for (std::size_t k = 1; k < cuts.size(); ++k) {
    const SoftStringStation below = result.stations.back();
    const EndAngles upper = AnglesAt(trajectory, cuts[k]);
    const double length = cuts[k - 1] - cuts[k];
    const model::Component& component = ComponentAtMiddle(input.string, input.bit_md - 0.5 * (cuts[k - 1] + cuts[k]));
    const double weight = model::BuoyedWeightPerLength(component, input) * length;  // W = w L
    const model::WallFriction friction = FrictionAt(input, hole, operation, 0.5 * (cuts[k - 1] + cuts[k]));
    double normal_force = ComputeElementNormalForce(below.axial_force, weight, lower, upper);
    if (operation.wall_climb && operation.motion == SoftStringMotion::Rotating) {
      normal_force /= std::hypot(1.0, friction.tangential);  // N √(1 + μ_t²) = L
    }
    const double mean_inclination = 0.5 * (lower.inclination + upper.inclination);
    SoftStringStation station;
    station.s = input.bit_md - cuts[k];
    station.md = cuts[k];
    station.axial_force = below.axial_force + ComputeTensionChange(weight, mean_inclination, normal_force, operation, friction);
    station.torque = below.torque + ComputeTorqueChange(normal_force, component, operation, friction);
    station.normal_force = normal_force;
    result.stations.push_back(station);
    lower = upper;
  }
  result.hook_load = result.stations.back().axial_force;
  result.surface_torque = result.stations.back().torque;
  return result;
}

}  // namespace drillflex::analyses
