// The builder's first part: the string cut into bodies, each section reduced once (model/build_parts.hpp).
#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "cms/reduced_body.hpp"
#include "core/error.hpp"
#include "model/build_parts.hpp"

namespace drillflex::model {
namespace {

fe::BodyFeOptions FeOptions(const ModelSettings& settings) {
  fe::BodyFeOptions options;
  options.mass = settings.mass;
  options.beam = settings.beam;
  options.bending_rotary_inertia = settings.rotary_inertia;
  options.bending_stiffness_factor = settings.bending_stiffness_factor;
  return options;
}

Body MakeBody(const std::shared_ptr<const cms::ReducedBody>& reduced, const fe::BodySpec& spec, Index component,
              double s_start, double contact_diameter, const MatX& mass_correction) {
  Body body;
  body.reduced = reduced;
  body.component = component;
  body.s_start = s_start;
  body.flexible_count = reduced->flexible_count;
  body.reference_position = Vec3(s_start, 0.0, 0.0);
  body.reference_orientation = Quat::Identity();
  body.axial_rigidity = spec.material.youngs_modulus * spec.section.area();
  body.bending_rigidity =
      spec.material.youngs_modulus * spec.section.second_moment() * spec.options.bending_stiffness_factor;
  body.torsional_rigidity = spec.material.shear_modulus() * spec.section.polar_moment();
  body.element_length = spec.length / spec.element_count;
  body.outer_diameter = spec.section.outer_diameter;
  body.contact_diameter = contact_diameter;
  // N = EA/L (u_x(L) − u_x(0)) from the axial rows of the end nodes.
  const Index last = reduced->node_count() - 1;
  body.axial_force_row = (body.axial_rigidity / spec.length) *
                         (reduced->node_translation_modes[last].row(0) - reduced->node_translation_modes[0].row(0)).transpose();
  body.torque_row = (body.torsional_rigidity / spec.length) *
                    (reduced->node_rotation_modes[last].row(0) - reduced->node_rotation_modes[0].row(0)).transpose();
  body.mass_correction = mass_correction;
  body.reference_mass = cms::NodalReferenceMassMatrix(*reduced) + mass_correction;
  return body;
}

// Where bodies must meet: the bent housing of a motor (its bend sits in a coupling) and every
// case support (it then acts on a node exactly where it is), m from the bit.
std::vector<double> BodyCuts(const ModelInput& input) {
  std::vector<double> cuts;
  for (const Component& component : input.string.components) {
    if (component.bend_angle && component.bend_to_bit) cuts.push_back(*component.bend_to_bit);
  }
  for (const Support& support : input.supports) cuts.push_back(support.at);
  std::sort(cuts.begin(), cuts.end());
  return cuts;
}

// The reduction of a component's section. A section whose stiffness or mass the reduction cannot
// tell from rounding (an od of 1e-9 m, a modulus of 1e-300 Pa: found by fuzz/case_file, where the
// reduction's LogicError ended the program) is the case's to fix: an InputError at the component.
std::shared_ptr<const cms::ReducedBody> ReduceSection(cms::ReductionCache& cache, const fe::BodySpec& spec,
                                                      const cms::ReductionOptions& reduction,
                                                      const Component& component, std::size_t index) {
  try {
    return cache.Get(spec, reduction);
  } catch (const LogicError& error) {
    throw InputError({"", component.source_line, 0}, fmt::format("string[{}]", index),
                     fmt::format("the {} (od {:.6g} m, id {:.6g} m, E {:.6g} Pa, density {:.6g} kg/m3) cannot be "
                                 "modelled: {}; check its diameters, length and material",
                                 component.name, spec.section.outer_diameter, spec.section.inner_diameter,
                                 spec.material.youngs_modulus, spec.material.density, error.what()));
  }
}

}  // namespace

// Masses (kg) and inertias (kg·m²) of one FE element of a body, for spring damping.
Vec6 ElementInertia(const Body& body) {
  const auto& spec = body.reduced->spec;
  const double l = body.element_length;
  const double rho = spec.material.density;
  const double mass = rho * spec.section.area() * l;
  const double bending = rho * spec.section.second_moment() * l + mass * l * l / 12.0;
  Vec6 m;
  m << mass, mass, mass, rho * spec.section.polar_moment() * l, bending, bending;
  return m;
}

// c = 2 ζ sqrt(k m): a spring damped at the coupling's ratio ζ against the inertia it holds.
double SpringDamping(double stiffness, double inertia) {
  return 2.0 * kCouplingDampingRatio * std::sqrt(stiffness * inertia);
}

Vec6 SpringDamping(const Vec6& stiffness, const Vec6& inertia) {
  return (2.0 * kCouplingDampingRatio * (stiffness.cwiseProduct(inertia)).cwiseSqrt());
}

std::vector<Body> CutBodies(const ModelInput& input, cms::ReductionCache& cache) {
  std::vector<Body> bodies;
  const ModelSettings& settings = input.settings;
  cms::ReductionOptions reduction;
  reduction.modes_per_body = settings.modes_per_body;
  reduction.structural_damping = settings.structural_damping;
  const std::vector<double> cuts = BodyCuts(input);
  double s = 0.0;
  for (Index c = 0; c < std::ssize(input.string.components); ++c) {
    const Component& component = input.string.components[c];
    const double span = component.length * component.count;
    // The component's stretches between the cuts inside it, each split evenly into bodies.
    std::vector<double> ends;
    for (const double cut : cuts) {
      if (cut > s + 1e-6 && cut < s + span - 1e-6 && (ends.empty() || cut > ends.back() + 1e-6)) ends.push_back(cut);
    }
    ends.push_back(s + span);
    double stretch_start = s;
    for (const double stretch_end : ends) {
      const double stretch = stretch_end - stretch_start;
      const Index count = std::max<Index>(1, std::lround(std::ceil(stretch / settings.body_length - 1e-9)));
      fe::BodySpec spec;
      spec.section = {component.outer_diameter, component.inner_diameter};
      spec.material = input.materials.at(component.material);
      // Tool joints: their steel smeared along the pipe (the adjusted weight of API RP 7G); the
      // stiffness stays the pipe body's. Their displaced and held fluid: BuoyedWeightPerLength.
      spec.material.density *= AverageAreas(component).material / spec.section.area();
      spec.length = stretch / count;
      // A body shorter than body_length gets proportionally fewer elements (at least 2), so that
      // the element length ℓ stays near body_length / elements_per_body: the coupling stiffness
      // grows as 1/ℓ³ and a 1 ft bit cut into 10 elements would make the couplings 1000 times
      // stiffer than the rest of the model for no accuracy (ill-conditioned tangents).
      spec.element_count = std::clamp<Index>(
          std::lround(settings.elements_per_body * spec.length / settings.body_length), 2, settings.elements_per_body);
      reduction.modes_per_body = std::min<Index>(settings.modes_per_body, 6 * (spec.element_count - 1));
      spec.options = FeOptions(settings);
      const auto reduced = ReduceSection(cache, spec, reduction, component, c);
      // Once per section (it was 2/3 of the build time of a 1000-body string when made per body).
      const MatX mass_correction = cms::ReferenceMassMatrix(*reduced) - cms::NodalReferenceMassMatrix(*reduced);
      double body_start = stretch_start;
      for (Index i = 0; i < count; ++i) {
        bodies.push_back(
            MakeBody(reduced, spec, c, body_start, ContactDiameter(component), mass_correction));
        body_start += spec.length;
      }
      stretch_start = stretch_end;
    }
    s += span;
  }
  Index q_offset = 0, v_offset = 0;
  for (Body& body : bodies) {
    body.q_offset = q_offset;
    body.v_offset = v_offset;
    q_offset += body.position_count();
    v_offset += body.velocity_count();
  }
  return bodies;
}

}  // namespace drillflex::model
