// A run's modes (and Campbell diagram) for drillflex.ModesResult: per mode its figures as arrays that
// view the run's own storage, its shape per station, and the first lateral mode's critical speed (SI).
#include <pybind11/stl.h>

#include "analyses/gyroscopic_modes.hpp"
#include "arrays.hpp"

namespace drillflex::python {
namespace {

using analyses::ModeResult;

py::dict Campbell(const analyses::CampbellResult& campbell) {
  const std::size_t columns = campbell.points.empty() ? 0 : campbell.points.front().modes.size();
  py::array_t<double> speed(static_cast<py::ssize_t>(campbell.points.size()));
  py::array_t<double> frequency = Matrix(campbell.points.size(), columns);
  for (std::size_t i = 0; i < campbell.points.size(); ++i) {
    const auto row = static_cast<py::ssize_t>(i);
    speed.mutable_at(row) = campbell.points[i].rotary_speed;
    for (std::size_t j = 0; j < columns; ++j) {
      const auto& modes = campbell.points[i].modes;
      frequency.mutable_at(row, static_cast<py::ssize_t>(j)) = j < modes.size() ? modes[j].frequency_hz : 0.0;
    }
  }
  py::list synchronous;
  for (const analyses::CampbellCrossing& crossing : campbell.synchronous) {
    synchronous.append(py::dict(py::arg("rotary_speed") = crossing.rotary_speed, py::arg("frequency_hz") = crossing.frequency_hz,
                                py::arg("branch") = crossing.branch, py::arg("whirl") = analyses::WhirlName(crossing.whirl)));
  }
  return py::dict(py::arg("rotary_speed") = speed, py::arg("frequency_hz") = frequency, py::arg("synchronous") = synchronous,
                  py::arg("basis_size") = campbell.basis_size);
}

}  // namespace

void BindModesResult(py::class_<RunHandle>& run) {
  DefFields(run, "modes_fields", &pipeline::CaseResults::modes,
            [](const RunHandle& self, const analyses::ModesResult& result, const py::capsule& owner) {
    const std::vector<ModeResult>& modes = result.modes;
    py::dict fields;
    fields["s"] = VectorView(result.s, owner);
    fields["frequency_hz"] = FieldView(modes, &ModeResult::frequency_hz, owner);
    fields["eigenvalue"] = FieldView(modes, &ModeResult::eigenvalue, owner);
    fields["damping_ratio"] = FieldView(modes, &ModeResult::damping_ratio, owner);
    fields["axial_fraction"] = FieldView(modes, &ModeResult::axial_fraction, owner);
    fields["torsional_fraction"] = FieldView(modes, &ModeResult::torsional_fraction, owner);
    fields["lateral_fraction"] = FieldView(modes, &ModeResult::lateral_fraction, owner);
    fields["rigid_body"] = FieldView(modes, &ModeResult::rigid_body, owner);
    fields["negative_stiffness"] = FieldView(modes, &ModeResult::negative_stiffness, owner);
    fields["near_zero"] = FieldView(modes, &ModeResult::near_zero, owner);
    fields["whirl_index"] = FieldView(modes, &ModeResult::whirl_index, owner);
    py::list kinds, whirls, displacements, rotations;
    for (const ModeResult& mode : modes) {
      kinds.append(analyses::ModeKindName(mode.kind));
      whirls.append(analyses::WhirlName(mode.whirl));
      displacements.append(Vec3View(mode.displacement, owner));
      rotations.append(Vec3View(mode.rotation, owner));
    }
    fields["kind"] = kinds;
    fields["whirl"] = whirls;
    fields["displacement"] = displacements;
    fields["rotation"] = rotations;
    fields["rigid_body_modes"] = result.rigid_body_modes;
    fields["near_zero_modes"] = result.near_zero_modes;
    fields["negative_stiffness_modes"] = result.negative_stiffness_modes;
    fields["gyroscopic"] = result.gyroscopic;
    fields["rotary_speed"] = result.rotary_speed;
    const ModeResult* lateral = analyses::FirstLateralMode(result);
    fields["first_lateral"] = lateral ? py::object(py::int_(lateral - modes.data())) : py::object(py::none());
    fields["critical_speed"] = lateral ? py::object(py::float_(2.0 * kPi * lateral->frequency_hz)) : py::object(py::none());
    fields["campbell"] = self.results->campbell ? py::object(Campbell(*self.results->campbell)) : py::object(py::none());
    return fields;
  });
}

}  // namespace drillflex::python
