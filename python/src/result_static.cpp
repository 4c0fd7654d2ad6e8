// A run's static result for drillflex.StaticResult (python/drillflex/results.py): its figures, and its
// stations and contacts as columns of arrays that view the run's own storage (SI).
#include <pybind11/stl.h>

#include "analyses/bit_tendency.hpp"
#include "arrays.hpp"
#include "io/analysis_results.hpp"

namespace drillflex::python {
namespace {

using analyses::ContactReport;
using analyses::StaticNodeResult;

py::dict Stations(const io::Case& c, const std::vector<StaticNodeResult>& nodes, const py::capsule& owner) {
  py::dict columns;
  columns["s"] = FieldView(nodes, &StaticNodeResult::s, owner);
  const bool wall = !nodes.empty() && nodes.front().has_wall;
  if (wall) {
    columns["md"] = FieldView(nodes, &StaticNodeResult::md, owner);
  } else {
    py::array_t<double> md(static_cast<py::ssize_t>(nodes.size()));
    for (std::size_t i = 0; i < nodes.size(); ++i) md.mutable_at(static_cast<py::ssize_t>(i)) = io::StationMd(c, nodes[i].s);
    columns["md"] = md;
  }
  columns["position"] = FieldView(nodes, &StaticNodeResult::position, owner);
  columns["displacement"] = FieldView(nodes, &StaticNodeResult::displacement, owner);
  columns["rotation"] = FieldView(nodes, &StaticNodeResult::rotation, owner);
  columns["lateral_offset"] = FieldView(nodes, &StaticNodeResult::lateral_offset, owner);
  columns["axial_force"] = FieldView(nodes, &StaticNodeResult::axial_force, owner);
  columns["torque"] = FieldView(nodes, &StaticNodeResult::torque, owner);
  columns["bending_moment"] = FieldView(nodes, &StaticNodeResult::bending_moment, owner);
  columns["shear_force"] = FieldView(nodes, &StaticNodeResult::shear_force, owner);
  columns["force"] = FieldView(nodes, &StaticNodeResult::force, owner);
  columns["moment"] = FieldView(nodes, &StaticNodeResult::moment, owner);
  columns["bending_stress"] = FieldView(nodes, &StaticNodeResult::bending_stress, owner);
  columns["von_mises_stress"] = FieldView(nodes, &StaticNodeResult::von_mises_stress, owner);
  if (wall) {
    columns["wall_contact"] = FieldView(nodes, &StaticNodeResult::wall_contact, owner);
    columns["hole_offset"] = FieldView(nodes, &StaticNodeResult::hole_offset, owner);
    columns["offset_high_side_angle"] = FieldView(nodes, &StaticNodeResult::offset_high_side_angle, owner);
    columns["clearance"] = FieldView(nodes, &StaticNodeResult::clearance, owner);
    columns["hole_diameter"] = FieldView(nodes, &StaticNodeResult::hole_diameter, owner);
  }
  return columns;
}

py::dict Contacts(const io::Case& c, const std::vector<ContactReport>& contacts, const py::capsule& owner) {
  py::dict columns;
  columns["s"] = FieldView(contacts, &ContactReport::s, owner);
  columns["md"] = FieldView(contacts, &ContactReport::md, owner);
  columns["normal_force"] = FieldView(contacts, &ContactReport::normal_force, owner);
  columns["friction_force"] = FieldView(contacts, &ContactReport::friction_force, owner);
  columns["high_side_angle"] = FieldView(contacts, &ContactReport::high_side_angle, owner);
  columns["component"] = FieldView(contacts, &ContactReport::component, owner);
  columns["contact_point"] = FieldView(contacts, &ContactReport::contact_point, owner);
  columns["normal"] = FieldView(contacts, &ContactReport::normal, owner);
  py::list names;
  for (const ContactReport& contact : contacts) {
    const auto& components = c.input.string.components;
    const bool known = contact.component >= 0 && contact.component < static_cast<int>(components.size());
    names.append(known ? components[static_cast<std::size_t>(contact.component)].name : std::string());
  }
  columns["component_name"] = names;
  return columns;
}

py::object Bit(const std::optional<analyses::BitReport>& bit) {
  if (!bit) return py::none();
  const analyses::BitTendency tendency = analyses::ClassifyBitTendency(*bit);
  py::dict fields;
  fields["side_force"] = bit->side_force;
  fields["build_force"] = bit->build_force;
  fields["walk_force"] = bit->walk_force;
  fields["tilt"] = bit->tilt;
  fields["inclination_tendency"] = std::string(analyses::TendencyName(tendency.inclination));
  fields["azimuth_tendency"] = std::string(analyses::TendencyName(tendency.azimuth));
  fields["tendency_threshold"] = tendency.threshold;
  return fields;
}

}  // namespace

void BindStaticResult(py::class_<RunHandle>& run) {
  DefFields(run, "static_fields", &pipeline::CaseResults::static_result,
            [](const RunHandle& self, const analyses::StaticResult& result, const py::capsule& owner) {
    py::dict fields;
    fields["converged"] = result.converged;
    fields["iterations"] = result.iterations;
    fields["load_steps"] = result.load_steps;
    fields["residual_norm"] = result.residual_norm;
    fields["method"] = result.method;
    fields["warnings"] = result.warnings;
    fields["stable"] = result.stable;
    fields["q"] = VectorView(result.q, owner);
    fields["nodes"] = Stations(*self.c, result.nodes, owner);
    fields["contacts"] = Contacts(*self.c, result.contacts, owner);
    py::list reactions;
    for (const analyses::SupportReaction& reaction : result.reactions) {
      reactions.append(py::dict(py::arg("s") = reaction.s, py::arg("force") = py::make_tuple(reaction.force.x(), reaction.force.y(), reaction.force.z()),
                                py::arg("moment") = py::make_tuple(reaction.moment.x(), reaction.moment.y(), reaction.moment.z())));
    }
    fields["reactions"] = reactions;
    fields["bit"] = Bit(result.bit);
    if (result.pipe_above) {
      const analyses::PipeAboveReaction& pipe = *result.pipe_above;
      fields["pipe_above"] =
          py::dict(py::arg("s") = pipe.s, py::arg("force") = py::make_tuple(pipe.force.x(), pipe.force.y(), pipe.force.z()),
                   py::arg("moment") = py::make_tuple(pipe.moment.x(), pipe.moment.y(), pipe.moment.z()),
                   py::arg("tension") = pipe.tension, py::arg("buckled") = pipe.buckled);
    } else {
      fields["pipe_above"] = py::none();
    }
    if (result.mwd) {
      const analyses::MwdSag& mwd = *result.mwd;
      fields["mwd"] = py::dict(py::arg("s") = mwd.s, py::arg("md") = mwd.md,
                               py::arg("axis_inclination") = mwd.axis_inclination,
                               py::arg("hole_inclination") = mwd.hole_inclination, py::arg("sag") = mwd.sag,
                               py::arg("axis_azimuth") = mwd.axis_azimuth, py::arg("hole_azimuth") = mwd.hole_azimuth);
    } else {
      fields["mwd"] = py::none();
    }
    return fields;
  });
}

}  // namespace drillflex::python
