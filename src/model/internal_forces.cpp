#include "model/internal_forces.hpp"

#include <map>

#include <fmt/format.h>

#include "core/error.hpp"
#include "fe/beam_element.hpp"
#include "fe/body_fe_model.hpp"
#include "model/body_dynamics.hpp"
#include "model/nodal_loads.hpp"
#include "model/spring_elements.hpp"

namespace drillflex::model {
namespace {

using Vec12 = Eigen::Matrix<double, 12, 1>;

// The element matrices every element of a body shares (uniform bodies), rebuilt from its spec.
struct ElementMatrices {
  fe::Mat12 stiffness;  // K_e, N/m, N, N·m
  fe::Mat12 geometric;  // K_G,e per unit axial force (tension +), 1/m
};

ElementMatrices MakeElementMatrices(const fe::BodySpec& spec) {
  const fe::BeamElementProperties properties = fe::BodyElementProperties(spec);
  return {fe::ElementStiffness(properties, spec.options.beam),
          fe::ElementGeometricStiffness(properties, spec.options.beam)};
}

// One element-matrix pair per distinct reduced body (identical bodies share their ReducedBody).
class ElementMatrixCache {
 public:
  const ElementMatrices& Get(const Body& body) {
    auto it = cache_.find(body.reduced.get());
    if (it == cache_.end()) it = cache_.emplace(body.reduced.get(), MakeElementMatrices(body.reduced->spec)).first;
    return it->second;
  }

