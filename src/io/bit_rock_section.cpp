// Reads `analyses.transient.bit_rock`: the law of the rock's reaction on the bit
// (model/bit_rock.hpp), Detournay's cutting and contact or a static/kinetic friction torque, and
// beside it the hole bottom as a contact (`bottom`, model/bit_bottom.hpp) and the bit's side
// cutting (`side_cutting`, model/bit_side_cutting.hpp).
#include <fmt/format.h>

#include "io/case_sections.hpp"

namespace drillflex::io {
namespace {

using units::Quantity;

// `bottom: {stiffness, damping_ratio, motion: {amplitude, frequency, ramp}}`.
model::BitBottomParameters ReadBottom(const YamlView& node) {
  node.ExpectMap("the bottom contact {stiffness, damping_ratio, motion}", true);
  node.AllowOnlyKeys({"stiffness", "damping_ratio", "motion"});
  model::BitBottomParameters p;
  p.stiffness = node.OptionalPositive("stiffness", Quantity::Stiffness).value_or(0.0);
  p.damping_ratio = node.QuantityOr("damping_ratio", Quantity::Dimensionless, p.damping_ratio);
  if (p.damping_ratio < 0.0) node.Child("damping_ratio").Fail("expected a damping ratio of 0 or more");
  if (const auto motion = node.OptionalChild("motion")) {
    motion->ExpectMap("the bottom's motion {amplitude, frequency, ramp}", false);
    motion->AllowOnlyKeys({"amplitude", "frequency", "ramp"});
    p.amplitude = motion->Positive("amplitude", Quantity::Diameter);
    p.frequency = motion->Positive("frequency", Quantity::Frequency);
    p.ramp_time = motion->QuantityOr("ramp", Quantity::Time, 0.0);
    if (p.ramp_time < 0.0) motion->Child("ramp").Fail("expected a ramp time of 0 or more");
  }
  return p;
}

// `side_cutting: {resistance}`: k_s, the side force that cuts 1 m sideways per revolution.
double ReadSideCutting(const YamlView& node) {
  node.ExpectMap("the side cutting {resistance}", false);
  node.AllowOnlyKeys({"resistance"});
  return node.Positive("resistance", Quantity::Stiffness);
}

}  // namespace

model::BitRockParameters ReadBitRockSection(const YamlView& node) {
  node.ExpectMap("the bit-rock interaction {law, ...}", false);
  model::BitRockParameters p;
  p.stick_speed = node.OptionalPositive("stick_speed", Quantity::RotarySpeed).value_or(model::kDefaultStickSpeed);
  // `bottom:` present even empty (`bottom: {}`, `bottom:`) switches the contact on with its defaults.
  if (const auto bottom = node.PresentChild("bottom")) p.bottom = ReadBottom(*bottom);
  if (const auto side = node.OptionalChild("side_cutting")) p.side_cutting = ReadSideCutting(*side);
  const std::string law = node.Has("law") ? node.Child("law").AsString() : "";
  if (law == "detournay") {
    node.AllowOnlyKeys({"law", "specific_energy", "cutting_ratio", "contact_force", "friction", "geometry", "radius",
                        "stick_speed", "contact_speed", "bottom", "side_cutting"});
    if (p.bottom) {
      node.Child("bottom").Fail(
          "a bottom contact does not go with law 'detournay': its WOB already is the rock's axial reaction, a law of "
          "the penetration rate (a bit pressing ahead cuts its way down, which a fixed bottom would stop); use the "
          "'friction' law or no law with 'bottom'");
    }
    p.law = model::BitRockLaw::Detournay;
    p.specific_energy = node.Positive("specific_energy", Quantity::Stress);
    p.cutting_ratio = node.Positive("cutting_ratio", Quantity::Dimensionless);
    p.contact_force = node.QuantityOr("contact_force", Quantity::Force, 0.0);
    if (p.contact_force < 0.0) node.Child("contact_force").Fail("expected a contact force of 0 or more");
    p.friction = node.QuantityOr("friction", Quantity::Dimensionless, 0.0);
    if (p.friction < 0.0) node.Child("friction").Fail("expected a friction coefficient of 0 or more");
    if (p.contact_force > 0.0 && !node.Has("friction")) {
      node.Fail("a wear-flat contact_force needs its friction coefficient 'friction' (mu)");
    }
    p.geometry = node.OptionalPositive("geometry", Quantity::Dimensionless).value_or(1.0);
    p.radius = node.OptionalPositive("radius", Quantity::Diameter).value_or(0.0);
    p.contact_speed = node.OptionalPositive("contact_speed", Quantity::Velocity).value_or(model::kDefaultContactSpeed);
  } else if (law == "friction") {
    node.AllowOnlyKeys({"law", "static_torque", "kinetic_torque", "stick_speed", "stribeck_speed", "bottom", "side_cutting"});
    p.law = model::BitRockLaw::Friction;
    p.static_torque = node.Positive("static_torque", Quantity::Moment);
    p.kinetic_torque = node.Quantity("kinetic_torque", Quantity::Moment);
    if (p.kinetic_torque < 0.0) node.Child("kinetic_torque").Fail("expected a kinetic torque of 0 or more");
    if (!(p.static_torque > p.kinetic_torque)) {
      node.Child("static_torque").Fail("the static friction torque must exceed the kinetic one (stick-slip needs T_s > T_d)");
    }
    p.stribeck_speed = node.OptionalPositive("stribeck_speed", Quantity::RotarySpeed).value_or(p.stick_speed);
  } else if (!node.Has("law")) {
    // No torque law: the case's torque on bit stays applied; a bottom contact or side cutting alone.
    node.AllowOnlyKeys({"stick_speed", "bottom", "side_cutting"});
    if (!p.bottom && !p.side_cutting) {
      node.Fail("expected a 'law' (detournay or friction), a 'bottom' contact or 'side_cutting'");
    }
    p.law = model::BitRockLaw::None;
  } else {
    node.Child("law").Fail(fmt::format("expected 'detournay' or 'friction', got '{}'", law));
  }
  return p;
}

}  // namespace drillflex::io
