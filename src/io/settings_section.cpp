// Reads `fluid:`, `model:`, `supports:`, `loads:` and `operation:`.
#include <cmath>

#include <fmt/format.h>

#include "io/case_sections.hpp"

namespace drillflex::io {
namespace {

using units::Quantity;

std::array<bool, 6> ReadFixedDofs(const YamlView& node) {
  std::array<bool, 6> fixed{};
  static const std::vector<std::string> names = {"x", "y", "z", "rx", "ry", "rz"};
  auto read_one = [&](const YamlView& item) {
    const std::string name = item.AsString();
    if (name == "all") { fixed.fill(true); return; }
    for (std::size_t d = 0; d < names.size(); ++d) {
      if (names[d] == name) { fixed[d] = true; return; }
    }
    item.Fail(fmt::format("unknown degree of freedom '{}'; expected x, y, z, rx, ry, rz or all", name));
  };
  if (node.IsScalar()) {
    read_one(node);
  } else {
    node.ExpectSequence("degrees of freedom to fix, e.g. [x, y, z]");
    for (std::size_t i = 0; i < node.size(); ++i) read_one(node.Item(i));
  }
  return fixed;
}

}  // namespace

model::FluidConfig ReadFluidSection(const YamlView& node) {
  node.ExpectMap("the drilling fluid {density, viscosity}", false);
  node.AllowOnlyKeys({"density", "viscosity", "internal_density", "added_mass_coefficient"});
  model::FluidConfig fluid;
  fluid.density = node.Positive("density", Quantity::Density);
  fluid.viscosity = node.QuantityOr("viscosity", Quantity::Viscosity, 0.0);
  if (fluid.viscosity < 0.0) node.Child("viscosity").Fail("the viscosity must not be negative");
  if (const auto inside = node.OptionalChild("internal_density")) {
    fluid.internal_density = inside->AsQuantity(Quantity::Density);
    if (*fluid.internal_density < 0.0) inside->Fail("the density must not be negative");
  }
  if (const auto cm = node.OptionalChild("added_mass_coefficient")) {
    fluid.added_mass_coefficient_override = cm->AsQuantity(Quantity::Dimensionless);
    if (fluid.added_mass_coefficient_override < 0.0) cm->Fail("expected a coefficient >= 0");
  }
  return fluid;
}

model::ModelSettings ReadModelSection(const YamlView& node) {
  node.ExpectMap("the model settings");
  node.AllowOnlyKeys({"body_length", "elements_per_body", "modes_per_body", "coupling_factor",
                      "structural_damping", "contact", "mass", "beam", "rotary_inertia",
                      "bending_stiffness_factor", "top"});
  model::ModelSettings settings;
  if (node.IsNull()) return settings;
  settings.body_length = node.OptionalPositive("body_length", Quantity::Length).value_or(settings.body_length);
  settings.elements_per_body = node.IntegerOr("elements_per_body", settings.elements_per_body);
  if (settings.elements_per_body < 1 || settings.elements_per_body > 200) {
    node.Child("elements_per_body").Fail("expected between 1 and 200 elements per body");
  }
  settings.modes_per_body = node.IntegerOr("modes_per_body", settings.modes_per_body);
  const int max_modes = 6 * (settings.elements_per_body - 1);  // the internal DOF of one body
  if (settings.modes_per_body < 0 || settings.modes_per_body > max_modes) {
    (node.Has("modes_per_body") ? node.Child("modes_per_body") : node)
        .Fail(fmt::format("expected between 0 and {} modes per body (6 x (elements_per_body - 1))", max_modes));
  }
  settings.coupling_factor = node.OptionalPositive("coupling_factor", Quantity::Dimensionless)
                                 .value_or(settings.coupling_factor);
  settings.structural_damping = node.QuantityOr("structural_damping", Quantity::Dimensionless,
                                                settings.structural_damping);
  if (settings.structural_damping < 0.0) node.Child("structural_damping").Fail("expected a damping ratio >= 0");
  if (const auto mass = node.OptionalChild("mass")) {
    const std::string kind = mass->AsString();
    if (kind == "consistent") settings.mass = fe::MassKind::kConsistent;
    else if (kind == "lumped") settings.mass = fe::MassKind::kLumped;
    else mass->Fail(fmt::format("expected 'consistent' or 'lumped', got '{}'", kind));
  }
  if (const auto beam = node.OptionalChild("beam")) {
    const std::string kind = beam->AsString();
    if (kind == "euler_bernoulli") settings.beam = fe::BeamTheory::kEulerBernoulli;
    else if (kind == "timoshenko") settings.beam = fe::BeamTheory::kTimoshenko;
    else beam->Fail(fmt::format("expected 'euler_bernoulli' or 'timoshenko', got '{}'", kind));
  }
  if (const auto rotary = node.OptionalChild("rotary_inertia")) settings.rotary_inertia = rotary->AsBool();
  settings.bending_stiffness_factor = node.OptionalPositive("bending_stiffness_factor", Quantity::Dimensionless)
                                          .value_or(settings.bending_stiffness_factor);
  if (settings.bending_stiffness_factor > 1e3) {
    node.Child("bending_stiffness_factor").Fail("expected a factor of the sections' bending stiffness EI, > 0 and <= 1000");
  }
  if (const auto top = node.OptionalChild("top")) {
    const std::string kind = top->AsString();
    if (kind == "string_above") settings.top = model::TopCondition::StringAbove;
    else if (kind == "free") settings.top = model::TopCondition::Free;
    else if (kind == "guided") settings.top = model::TopCondition::Guided;
    else top->Fail(fmt::format("expected 'string_above', 'free' or 'guided', got '{}'", kind));
  }
  if (const auto contact = node.OptionalChild("contact")) {
    contact->ExpectMap("the contact settings {stiffness, damping_ratio, friction}");
    contact->AllowOnlyKeys(
        {"stiffness", "penetration_fraction", "damping_ratio", "friction", "axial_friction", "friction_velocity"});
    auto& c = settings.contact;
    c.stiffness = contact->OptionalPositive("stiffness", Quantity::Stiffness).value_or(c.stiffness);
    c.penetration_fraction =
        contact->QuantityOr("penetration_fraction", Quantity::Dimensionless, c.penetration_fraction);
    if (!(c.penetration_fraction >= 0.0 && c.penetration_fraction < 1.0)) {
      contact->Child("penetration_fraction").Fail("expected a fraction of the radial clearance, 0 <= x < 1 (0: off)");
    }
    c.damping_ratio = contact->QuantityOr("damping_ratio", Quantity::Dimensionless, c.damping_ratio);
    c.friction = contact->QuantityOr("friction", Quantity::Dimensionless, c.friction);
    c.axial_friction = contact->OptionalQuantity("axial_friction", Quantity::Dimensionless);
    c.friction_velocity = contact->OptionalPositive("friction_velocity", Quantity::Velocity);
    if (c.damping_ratio < 0.0) contact->Child("damping_ratio").Fail("expected a damping ratio >= 0");
    if (c.friction < 0.0) contact->Child("friction").Fail("expected a friction coefficient >= 0");
    if (c.axial_friction && *c.axial_friction < 0.0) contact->Child("axial_friction").Fail("expected a friction coefficient >= 0");
  }
  return settings;
}

std::vector<model::Support> ReadSupportsSection(const YamlView& node) {
  node.ExpectSequence("supports [{at, fix}]");
  std::vector<model::Support> supports;
  for (std::size_t i = 0; i < node.size(); ++i) {
    const YamlView item = node.Item(i);
    item.ExpectMap("a support {at, fix}", false);
    item.AllowOnlyKeys({"at", "fix"});
    model::Support support;
    support.at = item.Quantity("at", Quantity::Length);
    support.fixed = ReadFixedDofs(item.Child("fix"));
    support.source_line = item.location().line;
    supports.push_back(support);
  }
  return supports;
}

std::vector<model::Load> ReadLoadsSection(const YamlView& node) {
  node.ExpectSequence("loads [{at, force}, {from, to, per_length}, ...]");
  std::vector<model::Load> loads;
  for (std::size_t i = 0; i < node.size(); ++i) {
    const YamlView item = node.Item(i);
    item.ExpectMap("a load", false);
    item.AllowOnlyKeys({"at", "from", "to", "force", "moment", "per_length", "moment_per_length"});
    model::Load load;
    load.source_line = item.location().line;
    load.distributed = item.Has("from") || item.Has("to");
    if (load.distributed) {
      if (item.Has("at")) item.Child("at").Fail("a load has either 'at' (a point) or 'from' and 'to' (distributed)");
      load.from = item.Quantity("from", Quantity::Length);
      load.to = item.Quantity("to", Quantity::Length);
      if (!(load.to > load.from)) item.Child("to").Fail("'to' must lie beyond 'from'");
      if (item.Has("force") || item.Has("moment")) item.Fail("a distributed load takes 'per_length' and 'moment_per_length'");
      if (const auto q = item.OptionalChild("per_length")) load.force_per_length = q->AsVector3(Quantity::ForcePerLength);
      if (const auto m = item.OptionalChild("moment_per_length")) load.moment_per_length = m->AsVector3(Quantity::Force);
      if (!item.Has("per_length") && !item.Has("moment_per_length")) item.Fail("a distributed load needs 'per_length' or 'moment_per_length'");
    } else {
      load.at = item.Quantity("at", Quantity::Length);
      if (item.Has("per_length") || item.Has("moment_per_length")) item.Fail("a point load takes 'force' and 'moment'; a distributed one needs 'from' and 'to'");
      if (const auto f = item.OptionalChild("force")) load.force = f->AsVector3(Quantity::Force);
      if (const auto m = item.OptionalChild("moment")) load.moment = m->AsVector3(Quantity::Moment);
      if (!item.Has("force") && !item.Has("moment")) item.Fail("a point load needs 'force' or 'moment'");
    }
    loads.push_back(load);
  }
  return loads;
}

namespace {

// The operating point's plausible bounds, in field units (the lab rotors of the validation spin at
// 30 000 rpm): far beyond any rig's.
constexpr double kMaxRpm = 100000.0, kMaxWobLbf = 1.0e6, kMaxTorqueFtLbf = 2.0e5, kMaxHookLoadLbf = 5.0e6,
                 kMaxFlowGpm = 5000.0;

double FieldToSI(double value, Quantity quantity) { return units::ToSI(value, quantity, units::System::Field); }

}  // namespace

model::Operation ReadOperationSection(const YamlView& node) {
  node.ExpectMap("the operating point {wob, rpm, torque_on_bit}");
  node.AllowOnlyKeys({"wob", "rpm", "torque_on_bit", "flow_rate", "hook_load"});
  model::Operation operation;
  if (node.IsNull()) return operation;
  operation.weight_on_bit = node.QuantityOr("wob", Quantity::WeightOnBit, 0.0);
  operation.rotary_speed = node.QuantityOr("rpm", Quantity::RotarySpeed, 0.0);
  operation.torque_on_bit = node.QuantityOr("torque_on_bit", Quantity::Moment, 0.0);
  operation.flow_rate = node.OptionalQuantity("flow_rate", Quantity::FlowRate);
  operation.hook_load = node.OptionalQuantity("hook_load", Quantity::Force);
  if (operation.weight_on_bit < 0.0) node.Child("wob").Fail("the WOB must not be negative (it is the compression at the bit)");
  if (operation.hook_load) {
    if (node.Has("wob")) {
      node.Child("hook_load").Fail("give the WOB or the hook load, not both: a hook load sets the WOB (the string's "
                                   "buoyed weight along the hole less the hook load)");
    }
    if (*operation.hook_load < 0.0) node.Child("hook_load").Fail("the hook load must not be negative (it is the tension the hook holds)");
  }
  if (operation.flow_rate && *operation.flow_rate < 0.0) node.Child("flow_rate").Fail("the flow rate must not be negative");
  if (operation.rotary_speed < 0.0) {
    node.Child("rpm").Fail("the rotary speed must not be negative (the string turns clockwise looking down-hole)");
  }
  // Plausible bounds, far beyond any rig's (as E and density have): a value past them is a unit or a
  // typing slip, refused before anything is solved rather than after a solve that cannot converge.
  auto at_most = [&](const char* key, double value, double bound, const char* what) {
    if (std::abs(value) > bound) {
      node.Child(key).Fail(fmt::format("expected at most {} ({:.6g} in SI), got {:.6g} in SI", what, bound, value));
    }
  };
  at_most("rpm", operation.rotary_speed, FieldToSI(kMaxRpm, Quantity::RotarySpeed), "100 000 rpm");
  at_most("wob", operation.weight_on_bit, FieldToSI(kMaxWobLbf, Quantity::Force), "1000 klbf");
  at_most("torque_on_bit", operation.torque_on_bit, FieldToSI(kMaxTorqueFtLbf, Quantity::Moment), "200 000 ft*lbf");
  if (operation.hook_load) at_most("hook_load", *operation.hook_load, FieldToSI(kMaxHookLoadLbf, Quantity::Force), "5000 klbf");
  if (operation.flow_rate) at_most("flow_rate", *operation.flow_rate, FieldToSI(kMaxFlowGpm, Quantity::FlowRate), "5000 gpm");
  return operation;
}

}  // namespace drillflex::io
