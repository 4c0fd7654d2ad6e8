#include "fe/body_fe_model.hpp"

#include <cmath>
#include <string>

#include "core/error.hpp"

namespace drillflex::fe {
namespace {

void ValidateSpec(const BodySpec& spec) {
  ValidateSection(spec.section);
  ValidateMaterial(spec.material);
  if (!(spec.length > 0.0) || !std::isfinite(spec.length)) {
    throw InputError({}, "length", "a body needs a positive finite length");
  }
  if (spec.element_count < 1) {
    throw InputError({}, "element_count", "a body needs at least one element");
  }
  if (spec.options.added_lateral_mass_per_length < 0.0 ||
      spec.options.internal_fluid_mass_per_length < 0.0) {
    throw InputError({}, "fluid", "fluid masses per length must not be negative");
  }
}

// Adds a 12 × 12 element matrix of element e (nodes e, e + 1) to the triplet list.
void AddElement(const Mat12& element, Index e, std::vector<Triplet>& triplets) {
  const Index offset = kDofPerNode * e;
  for (Index c = 0; c < 12; ++c) {
    for (Index r = 0; r < 12; ++r) {
      if (element(r, c) != 0.0) triplets.emplace_back(offset + r, offset + c, element(r, c));
    }
  }
}

SparseMat Assemble(const Mat12& element, Index element_count) {
  std::vector<Triplet> triplets;
  triplets.reserve(element_count * 144);
  for (Index e = 0; e < element_count; ++e) AddElement(element, e, triplets);
  const Index n = kDofPerNode * (element_count + 1);
  SparseMat matrix(n, n);
  matrix.setFromTriplets(triplets.begin(), triplets.end());
  return matrix;
}

}  // namespace

BeamElementProperties BodyElementProperties(const BodySpec& spec) {
  BeamElementProperties p =
      MakeElementProperties(spec.section, spec.material, spec.length / spec.element_count);
  p.lateral_mass_per_length = spec.options.lateral_mass_per_length();
  p.bending_rotary_inertia = spec.options.bending_rotary_inertia;
  p.bending_stiffness_factor = spec.options.bending_stiffness_factor;
  return p;
}

BodyFeModel BuildBodyFeModel(const BodySpec& spec) {
  ValidateSpec(spec);
  const BodyFeOptions& options = spec.options;
  const BeamElementProperties element = BodyElementProperties(spec);
  const Index n = spec.element_count;

  BodyFeModel model;
  model.spec = spec;
  model.node_x.resize(n + 1);
  for (Index k = 0; k <= n; ++k) model.node_x[k] = spec.length * k / n;
  model.node_x[n] = spec.length;

  // Every element is the same, so each matrix is one element matrix assembled n times.
  const Mat12 lumped = ElementLumpedMass(element, options.lumped_rotary);
  const Mat12 mass =
      options.mass == MassKind::kConsistent ? ElementConsistentMass(element, options.beam) : lumped;
  model.stiffness = Assemble(ElementStiffness(element, options.beam), n);
  model.mass = Assemble(mass, n);
  model.element_geometric_stiffness = ElementGeometricStiffness(element, options.beam);
  model.geometric_stiffness = Assemble(model.element_geometric_stiffness, n);
  model.torque_geometric_stiffness = Assemble(ElementTorqueGeometricStiffness(element, options.beam), n);

  // Lumped nodal data: the sum of the element lumped diagonals meeting at each node.
  const double structural_half = element.density * element.area * 0.5 * element.length;
  model.node_mass.assign(n + 1, 0.0);
  model.node_lateral_mass.assign(n + 1, 0.0);
  model.node_rotary_inertia.assign(n + 1, Vec3::Zero());
  for (Index e = 0; e < n; ++e) {
    for (Index side = 0; side < 2; ++side) {
      const Index k = e + side;
      const Index d = kDofPerNode * side;
      model.node_mass[k] += structural_half;
      model.node_lateral_mass[k] += lumped(d + 1, d + 1) - structural_half;
      model.node_rotary_inertia[k] += lumped.diagonal().segment<3>(d + 3);
    }
  }
  return model;
}

MatX RigidBodyFields(const std::vector<double>& node_x) {
  const Index nodes = std::ssize(node_x);
  MatX fields = MatX::Zero(kDofPerNode * nodes, 6);
  for (Index k = 0; k < nodes; ++k) {
    const Index row = kDofPerNode * k;
    fields.block<3, 3>(row, 0).setIdentity();
    // θ × ρ_k with ρ_k = (x, 0, 0): rotation about y moves w by −x θy, about z moves v by x θz.
    fields(row + 2, 4) = -node_x[k];
    fields(row + 1, 5) = node_x[k];
    fields.block<3, 3>(row + 3, 3).setIdentity();
  }
  return fields;
}

}  // namespace drillflex::fe
