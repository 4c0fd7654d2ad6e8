#include "model/lateral_fluid.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "core/error.hpp"
#include "fe/annulus_fluid.hpp"
#include "model/node_kinematics.hpp"
#include "well/hole.hpp"

namespace drillflex::model {
namespace {

// Tributary length of node k of a body: half the distance to each neighbour inside the body.
double TributaryLength(const Body& body, Index k) {
  const auto& nodes = body.reduced->node_positions;
  const Index last = body.node_count() - 1;
  const double below = k > 0 ? nodes[k].x() - nodes[k - 1].x() : 0.0;
  const double above = k < last ? nodes[k + 1].x() - nodes[k].x() : 0.0;
  return 0.5 * (below + above);
}

}  // namespace

LateralFluid MakeLateralFluid(const ModelInput& input, const SystemModel& model) {
  return MakeLateralFluid(input, model.bodies());
}

LateralFluid MakeLateralFluid(const ModelInput& input, const std::vector<Body>& bodies) {
  LateralFluid fluid;
  if (!input.fluid) return fluid;
  fluid.density = input.fluid->density;
  fluid.kinematic_viscosity = fluid.density > 0.0 ? input.fluid->viscosity / fluid.density : 0.0;
  fluid.added_mass_override = input.fluid->added_mass_coefficient_override;
  const double inside = input.fluid->internal_density.value_or(input.fluid->density);
  const well::HoleProfile* hole = input.well && !input.well->hole.empty() ? &input.well->hole : nullptr;
  for (Index b = 0; b < std::ssize(bodies); ++b) {
    const Body& body = bodies[b];
    const AveragedAreas areas = AverageAreas(input.string.components.at(body.component));
    for (Index k = 0; k < body.node_count(); ++k) {
      LateralFluidNode node;
      node.body = b;
      node.node = k;
      node.length = TributaryLength(body, k);
      node.internal_mass = inside * areas.bore * node.length;
      node.rod_radius = 0.5 * body.outer_diameter;
      if (hole) {
        const double s = body.NodeS(k);
        const double hole_radius = 0.5 * hole->Diameter(input.bit_md - s);
        // No annulus where the body fills the hole (the case checks forbid it; a guard only).
        if (hole_radius > node.rod_radius) node.hole_radius = hole_radius;
      }
      fluid.nodes.push_back(node);
    }
  }
  return fluid;
}

void AttachLateralFluid(const ModelInput& input, double circular_frequency, std::vector<Body>& bodies) {
  const LateralFluid fluid = MakeLateralFluid(input, bodies);
  if (fluid.empty()) return;
  if (fluid.frequency_dependent() && !(circular_frequency > 0.0)) {
    throw LogicError("AttachLateralFluid: a viscous fluid's annulus terms need a positive frequency");
  }
  for (Body& body : bodies) {
    // The reduction's own lateral node mass (fe::BodyFeOptions added/internal fluid mass) is the
    // other way to carry the fluid; both at once would count it twice.
    for (const double m : body.reduced->node_lateral_mass) {
      if (m != 0.0) throw LogicError("AttachLateralFluid: the body's reduction already carries a lateral fluid mass");
    }
    body.fluid_lateral_mass = VecX::Zero(body.node_count());
    body.fluid_lateral_damping = VecX::Zero(body.node_count());
  }
  for (Index i = 0; i < std::ssize(fluid.nodes); ++i) {
    const LateralFluidNode& node = fluid.nodes[i];
    const NodeFluidTerms terms = ComputeNodeFluidTerms(fluid, i, circular_frequency);
    bodies[node.body].fluid_lateral_mass[node.node] = terms.mass;
    bodies[node.body].fluid_lateral_damping[node.node] = terms.damping;
  }
}

NodeFluidTerms ComputeNodeFluidTerms(const LateralFluid& fluid, std::size_t index, double circular_frequency) {
  const LateralFluidNode& node = fluid.nodes.at(index);
  NodeFluidTerms terms;
  terms.mass = node.internal_mass;
  if (node.hole_radius <= 0.0 || fluid.density <= 0.0) return terms;
  fe::AnnulusFluidCoefficients coefficients;
  if (fluid.added_mass_override >= 0.0) {
    coefficients.added_mass = fluid.added_mass_override;
  } else if (!fluid.frequency_dependent() || circular_frequency <= 0.0) {
    coefficients = fe::ComputeAnnulusFluidCoefficients(node.rod_radius, node.hole_radius, 0.0, 0.0);
  } else {
    coefficients = fe::ComputeAnnulusFluidCoefficients(node.rod_radius, node.hole_radius, circular_frequency,
                                                    fluid.kinematic_viscosity);
  }
  // m_a = C_m ρ π a² and c = C_v ρ π a² ω per length (Chen et al. 1976; fe/annulus_fluid.hpp).
  terms.mass += fe::AddedMassPerLength(coefficients, fluid.density, node.rod_radius) * node.length;
  terms.damping =
      fe::DampingPerLength(coefficients, fluid.density, node.rod_radius, circular_frequency) * node.length;
  return terms;
}

MatX LateralNodeJacobian(const SystemModel& model, const std::vector<BodyPose>& poses, const LateralFluidNode& node) {
  const Body& body = model.bodies()[node.body];
  const BodyPose& pose = poses[node.body];
  // t_k = Aᵀṙ + ω × u_k + Φ_k η̇ (body frame, method.md §4).
  Eigen::Matrix<double, 3, Eigen::Dynamic> jacobian;
  NodeVelocityJacobian(body, pose, node.node, pose.NodeOffset(body, node.node), jacobian);
  return jacobian.bottomRows<2>();
}

LateralFluidMatrices ComputeLateralFluidMatrices(const SystemModel& model, const LateralFluid& fluid, const VecX& q,
                                              double circular_frequency, FluidPart part) {
  const auto poses = model.Poses(q);
  std::vector<Eigen::Triplet<double>> mass, damping;
  for (Index i = 0; i < std::ssize(fluid.nodes); ++i) {
    const LateralFluidNode& node = fluid.nodes[i];
    NodeFluidTerms terms = ComputeNodeFluidTerms(fluid, i, circular_frequency);
    if (part == FluidPart::Annulus) terms.mass -= node.internal_mass;
    if (part == FluidPart::Internal) terms = {node.internal_mass, 0.0};
    if (terms.mass == 0.0 && terms.damping == 0.0) continue;
    const MatX jacobian = LateralNodeJacobian(model, poses, node);
    const MatX product = jacobian.transpose() * jacobian;
    const Index offset = model.bodies()[node.body].v_offset;
    for (Eigen::Index r = 0; r < product.rows(); ++r) {
      for (Eigen::Index c = 0; c < product.cols(); ++c) {
        if (product(r, c) == 0.0) continue;
        const Index row = offset + r, col = offset + c;
        if (terms.mass != 0.0) mass.emplace_back(row, col, terms.mass * product(r, c));
        if (terms.damping != 0.0) damping.emplace_back(row, col, terms.damping * product(r, c));
      }
    }
  }
  const Index n = model.num_velocities();
  LateralFluidMatrices matrices{SparseMat(n, n), SparseMat(n, n)};
  matrices.mass.setFromTriplets(mass.begin(), mass.end());
  matrices.damping.setFromTriplets(damping.begin(), damping.end());
  return matrices;
}

std::vector<AnnulusGroup> ComputeAnnulusGroups(const SystemModel& model, const LateralFluid& fluid, const VecX& q) {
  const auto poses = model.Poses(q);
  const Index n = model.num_velocities();
  std::vector<AnnulusGroup> groups;
  std::vector<std::vector<Eigen::Triplet<double>>> triplets;
  for (const LateralFluidNode& node : fluid.nodes) {
    if (node.hole_radius <= 0.0 || fluid.density <= 0.0) continue;
    auto group = std::find_if(groups.begin(), groups.end(), [&](const AnnulusGroup& g) {
      return g.rod_radius == node.rod_radius && g.hole_radius == node.hole_radius;
    });
    if (group == groups.end()) {
      groups.push_back({node.rod_radius, node.hole_radius, SparseMat(n, n)});
      triplets.emplace_back();
      group = groups.end() - 1;
    }
    auto& list = triplets[group - groups.begin()];
    const MatX jacobian = LateralNodeJacobian(model, poses, node);
    const MatX product = (fluid.density * kPi * node.rod_radius * node.rod_radius * node.length) *
                         (jacobian.transpose() * jacobian);
    const Index offset = model.bodies()[node.body].v_offset;
    for (Eigen::Index r = 0; r < product.rows(); ++r) {
      for (Eigen::Index c = 0; c < product.cols(); ++c) {
        if (product(r, c) != 0.0) list.emplace_back(offset + r, offset + c, product(r, c));
      }
    }
  }
  for (Index g = 0; g < std::ssize(groups); ++g) {
    groups[g].unit_mass.setFromTriplets(triplets[g].begin(), triplets[g].end());
  }
  return groups;
}

LateralFluidMatrices ComputeAnnulusMatrices(const std::vector<AnnulusGroup>& groups, const LateralFluid& fluid,
                                         double circular_frequency) {
  const Eigen::Index n = groups.empty() ? 0 : groups.front().unit_mass.rows();
  LateralFluidMatrices matrices{SparseMat(n, n), SparseMat(n, n)};
  for (const AnnulusGroup& group : groups) {
    fe::AnnulusFluidCoefficients coefficients;
    if (fluid.added_mass_override >= 0.0) {
      coefficients.added_mass = fluid.added_mass_override;
    } else {
      const bool viscous = fluid.frequency_dependent() && circular_frequency > 0.0;
      coefficients = fe::ComputeAnnulusFluidCoefficients(group.rod_radius, group.hole_radius,
                                                      viscous ? circular_frequency : 0.0,
                                                      viscous ? fluid.kinematic_viscosity : 0.0);
    }
    // m_a = C_m ρ π a², c = C_v ρ π a² ω per length (fe/annulus_fluid.hpp).
    matrices.mass += coefficients.added_mass * group.unit_mass;
    if (coefficients.damping != 0.0) matrices.damping += (coefficients.damping * circular_frequency) * group.unit_mass;
  }
  return matrices;
}

std::vector<double> LateralNodeSquares(const SystemModel& model, const LateralFluid& fluid, const VecX& q,
                                       const VecX& v) {
  const auto poses = model.Poses(q);
  std::vector<double> squares;
  squares.reserve(fluid.nodes.size());
  for (const LateralFluidNode& node : fluid.nodes) {
    const Body& body = model.bodies()[node.body];
    squares.push_back((LateralNodeJacobian(model, poses, node) * v.segment(body.v_offset, body.velocity_count()))
                          .squaredNorm());
  }
  return squares;
}

}  // namespace drillflex::model
