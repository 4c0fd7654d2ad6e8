// Checks across sections: the string fits the hole, lies inside the well, and every position
// given along it (supports, loads, excitations, probes) is on it.
#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "io/case_sections.hpp"
#include "well/hole.hpp"

namespace drillflex::io {
namespace {

using units::Quantity;

std::string Show(double si, Quantity quantity, units::System system) {
  return fmt::format("{:.6g} {}", units::FromSI(si, quantity, system), units::DefaultUnit(quantity, system));
}

void CheckStringFitsHole(const Case& c, const YamlView& root) {
  const WellConfig& well = *c.well;
  const units::System system = c.units;
  const well::HoleProfile hole(well.hole);
  const double length = StringLength(c);
  const double top_md = well.bit_md - length;
  if (top_md < well.survey.front().md - 1e-9) {
    root.Child("string").Fail(fmt::format(
        "the string ({}) is longer than the well above the bit (bit MD {}, first survey station {})",
        Show(length, Quantity::Length, system), Show(well.bit_md, Quantity::Length, system),
        Show(well.survey.front().md, Quantity::Length, system)));
  }
  double s = 0.0;  // distance of the item's bottom from the bit
  for (std::size_t i = 0; i < c.input.string.components.size(); ++i) {
    const model::Component& component = c.input.string.components[i];
    const double span = component.length * component.count;
    const double md_bottom = well.bit_md - s;
    const double md_top = md_bottom - span;
    const double needed = model::ContactDiameter(component);
    const double available = hole.MinDiameter(md_top, md_bottom);
    if (needed > available * (1.0 + 1e-9)) {
      root.Child("string").Item(i).Fail(fmt::format(
          "the {} ({} across its largest diameter) does not fit the hole: {} between MD {} and {}",
          component.name, Show(needed, Quantity::Diameter, system), Show(available, Quantity::Diameter, system),
          Show(md_top, Quantity::Length, system), Show(md_bottom, Quantity::Length, system)));
    }
    s += span;
  }
}

// The builder cuts the string into bodies at most model.body_length long (model/builder.cpp), a few
// kB each: a string of 1e9 m at 3 m would be 3e8 bodies and gigabytes before any message. 20 000 is
// twenty times the largest case shipped (10 000 ft of pipe in 3 m bodies).
constexpr double kMaxBodies = 20000;

void CheckModelSize(const Case& c, const YamlView& root) {
  const double body_length = c.input.settings.body_length;
  double bodies = 0.0;
  for (const model::Component& component : c.input.string.components) {
    bodies += std::ceil(component.length * component.count / body_length);
  }
  if (!(bodies <= kMaxBodies)) {
    root.Child("string").Fail(fmt::format(
        "the model would cut the string ({}) into {:.3g} bodies of at most model.body_length ({}): at most {:.0f}; "
        "give a longer body_length",
        Show(StringLength(c), Quantity::Length, c.units), bodies, Show(body_length, Quantity::Length, c.units),
        kMaxBodies));
  }
}

void CheckOnString(double at, double length, const YamlView& item, const char* key, units::System system) {
  if (at < -1e-9 || at > length * (1.0 + 1e-12)) {
    item.Child(key).Fail(fmt::format("{} lies off the string, which runs from 0 to {} from the bit",
                                     Show(at, Quantity::Length, system), Show(length, Quantity::Length, system)));
  }
}

}  // namespace

void CheckCaseConsistency(const Case& c, const YamlView& root) {
  CheckModelSize(c, root);
  const double length = StringLength(c);
  const units::System system = c.units;
  if (c.well) CheckStringFitsHole(c, root);
  for (std::size_t i = 0; i < c.input.supports.size(); ++i) {
    CheckOnString(c.input.supports[i].at, length, root.Child("supports").Item(i), "at", system);
  }
  // Loads (the case's, or a transient's initial ones) listed at `list`.
  auto check_loads = [&](const std::vector<model::Load>& loads, const YamlView& list) {
    for (std::size_t i = 0; i < loads.size(); ++i) {
      const model::Load& load = loads[i];
      const YamlView item = list.Item(i);
      if (load.distributed) {
        CheckOnString(load.from, length, item, "from", system);
        CheckOnString(load.to, length, item, "to", system);
      } else {
        CheckOnString(load.at, length, item, "at", system);
      }
    }
  };
  if (!c.input.loads.empty()) check_loads(c.input.loads, root.Child("loads"));
  if (c.analyses.vibration) {
    const auto& excitations = c.analyses.vibration->excitations;
    for (std::size_t i = 0; i < excitations.size(); ++i) {
      if (excitations[i].type != analyses::ExcitationType::Imbalance) continue;
      CheckOnString(excitations[i].at, length,
                    root.Child("analyses").Child("vibration").Child("excitations").Item(i), "at", system);
    }
  }
  if (c.analyses.transient) {
    const auto& probes = c.analyses.transient->probes;
    const YamlView list = root.Child("analyses").Child("transient");
    const auto& initial = c.analyses.transient->initial_loads;
    if (!initial.empty()) check_loads(initial, list.Child("initial_loads"));
    const auto& imbalances = c.analyses.transient->imbalances;
    for (std::size_t i = 0; i < imbalances.size(); ++i) {
      CheckOnString(imbalances[i].at, length, list.Child("excitations").Item(i), "at", system);
    }
    for (std::size_t i = 0; i < probes.size(); ++i) {
      if (probes[i] < 0.0 || probes[i] > length * (1.0 + 1e-12)) {
        list.Child("probes").Item(i).Fail(fmt::format(
            "the probe at {} lies off the string (0 to {})", Show(probes[i], Quantity::Length, system),
            Show(length, Quantity::Length, system)));
      }
    }
  }
}

}  // namespace drillflex::io
