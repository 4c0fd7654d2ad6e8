// The builder's applied loads (model/build_parts.hpp).
#include <algorithm>
#include <cmath>
#include <utility>

#include "model/build_parts.hpp"
#include "model/nodal_loads.hpp"
#include "model/node_kinematics.hpp"

namespace drillflex::model {
namespace {

// The work-equivalent nodal forces and moments of a uniform global line load over every element of
// a body (the buoyed weight, N/m).
void AddLineLoad(const Body& body, const Vec3& per_length, std::vector<Vec3>& forces, std::vector<Vec3>& moments) {
  for (Index k = 0; k + 1 < body.node_count(); ++k) {
    AddUniformLineLoad(NodeReferencePosition(body, k), NodeReferencePosition(body, k + 1), per_length, forces[k],
                       moments[k], forces[k + 1], moments[k + 1]);
  }
}

// The same of one of the case's distributed loads (string frame, over the part of each element inside
// [from, to]). True when the load reaches the body.
bool AddDistributedLoad(const Body& body, const Load& load, std::vector<Vec3>& forces, std::vector<Vec3>& moments) {
  const Mat3 frame = body.reference_orientation.toRotationMatrix();
  bool any = false;
  for (Index k = 0; k + 1 < body.node_count(); ++k) {
    const double a = std::max(load.from, body.NodeS(k)), c = std::min(load.to, body.NodeS(k + 1));
    if (c <= a) continue;
    any = true;
    const Vec3 q = frame * load.force_per_length;
    const Vec3 m = frame * load.moment_per_length;
    const double h = body.NodeS(k + 1) - body.NodeS(k);
    if (c - a >= h * (1.0 - 1e-12)) {
      AddUniformLineLoad(NodeReferencePosition(body, k), NodeReferencePosition(body, k + 1), q, forces[k], moments[k],
                         forces[k + 1], moments[k + 1]);
    } else {  // a partly loaded element: the resultant shared by the lever rule
      const double share = (0.5 * (a + c) - body.NodeS(k)) / h;
      forces[k] += (1.0 - share) * (c - a) * q;
      forces[k + 1] += share * (c - a) * q;
    }
    moments[k] += 0.5 * (c - a) * m;
    moments[k + 1] += 0.5 * (c - a) * m;
  }
  return any;
}
}  // namespace

// Applied loads, each group its own elements (LoadParameters scales or replaces each): the buoyed
// weight per body; the case's distributed loads per body and point loads; the transient's initial
// loads; the WOB and the torque on bit per unit of their value.
PlacedLoads PlaceLoads(ModelDraft& draft) {
  const ModelInput& input = draft.input;
  const std::vector<Body>& placed = draft.bodies;
  const double length = draft.length;
  std::vector<ElementHandle<NodalLoadElement>> handles;
  auto add = [&](const Body& body, std::vector<Vec3> forces, std::vector<Vec3> moments, LoadGroup group,
                 double value) {
    handles.push_back(draft.elements.Add<NodalLoadElement>(&body, std::move(forces), std::move(moments), group, value));
  };
  double force_scale = 0.0;
  for (const Body& body : placed) {
    std::vector<Vec3> forces(body.node_count(), Vec3::Zero()), moments(body.node_count(), Vec3::Zero());
    const double weight = BuoyedWeightPerLength(body, input);
    if (weight != 0.0) {
      AddLineLoad(body, weight * Vec3(kGravityDirection[0], kGravityDirection[1], kGravityDirection[2]), forces, moments);
    }
    for (Index k = 0; k < body.node_count(); ++k) force_scale += forces[k].norm();
    add(body, std::move(forces), std::move(moments), LoadGroup::kWeight, 1.0);
  }
  for (const auto& [loads, group] : {std::pair{&input.loads, LoadGroup::kCaseLoads},
                                     std::pair{&input.initial_loads, LoadGroup::kInitialLoads}}) {
    for (const Body& body : placed) {
      std::vector<Vec3> forces(body.node_count(), Vec3::Zero()), moments(body.node_count(), Vec3::Zero());
      bool any = false;
      for (const Load& load : *loads) {
        if (load.distributed) any = AddDistributedLoad(body, load, forces, moments) || any;
      }
      if (!any) continue;
      if (group == LoadGroup::kCaseLoads) {
        for (Index k = 0; k < body.node_count(); ++k) force_scale += forces[k].norm();
      }
      add(body, std::move(forces), std::move(moments), group, 1.0);
    }
    for (const Load& load : *loads) {
      if (load.distributed) continue;
      const auto [b, node] = FindNodeAt(placed, load.at);
      const Body& body = placed[b];
      const Mat3 frame = body.reference_orientation.toRotationMatrix();
      std::vector<Vec3> forces(body.node_count(), Vec3::Zero()), moments(body.node_count(), Vec3::Zero());
      forces[node] = frame * load.force;
      moments[node] = frame * load.moment;
      if (group == LoadGroup::kCaseLoads) force_scale += load.force.norm() + load.moment.norm() / std::max(length, 1e-3);
      add(body, std::move(forces), std::move(moments), group, 1.0);
    }
  }
  // The formation pushes the bit up-hole with the WOB and resists its rotation with the torque on
  // bit: per newton and per N·m, their values the case's (or the parameter block's). A bit-rock law
  // gives the rock's reaction from the bit's motion instead (model/bit_rock.hpp): the torque on bit,
  // and under Detournay's law or with a bottom contact the WOB too.
  const bool rock_wob = input.bit_rock && (input.bit_rock->law == BitRockLaw::Detournay || input.bit_rock->bottom);
  const bool rock_tob = input.bit_rock && input.bit_rock->law != BitRockLaw::None;
  const auto [b, node] = FindNodeAt(placed, 0.0);
  const Body& body = placed[b];
  const Vec3 axis = body.reference_orientation.toRotationMatrix().col(0);
  const double wob = input.operation.weight_on_bit, tob = input.operation.torque_on_bit;
  if (!rock_wob) {
    std::vector<Vec3> forces(body.node_count(), Vec3::Zero()), moments(body.node_count(), Vec3::Zero());
    forces[node] = axis;
    force_scale += std::abs(wob);
    add(body, std::move(forces), std::move(moments), LoadGroup::kWeightOnBit, wob);
  }
  if (!rock_tob) {
    std::vector<Vec3> forces(body.node_count(), Vec3::Zero()), moments(body.node_count(), Vec3::Zero());
    moments[node] = axis;
    force_scale += std::abs(tob) / std::max(length, 1e-3);
    add(body, std::move(forces), std::move(moments), LoadGroup::kTorqueOnBit, tob);
  }
  if (force_scale == 0.0) force_scale = placed.front().bending_rigidity / (length * length);
  return {std::move(handles), force_scale};
}

}  // namespace drillflex::model
