#include "analyses/string_limits.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <string>

#include <fmt/format.h>

#include "model/dogleg_fatigue.hpp"
#include "model/string_limits.hpp"
#include "well/hole.hpp"

namespace drillflex::analyses {
namespace {

// The steels a string is made of (built-in materials): of no grade, the lowest grade's yield.
bool IsSteel(const std::string& material) { return material == "steel" || material == "nonmag"; }

void Consider(LimitUtilisation& largest, const char* limit, double utilisation, const NodeLimits& node) {
  if (!std::isfinite(utilisation)) return;
  if (!std::isfinite(largest.utilisation) || utilisation > largest.utilisation) {
    largest = {limit, utilisation, node.s, node.md, node.component};
  }
}

// The stretches of stations at or beyond `state` (sorted by MD, shallower end first).
void AddZones(const std::vector<NodeLimits>& nodes, BucklingState state, std::vector<BuckledZone>& zones) {
  bool open = false;
  BuckledZone zone;
  zone.state = state;
  for (const NodeLimits& node : nodes) {
    const bool in = node.buckling >= state;
    if (in && !open) zone.md_from = zone.md_to = node.md, open = true;
    if (in) zone.md_from = std::min(zone.md_from, node.md), zone.md_to = std::max(zone.md_to, node.md);
    if (!in && open) zones.push_back(zone), open = false;
  }
  if (open) zones.push_back(zone);
}

// The fatigue screen of a rotating station (LoadStationLimits): node's yield and (in a well) the hole's
// curvature set, result its section forces.
void ScreenFatigue(const model::ModelInput& input, const model::Component& component, const StaticNodeResult& result,
                   NodeLimits& node) {
  const fe::HollowSection body{component.outer_diameter, component.inner_diameter};
  const double modulus = input.materials.at(component.material).youngs_modulus;
  const double stiffness = modulus * body.second_moment();
  const double tension = std::max(result.axial_force, 0.0);
  node.fatigue_bending_stress = std::abs(result.bending_moment) * 0.5 * body.outer_diameter / body.second_moment();
  const bool jointed = component.type == model::ComponentType::Pipe || component.type == model::ComponentType::Hwdp;
  const double half_spacing = 0.5 * component.joint_spacing.value_or(component.length);
  node.allowable_bending_stress = model::AllowableBendingStress(tension / body.area(), node.yield);
  if (std::isfinite(node.hole_curvature) && jointed) {
    node.dogleg_bending_stress = model::DoglegBendingStress(node.hole_curvature, modulus, body.outer_diameter,
                                                            tension, stiffness, half_spacing);
    node.fatigue_bending_stress = std::max(node.fatigue_bending_stress, node.dogleg_bending_stress);
    node.max_dogleg = model::MaxPermissibleCurvature(node.allowable_bending_stress, modulus, body.outer_diameter,
                                                     tension, stiffness, half_spacing);
  }
  // The tension alone past the endurance line (beyond yield already): a stress of 1 Pa allowed, the
  // utilisation finite and huge.
  node.fatigue_utilisation = node.fatigue_bending_stress / std::max(node.allowable_bending_stress, 1.0);
}

}  // namespace

const char* BucklingStateName(BucklingState state) {
  switch (state) {
    case BucklingState::NotScreened: return "not screened";
    case BucklingState::None: return "none";
    case BucklingState::Sinusoidal: return "sinusoidal";
    case BucklingState::Helical: return "helical";
  }
  return "none";
}

BucklingLoads BucklingLoadsAt(const model::ModelInput& input, double s, double md) {
  if (!input.well || input.well->hole.empty()) return {kNoLimit, kNoLimit};
  const model::Component& component = model::ComponentAt(input.string, s);
  // r of the component as a whole: the pipe lies on its tool joints (a stabilizer on its blades) all
  // along a buckle, which spans many joints; not the clearance at the station itself, which would
  // alternate between the joint's and the body's along every joint.
  const double clearance = 0.5 * (input.well->hole.Diameter(input.bit_md - s) - model::ContactDiameter(component));
  const fe::HollowSection body{component.outer_diameter, component.inner_diameter};
  const double stiffness = input.materials.at(component.material).youngs_modulus * body.second_moment();
  const double weight = std::abs(model::BuoyedWeightPerLength(component, input));
  const double inclined =
      model::SinusoidalBucklingLoad(stiffness, weight, input.well->trajectory.Inclination(md), clearance);
  return {std::max(inclined, model::VerticalSinusoidalBucklingLoad(stiffness, weight)),
          std::max(model::HelicalBucklingLoad(inclined), model::VerticalHelicalBucklingLoad(stiffness, weight))};
}

NodeLimits StationRatings(const model::ModelInput& input, double s, double md, double design_factor) {
  NodeLimits node;
  node.s = s;
  node.md = md;
  const model::Component& component = model::ComponentAt(input.string, s);
  node.component = &component - input.string.components.data();
  if (component.type != model::ComponentType::Bit) {
    if (component.yield_strength) {
      node.yield = *component.yield_strength;
    } else if (IsSteel(component.material)) {
      node.yield = model::FindSteelGrade(model::kDefaultGrade)->yield;
    }
    node.allowable_stress = node.yield / design_factor;
    const bool rotating = input.operation.rotary_speed > 0.0;
    if (rotating && std::isfinite(node.yield) && input.well) {
      node.hole_curvature = input.well->trajectory.Curvature(node.md).norm();
    }
  }
  if (component.makeup_torque) node.makeup_torque = *component.makeup_torque;
  const BucklingLoads buckling = BucklingLoadsAt(input, node.s, node.md);
  node.sinusoidal_load = buckling.sinusoidal;
  if (std::isfinite(node.sinusoidal_load)) node.helical_load = buckling.helical;
  return node;
}

void LoadStationLimits(const model::ModelInput& input, const StaticNodeResult& result, NodeLimits& node) {
  const model::Component& component = input.string.components[node.component];
  node.von_mises_stress =
      model::VonMisesStress(model::RatedSection(component), result.axial_force, result.torque, result.bending_moment);
  if (component.type != model::ComponentType::Bit) {
    node.stress_utilisation = node.von_mises_stress / node.allowable_stress;
    if (input.operation.rotary_speed > 0.0 && std::isfinite(node.yield)) ScreenFatigue(input, component, result, node);
  }
  if (std::isfinite(node.makeup_torque)) node.torque_utilisation = std::abs(result.torque) / node.makeup_torque;
  node.compression = -result.axial_force;
  if (std::isfinite(node.sinusoidal_load) && node.helical_load > 0.0) {
    node.buckling_utilisation = std::max(node.compression, 0.0) / node.helical_load;
    node.buckling = node.compression >= node.helical_load      ? BucklingState::Helical
                    : node.compression >= node.sinusoidal_load ? BucklingState::Sinusoidal
                                                               : BucklingState::None;
  }
}

StringLimits ComputeStringLimits(const model::ModelInput& input, const std::vector<StaticNodeResult>& nodes,
                                 double design_factor) {
  StringLimits limits;
  limits.design_factor = design_factor;
  const auto& components = input.string.components;
  std::set<int> assumed;  // components whose yield is taken as E-75's
  bool any_torque_limit = false;
  for (const StaticNodeResult& result : nodes) {
    const double md = result.has_wall ? result.md : (input.well ? input.bit_md - result.s : result.s);
    NodeLimits node = StationRatings(input, result.s, md, design_factor);
    LoadStationLimits(input, result, node);
    const model::Component& component = components[node.component];
    if (std::isfinite(node.yield) && !component.yield_strength) assumed.insert(node.component);
    any_torque_limit = any_torque_limit || std::isfinite(node.makeup_torque);
    Consider(limits.yield, "yield", node.stress_utilisation, node);
    Consider(limits.makeup_torque, "makeup_torque", node.torque_utilisation, node);
    Consider(limits.helical_buckling, "helical_buckling", node.buckling_utilisation, node);
    Consider(limits.fatigue, "fatigue", node.fatigue_utilisation, node);
    limits.nodes.push_back(node);
  }
  AddZones(limits.nodes, BucklingState::Sinusoidal, limits.zones);
  AddZones(limits.nodes, BucklingState::Helical, limits.zones);
  for (const LimitUtilisation* each :
       {&limits.yield, &limits.makeup_torque, &limits.helical_buckling, &limits.fatigue}) {
    if (std::isfinite(each->utilisation) &&
        (!std::isfinite(limits.closest.utilisation) || each->utilisation > limits.closest.utilisation)) {
      limits.closest = *each;
    }
  }
  const double default_yield = model::FindSteelGrade(model::kDefaultGrade)->yield;
  if (!assumed.empty()) {
    // One note for every component rated by default (a BHA's collars and tools seldom carry a grade).
    std::string names;
    std::set<std::string> named;  // a name given to two components once
    for (const int index : assumed) {
      if (named.insert(components[index].name).second) names += (names.empty() ? "'" : ", '") + components[index].name + "'";
    }
    limits.notes.push_back(fmt::format("{}: no grade or yield given, {} utilisation taken against {} ({:.0f} ksi), "
                                       "the lowest grade",
                                       names, assumed.size() == 1 ? "its" : "their", model::kDefaultGrade,
                                       default_yield / model::kPascalPerKsi));
  }
  if (!any_torque_limit) limits.notes.emplace_back("no make-up torque given: no torque limit");
  return limits;
}

std::vector<DoglegFatigue> FatigueDoglegs(const StringLimits& limits) {
  std::vector<DoglegFatigue> doglegs;
  bool open = false;
  for (const NodeLimits& node : limits.nodes) {
    const bool in = std::isfinite(node.fatigue_utilisation) && node.hole_curvature > kDoglegCurvature;
    if (!in) {
      open = false;
      continue;
    }
    if (!open) doglegs.push_back({node.md, node.md, node.fatigue_utilisation, node.md, node.hole_curvature, node.component});
    open = true;
    DoglegFatigue& dogleg = doglegs.back();
    dogleg.md_from = std::min(dogleg.md_from, node.md);
    dogleg.md_to = std::max(dogleg.md_to, node.md);
    if (node.fatigue_utilisation > dogleg.utilisation) {
      dogleg = {dogleg.md_from, dogleg.md_to, node.fatigue_utilisation, node.md, node.hole_curvature, node.component};
    }
  }
  std::sort(doglegs.begin(), doglegs.end(),
            [](const DoglegFatigue& a, const DoglegFatigue& b) { return a.md_from < b.md_from; });
  return doglegs;
}

}  // namespace drillflex::analyses
