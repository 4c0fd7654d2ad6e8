// Reads `analyses.transient.bit_rock`: the law of the rock's reaction on the bit
// (model/bit_rock.hpp), Detournay's cutting and contact or a static/kinetic friction torque.
#include <fmt/format.h>

#include "io/case_sections.hpp"

namespace drillflex::io {

using units::Quantity;

model::BitRockParameters ReadBitRockSection(const YamlView& node) {
  node.ExpectMap("the bit-rock interaction {law, ...}", false);
  model::BitRockParameters p;
  const std::string law = node.Child("law").AsString();
  p.stick_speed = node.OptionalPositive("stick_speed", Quantity::RotarySpeed).value_or(model::kDefaultStickSpeed);
  if (law == "detournay") {
    node.AllowOnlyKeys({"law", "specific_energy", "cutting_ratio", "contact_force", "friction", "geometry", "radius",
                        "stick_speed", "contact_speed"});
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
    node.AllowOnlyKeys({"law", "static_torque", "kinetic_torque", "stick_speed", "stribeck_speed"});
    p.law = model::BitRockLaw::Friction;
    p.static_torque = node.Positive("static_torque", Quantity::Moment);
    p.kinetic_torque = node.Quantity("kinetic_torque", Quantity::Moment);
    if (p.kinetic_torque < 0.0) node.Child("kinetic_torque").Fail("expected a kinetic torque of 0 or more");
    if (!(p.static_torque > p.kinetic_torque)) {
      node.Child("static_torque").Fail("the static friction torque must exceed the kinetic one (stick-slip needs T_s > T_d)");
    }
    p.stribeck_speed = node.OptionalPositive("stribeck_speed", Quantity::RotarySpeed).value_or(p.stick_speed);
  } else {
    node.Child("law").Fail(fmt::format("expected 'detournay' or 'friction', got '{}'", law));
  }
  return p;
}

}  // namespace drillflex::io
