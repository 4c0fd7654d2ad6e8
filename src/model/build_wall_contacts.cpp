// The builder's wall contacts (model/build_parts.hpp).
#include <cmath>
#include <memory>

#include "model/build_parts.hpp"
#include "model/contact_circles.hpp"
#include "model/hole_friction.hpp"
#include "model/wall_contact.hpp"
#include "well/hole.hpp"

namespace drillflex::model {

// Wall contact at every node (a joint once, on the upper body's start node): tool joints and
// blades as point contacts, each circle as stiff as the string length it stands for
// (model/contact_circles.hpp), a tight one stiffer (WallContactStiffness).
std::vector<ElementHandle<WallContactElement>> PlaceWallContacts(ModelDraft& draft) {
  const ModelInput& input = draft.input;
  const std::vector<Body>& placed = draft.bodies;
  std::vector<ElementHandle<WallContactElement>> contacts;
  if (!input.well || input.well->hole.empty()) return contacts;
  const std::shared_ptr<const Wellbore>& wellbore = input.well;  // shared by the contacts, not copied
  struct ContactNode { const Body* body; Index node; double s; };
  std::vector<ContactNode> nodes;
  for (Index b = 0; b < std::ssize(placed); ++b) {
    const Body& body = placed[b];
    // The bit cuts the hole it sits in (its support holds it at the hole centre): no contact.
    if (input.string.components[body.component].type == ComponentType::Bit) continue;
    for (Index k = 0; k < body.node_count(); ++k) {
      if (k == body.node_count() - 1 && b + 1 != std::ssize(placed)) continue;  // the next body's node 0 carries it
      nodes.push_back({&body, k, body.NodeS(k)});
    }
  }
  std::vector<double> positions;
  for (const ContactNode& node : nodes) positions.push_back(node.s);
  // A string that is a bit alone has no node to touch the wall (found by fuzz/case_file).
  const std::vector<ContactCircle> circles =
      nodes.empty() ? std::vector<ContactCircle>{} : ContactCircles(input.string, positions);
  const ContactSettings& contact = input.settings.contact;
  for (Index i = 0; i < std::ssize(nodes); ++i) {
    const auto [body, k, s] = nodes[i];
    const double clearance = 0.5 * (wellbore->hole.Diameter(input.bit_md - s) - circles[i].diameter);
    // A circle wider than its body is a point contact (blades, a tool joint): it carries a span.
    const bool point = circles[i].diameter > input.string.components[body->component].outer_diameter * (1.0 + 1e-9);
    const double stiffness = WallContactStiffness(contact, circles[i].length, BuoyedWeightPerLength(*body, input),
                                                  clearance, point ? kContactWeightSpan : circles[i].length);
    WallContactParameters parameters;
    parameters.contact_radius = 0.5 * circles[i].diameter;
    parameters.normal_stiffness = stiffness;
    parameters.normal_damping = 2.0 * contact.damping_ratio * std::sqrt(stiffness * ElementInertia(*body)[0]);
    // The friction of the hole section the contact starts in (the string moves centimetres in a
    // static, a stand at most in a transient: a contact keeps its section).
    const HoleFriction friction = HoleFrictionAt(wellbore->hole, contact, input.bit_md - s);
    parameters.tangential_friction = friction.friction.tangential;
    parameters.axial_friction = friction.friction.axial;
    parameters.cased = friction.cased;
    parameters.regularization_velocity =
        contact.friction_velocity.value_or(kFrictionRegularizationSpin * parameters.contact_radius);
    parameters.prescribed_sliding = input.static_sliding;
    contacts.push_back(draft.elements.Add<WallContactElement>(body, k, wellbore, parameters, input.bit_md - s));
  }
  return contacts;
}

}  // namespace drillflex::model
