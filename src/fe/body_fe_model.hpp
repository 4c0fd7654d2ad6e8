// The finite-element model of one uniform flexible body in its body frame (method.md §3 step 1):
// nodes x_0 = 0 … x_n = L on the local x-axis, n equal two-node beam elements, 6 DOF per node
// (u, v, w, θx, θy, θz), global DOF index 6 k + d. Matrices are sparse (a 1000-element mesh is
// cheap to build); the reduction converts the small ones to dense.
#pragma once

#include <vector>

#include "core/types.hpp"
#include "fe/beam_element.hpp"
#include "fe/material.hpp"
#include "fe/section.hpp"

namespace drillflex::fe {

struct BodyFeOptions {
  MassKind mass = MassKind::kConsistent;
  BeamTheory beam = BeamTheory::kEulerBernoulli;
  // Extra lateral inertia (moves with v, w only; method.md §7), kg/m:
  double added_lateral_mass_per_length = 0.0;   // annulus added mass C_m ρ_f π OD²/4
  double internal_fluid_mass_per_length = 0.0;  // bore fluid ρ_f,i A_i
  // false drops the ρI rotary inertia of bending (the Euler–Bernoulli inertia of the classical
  // β_n L tables); torsional inertia ρJ stays.
  bool bending_rotary_inertia = true;
  // Lumped mass only: which rotary inertia a node gets (see ElementLumpedMass).
  LumpedRotaryInertia lumped_rotary = LumpedRotaryInertia::kSection;
  // Multiplies the bending stiffness E I (BeamElementProperties::bending_stiffness_factor).
  double bending_stiffness_factor = 1.0;

  double lateral_mass_per_length() const {
    return added_lateral_mass_per_length + internal_fluid_mass_per_length;
  }
};

// What defines a body's FE model (also the reduction cache's key, with the reduction options).
struct BodySpec {
  HollowSection section;
  Material material;
  double length = 0.0;    // m
  Index element_count = 0;  // ≥ 1
  BodyFeOptions options;
};

struct BodyFeModel {
  BodySpec spec;
  std::vector<double> node_x;     // node positions along the body axis, m (x_0 = 0, x_n = L)
  SparseMat stiffness;            // K, N × N, N = 6 (n + 1)
  SparseMat mass;                 // M (consistent or lumped per spec.options.mass)
  SparseMat geometric_stiffness;  // K_G per unit axial force (tension positive), 1/m
  SparseMat torque_geometric_stiffness;  // K_T per unit torque (fe::ElementTorqueGeometricStiffness), 1/(N·m)
  // The one element's K_G per unit axial force (every element is the same): the body's axial force
  // varying from element to element (model/nodal_loads.hpp) weights it element by element.
  Mat12 element_geometric_stiffness = Mat12::Zero();
  // The lumped representation, whatever spec.options.mass is (the floating-frame node sum):
  std::vector<double> node_mass;          // structural mass ρ A L_k (isotropic), kg
  std::vector<double> node_lateral_mass;  // fluid mass moving laterally only (y, z), kg
  std::vector<Vec3> node_rotary_inertia;  // diag(Jx, Jy, Jz) about the node, kg·m²

  Index node_count() const { return std::ssize(node_x); }
  Index dof_count() const { return 6 * node_count(); }
};

inline constexpr Index kDofPerNode = 6;

// Builds the model. Throws InputError (no file position) on a bad section, material, length,
// element count or negative fluid mass.
BodyFeModel BuildBodyFeModel(const BodySpec& spec);

// The element properties every element of the body shares (length L/n, fluid mass, options).
BeamElementProperties BodyElementProperties(const BodySpec& spec);

// N × 6 rigid-body displacement fields about the body origin, columns (translation x, y, z,
// rotation x, y, z): node k moves by t + θ × ρ_k and rotates by θ, with ρ_k = (x_k, 0, 0).
MatX RigidBodyFields(const std::vector<double>& node_x);

}  // namespace drillflex::fe