 private:
  std::map<const cms::ReducedBody*, ElementMatrices> cache_;
};

SectionForces FromSix(const Eigen::Ref<const Vec12>& values, Index start, double sign) {
  SectionForces forces;
  forces.force = sign * values.segment<3>(start);
  forces.moment = sign * values.segment<3>(start + 3);
  return forces;
}

// Section forces of every node from the element end forces f_e (see the header's convention):
// node k carries +f_{k−1}(node 2) from the element below and −f_k(node 1) from the one above.
std::vector<SectionForces> NodeForces(const std::vector<Vec12>& element_forces) {
  const Index elements = std::ssize(element_forces);
  std::vector<SectionForces> nodes(elements + 1);
  for (Index k = 0; k <= elements; ++k) {
    const bool below = k > 0, above = k < elements;
    SectionForces sum;
    if (below) {
      const SectionForces lower = FromSix(element_forces[k - 1], 6, 1.0);
      sum.force += lower.force;
      sum.moment += lower.moment;
    }
    if (above) {
      const SectionForces upper = FromSix(element_forces[k], 0, -1.0);
      sum.force += upper.force;
      sum.moment += upper.moment;
    }
    const double sides = (below && above) ? 2.0 : 1.0;
    nodes[k].force = sum.force / sides;
    nodes[k].moment = sum.moment / sides;
  }
  return nodes;
}

// Replaces the element axial forces by N̄ + c_e − mean(c), c_e = −Σ_{j=1..e} a_j (header).
void RebuildAxialForces(double mean_axial_force, const std::vector<double>& axial_loads,
                        std::vector<Vec12>& element_forces) {
  const Index elements = std::ssize(element_forces);
  std::vector<double> cumulative(elements, 0.0);
  double sum = 0.0, running = 0.0;
  for (Index e = 0; e < elements; ++e) {
    if (e > 0 && !axial_loads.empty()) running -= axial_loads[e];
    cumulative[e] = running;
    sum += running;
  }
  const double mean = sum / elements;
  for (Index e = 0; e < elements; ++e) {
    const double axial = mean_axial_force + cumulative[e] - mean;
    element_forces[e][0] = -axial;  // force on the element at its lower node (tension pulls down)
    element_forces[e][6] = axial;   // at its upper node
  }
}

// The body's mean membrane force N̄ (header): the model's own BodyAxialForce.
double MembraneForce(const Body& body, const VecX& eta) {
  BodyPose pose;
  pose.eta = eta;
  return BodyAxialForce(body, pose);
}

std::vector<SectionForces> ForcesOfBody(const Body& body, const ElementMatrices& matrices, const VecX& eta,
                                        const std::vector<double>& axial_loads) {
  const Index elements = body.node_count() - 1;
  const VecX displacement = body.reduced->mode_shapes * eta;  // d = U η, FE order 6 k + d
  const double membrane = MembraneForce(body, eta);  // N̄, tension positive
  const fe::Mat12 tangent = matrices.stiffness + membrane * matrices.geometric;
  std::vector<Vec12> element_forces(elements);
  for (Index e = 0; e < elements; ++e) element_forces[e] = tangent * displacement.segment<12>(6 * e);
  RebuildAxialForces(membrane, axial_loads, element_forces);
  return NodeForces(element_forces);
}

// Dead axial nodal loads of every body (body frame x, N) from its NodalLoadElements.
std::vector<std::vector<double>> AxialNodalLoads(const BuiltModel& built, const std::vector<BodyPose>& poses,
                                                 const LoadParameters& load) {
  const SystemModel& model = built.system;
  std::vector<std::vector<double>> loads(model.bodies().size());
  for (Index b = 0; b < std::ssize(loads); ++b) loads[b].assign(model.bodies()[b].node_count(), 0.0);
  for (const auto handle : built.nodal_loads) {
    const NodalLoadElement& nodal = built.Get(handle);
    const Index b = model.IndexOf(nodal.bodies()[0]);
    const Vec3 axis = poses[b].A.col(0);
    const auto& forces = nodal.forces();
    const double scale = nodal.Scale(load);
    for (Index k = 0; k < std::ssize(forces); ++k) loads[b][k] += scale * axis.dot(forces[k]);
  }
  return loads;
}

}  // namespace

Eigen::Matrix<double, 12, 1> ElementEndForces(const Body& body, const VecX& eta, Index element) {
  if (element < 0 || element + 1 >= body.node_count()) {
    throw LogicError(fmt::format("ElementEndForces: element {} outside the body's {} elements", element,
                                 body.node_count() - 1));
  }
  const ElementMatrices matrices = MakeElementMatrices(body.reduced->spec);
  const Vec12 d = body.reduced->mode_shapes.middleRows<12>(6 * element) * eta;
  return (matrices.stiffness + MembraneForce(body, eta) * matrices.geometric) * d;
}

std::vector<SectionForces> BodyInternalForces(const Body& body, const VecX& eta,
                                              const std::vector<double>& axial_loads) {
  if (!axial_loads.empty() && std::ssize(axial_loads) != body.node_count()) {
    throw LogicError("BodyInternalForces: one axial load per node expected");
  }
  return ForcesOfBody(body, MakeElementMatrices(body.reduced->spec), eta, axial_loads);
}

std::vector<std::vector<SectionForces>> ComputeInternalForces(const BuiltModel& built, const VecX& q,
                                                              const LoadParameters& load) {
  std::vector<Index> all(built.system.bodies().size());
  for (Index b = 0; b < std::ssize(all); ++b) all[b] = b;
  return ComputeInternalForces(built, q, load, all);
}

std::vector<std::vector<SectionForces>> ComputeInternalForces(const BuiltModel& built, const VecX& q,
                                                              const LoadParameters& load, std::span<const Index> bodies) {
  const SystemModel& model = built.system;
  const std::vector<BodyPose> poses = model.Poses(q);
  const auto axial_loads = AxialNodalLoads(built, poses, load);
  ElementMatrixCache cache;
  std::vector<std::vector<SectionForces>> result(model.bodies().size());
  for (const Index b : bodies) {
    const Body& body = model.bodies().at(b);
    result[b] = ForcesOfBody(body, cache.Get(body), poses[b].eta, axial_loads[b]);
  }
  return result;
}

std::vector<SectionForces> JointInternalForces(const BuiltModel& built, const VecX& q, const VecX& v) {
  const std::size_t bodies = built.system.bodies().size();
  std::vector<Index> all(bodies > 0 ? bodies - 1 : 0);
  for (Index j = 0; j < std::ssize(all); ++j) all[j] = j;
  return JointInternalForces(built, q, v, all);
}

std::vector<SectionForces> JointInternalForces(const BuiltModel& built, const VecX& q, const VecX& v,
                                               std::span<const Index> joints) {
  const SystemModel& model = built.system;
  const std::size_t bodies = model.bodies().size();
  std::vector<SectionForces> result(bodies > 0 ? bodies - 1 : 0);
  std::vector<bool> wanted(result.size(), false), found(result.size(), false);
  for (const Index j : joints) wanted.at(j) = true;
  const std::vector<BodyPose> poses = model.Poses(q);
  for (const auto handle : built.couplings) {
    const CouplingElement& coupling = built.Get(handle);
    const Index lower = model.IndexOf(coupling.bodies()[0]);
    if (model.IndexOf(coupling.bodies()[1]) != lower + 1 || !wanted[lower]) continue;
    const Vec6 force = coupling.Force(model.StateOf(coupling, poses, v, 0.0, 1.0));
    result[lower].force = force.head<3>();
    result[lower].moment = force.tail<3>();
    found[lower] = true;
  }
  for (const Index j : joints) {
    if (!found[j]) throw LogicError(fmt::format("JointInternalForces: no coupling between bodies {} and {}", j, j + 1));
  }
  return result;
}

}  // namespace drillflex::model
