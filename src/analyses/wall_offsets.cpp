#include "analyses/wall_offsets.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <numeric>
#include <span>

#include <fmt/format.h>

#include "analyses/string_stations.hpp"
#include "core/error.hpp"
#include "model/wall_contact.hpp"

namespace drillflex::analyses {
namespace {

// Two stations closer than this along the string are the same node (FE nodes are centimetres apart
// at least; both s come from the same s_start + node position sums).
constexpr double kSameStationTolerance = 1e-6;  // m

struct ContactAtStation {
  double s = 0.0;
  const model::WallContactElement* element = nullptr;
};

double StationOf(const model::WallContactElement& contact) {
  const model::Body& body = *contact.bodies()[0];
  return body.NodeS(contact.node());
}

// The model's wall contacts sorted by station (at a joint two may share one: either serves).
std::vector<ContactAtStation> ContactsByStation(const model::BuiltModel& built) {
  std::vector<ContactAtStation> contacts;
  for (const auto handle : built.contacts) {
    const model::WallContactElement& contact = built.Get(handle);
    contacts.push_back({StationOf(contact), &contact});
  }
  std::stable_sort(contacts.begin(), contacts.end(),
                   [](const ContactAtStation& a, const ContactAtStation& b) { return a.s < b.s; });
  return contacts;
}

// The contact nearest to s along the string (contacts not empty, sorted by s).
const ContactAtStation& NearestContact(const std::vector<ContactAtStation>& contacts, double s) {
  auto above = std::lower_bound(contacts.begin(), contacts.end(), s,
                                [](const ContactAtStation& c, double value) { return c.s < value; });
  if (above == contacts.end()) return contacts.back();
  if (above == contacts.begin()) return *above;
  const auto below = std::prev(above);
  return s - below->s <= above->s - s ? *below : *above;
}

void SetFromContact(const model::WallContactResult& contact, double contact_radius, StaticNodeResult& node) {
  node.has_wall = true;
  node.md = contact.md;
  node.hole_offset = contact.offset;
  node.offset_high_side_angle = contact.high_side_angle;
  // R_h − R_c − ρ = −δ (model/wall_contact.hpp); written out rather than −penetration so that the
  // sum clearance + ρ is R_h − R_c up to one rounding.
  node.clearance = 0.5 * contact.hole_diameter - contact_radius - contact.offset;
  node.hole_diameter = contact.hole_diameter;
}

}  // namespace

void AddWallOffsets(const model::BuiltModel& built, const VecX& q, std::vector<StaticNodeResult>& nodes) {
  if (built.contacts.empty()) return;
  const std::size_t stations = StringStations(built.system).size();
  if (nodes.size() != stations) {
    throw LogicError(fmt::format("AddWallOffsets: {} node results for {} stations", nodes.size(), stations));
  }
  std::vector<Index> all(stations);
  std::iota(all.begin(), all.end(), 0);
  AddWallOffsets(built, q, nodes, all);
}

void AddWallOffsets(const model::BuiltModel& built, const VecX& q, std::vector<StaticNodeResult>& nodes,
                    std::span<const Index> station_indices) {
  if (built.contacts.empty()) return;
  const model::SystemModel& system = built.system;
  const std::vector<Station> stations = StringStations(system);
  if (station_indices.size() != nodes.size()) {
    throw LogicError(fmt::format("AddWallOffsets: {} node results for {} stations", nodes.size(),
                                 station_indices.size()));
  }
  const std::vector<ContactAtStation> contacts = ContactsByStation(built);
  const auto poses = system.Poses(q);
  const VecX rest = VecX::Zero(system.num_velocities());
  // The hole shared by the model's contacts, for the nodes without a contact of their own.
  const std::shared_ptr<const model::Wellbore>& wellbore = contacts.front().element->wellbore();

  for (Index i = 0; i < std::ssize(nodes); ++i) {
    StaticNodeResult& node = nodes[i];
    const Station& station = stations.at(station_indices[i]);
    const ContactAtStation& nearest = NearestContact(contacts, node.s);
    if (std::abs(nearest.s - node.s) <= kSameStationTolerance) {
      const model::WallContactElement& contact = *nearest.element;
      const auto result = contact.Result(system.StateOf(contact, poses, rest, 0.0, 1.0));
      SetFromContact(result, contact.parameters().contact_radius, node);
      node.wall_contact = true;
      continue;
    }
    // No contact here (a bit node): a contact circle of the body's contact diameter, evaluated only.
    // Start its closest-point search at the nearest contact's MD shifted by the distance along the
    // string (MD decreases up the string).
    const model::Body& body = system.bodies()[station.body];
    model::WallContactParameters parameters = nearest.element->parameters();
    parameters.contact_radius = 0.5 * body.contact_diameter;
    const model::WallContactResult nearest_result =
        nearest.element->Result(system.StateOf(*nearest.element, poses, rest, 0.0, 1.0));
    const model::WallContactElement probe(&body, station.node, wellbore, parameters,
                                          nearest_result.md + (nearest.s - node.s));
    SetFromContact(probe.Result(system.StateOf(probe, poses, rest, 0.0, 1.0)), parameters.contact_radius, node);
  }
}

}  // namespace drillflex::analyses
