// `drillflex check CASE`: read and validate a case, and print what it describes in its own units.
#include <algorithm>
#include <iostream>

#include <fmt/format.h>

#include "app/commands.hpp"
#include "io/case.hpp"
#include "pipeline/case_run.hpp"
#include "well/hole.hpp"
#include "well/trajectory.hpp"

namespace drillflex::app {
namespace {

using units::Quantity;

class Printer {
 public:
  explicit Printer(units::System system) : system_(system) {}
  std::string operator()(double si, Quantity quantity, int precision = 4) const {
    return fmt::format("{:.{}g} {}", units::FromSI(si, quantity, system_), precision,
                       units::DefaultUnit(quantity, system_));
  }

 private:
  units::System system_;
};

void PrintWell(const io::Case& c, const Printer& show) {
  if (!c.well) {
    std::cout << "well: none (the string lies straight along +x from the origin; no hole, no contact)\n";
    return;
  }
  const io::WellConfig& well = *c.well;
  const well::Trajectory trajectory(well.survey);
  double max_inclination = 0.0, max_inclination_md = 0.0, max_dls = 0.0, max_dls_md = 0.0;
  for (std::size_t i = 0; i < well.survey.size(); ++i) {
    if (well.survey[i].inclination > max_inclination) {
      max_inclination = well.survey[i].inclination;
      max_inclination_md = well.survey[i].md;
    }
    if (i == 0) continue;
    const double mid = 0.5 * (well.survey[i - 1].md + well.survey[i].md);
    if (trajectory.DoglegSeverity(mid) > max_dls * (1.0 + 1e-9) + 1e-15) {
      max_dls = trajectory.DoglegSeverity(mid);
      max_dls_md = well.survey[i - 1].md;
    }
  }
  const double td = well.survey.back().md;
  std::cout << fmt::format("well: TD {} MD, {} TVD; {} survey stations{}\n", show(td, Quantity::Length, 6),
                           show(trajectory.Position(td).z(), Quantity::Length, 6), well.survey.size(),
                           well.survey_file.empty() ? "" : " from " + well.survey_file);
  std::cout << fmt::format("  max inclination {} at {} MD; max DLS {} (first in the section from {} MD)\n",
                           show(max_inclination, Quantity::Angle), show(max_inclination_md, Quantity::Length, 6),
                           show(max_dls, Quantity::DoglegSeverity, 3), show(max_dls_md, Quantity::Length, 6));
  std::string hole;
  for (const auto& section : well.hole) {
    hole.append(hole.empty() ? "" : ", ").append(show(section.diameter, Quantity::Diameter));
    hole.append(section.to_md ? " to " + show(*section.to_md, Quantity::Length, 6) : " to TD");
  }
  std::cout << fmt::format("  hole: {}; bit at {} MD\n", hole, show(well.bit_md, Quantity::Length, 6));
}

void PrintString(const io::Case& c, const Printer& show) {
  double length = 0.0, weight_air = 0.0, weight_mud = 0.0;
  const double rho_out = c.input.fluid ? c.input.fluid->density : 0.0;
  const double rho_in = c.input.fluid ? c.input.fluid->internal_density.value_or(c.input.fluid->density) : 0.0;
  std::cout << fmt::format("string: {} entries, from the bit upward\n", c.input.string.components.size());
  std::cout << fmt::format("  {:>3} {:<12} {:<18} {:>12} {:>12} {:>12} {:>5} {:>14}\n", "#", "type", "name",
                           "OD", "ID", "length", "count", "top from bit");
  for (std::size_t i = 0; i < c.input.string.components.size(); ++i) {
    const auto& component = c.input.string.components[i];
    const double span = component.length * component.count;
    const auto areas = model::AverageAreas(component);
    const double density = c.input.materials.at(component.material).density;
    // Buoyed weight with fluid inside and out: w = g (ρ_s A − ρ_f A_o + ρ_fi A_i) (method.md §7).
    weight_air += c.input.gravity * density * areas.material * span;
    weight_mud += c.input.gravity * (density * areas.material - rho_out * areas.outer + rho_in * areas.bore) * span;
    length += span;
    std::cout << fmt::format("  {:>3} {:<12} {:<18} {:>12} {:>12} {:>12} {:>5} {:>14}\n", i,
                             model::ComponentTypeName(component.type), component.name,
                             show(component.outer_diameter, Quantity::Diameter),
                             show(component.inner_diameter, Quantity::Diameter),
                             show(component.length, Quantity::Length), component.count,
                             show(length, Quantity::Length, 6));
  }
  std::cout << fmt::format("  length {}; weight in air {}", show(length, Quantity::Length, 6),
                           show(weight_air, Quantity::Force, 6));
  if (c.input.fluid) {
    std::cout << fmt::format(", in {} mud {}", show(c.input.fluid->density, Quantity::Density),
                             show(weight_mud, Quantity::Force, 6));
  }
  std::cout << fmt::format(" (g = {:.5g} m/s2)\n", c.input.gravity);
}

void PrintModel(const io::Case& c) {
  const pipeline::CaseModel case_model = pipeline::BuildCaseModel(c);
  const model::BuiltModel& built = case_model.built;
  const cms::ReductionCache& cache = *case_model.cache;
  const auto& settings = c.input.settings;
  std::cout << fmt::format(
      "model: {} flexible bodies ({} distinct reductions), {} coordinates, {} couplings, {} supports, {} wall "
      "contacts\n",
      built.system.bodies().size(), cache.size(), built.system.num_velocities(),
      built.system.bodies().empty() ? 0 : built.system.bodies().size() - 1, built.supports.size(),
      built.contacts.size());
  std::cout << fmt::format("  {} elements and {} fixed-interface modes a body, coupling factor {:g}\n",
                           settings.elements_per_body, settings.modes_per_body, settings.coupling_factor);
}

// "; top drive 100 rpm in 1 s, block 0.5 ft/s in 2 s": the transient's drives (model/drives.hpp).
std::string DrivesText(const analyses::TransientSettings& t, const Printer& show) {
  std::string text;
  const auto ramp = [&](const model::LinearRamp& r) {
    return r.ramp_time > 0.0 ? fmt::format(" in {}", show(r.ramp_time, Quantity::Time)) : std::string();
  };
  if (t.top_drive) {
    const bool speed = t.top_drive->mode == model::TopDriveMode::Speed;
    text += fmt::format("; top drive {}{}", show(t.top_drive->setting.target, speed ? Quantity::RotarySpeed : Quantity::Moment),
                        ramp(t.top_drive->setting));
  }
  if (t.block) {
    const bool velocity = t.block->mode == model::BlockMode::Velocity;
    text += fmt::format("; block {}{}{}{}", velocity ? "" : "hook load ",
                        show(t.block->setting.target, velocity ? Quantity::Velocity : Quantity::Force),
                        ramp(t.block->setting),
                        t.block->line_stiffness
                            ? fmt::format(" through a line of {}", show(*t.block->line_stiffness, Quantity::Stiffness))
                            : std::string());
  }
  return text;
}

void PrintAnalyses(const io::Case& c, const Printer& show) {
  std::vector<std::string> names;
  const auto& a = c.analyses;
  if (a.static_analysis) names.push_back("static");
  if (a.modes) names.push_back(fmt::format("modes ({})", a.modes->count));
  if (a.vibration) names.push_back(fmt::format("vibration ({} excitations)", a.vibration->excitations.size()));
  if (a.buckling) names.push_back("buckling");
  if (a.transient) {
    names.push_back(fmt::format("transient ({:.4g} s{})", a.transient->duration, DrivesText(*a.transient, show)));
  }
  std::string list;
  for (const auto& name : names) list.append(list.empty() ? "" : ", ").append(name);
  std::cout << "analyses: " << (list.empty() ? "none listed" : list) << "\n";
}

}  // namespace

int RunCheck(const CommandOptions& options) {
  const io::Case c = io::ReadCase(options.case_path);
  const Printer show(c.units);
  std::cout << fmt::format("case: {} ({}), units: {}, results in {} units\n", c.name, c.file,
                           units::SystemName(c.units), units::SystemName(c.output_units));
  PrintWell(c, show);
  if (c.input.fluid) {
    std::cout << fmt::format("fluid: {}, {}\n", show(c.input.fluid->density, Quantity::Density),
                             show(c.input.fluid->viscosity, Quantity::Viscosity));
  }
  PrintString(c, show);
  PrintModel(c);
  PrintAnalyses(c, show);
  for (const std::string& warning : c.warnings) std::cout << "warning: " << warning << "\n";
  std::cout << "the case is valid\n";
  return kExitOk;
}

}  // namespace drillflex::app
