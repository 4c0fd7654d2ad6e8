// A run's forced response against RPM for drillflex.VibrationResult: the sweep's curves as arrays that
// view the run's own storage, the critical speeds and the windows (SI: rad/s, m, Pa, N).
#include <pybind11/stl.h>

#include "analyses/vibration_analysis.hpp"
#include "arrays.hpp"

namespace drillflex::python {
namespace {

// The windows as an (n, 2) array of (from, to).
py::array Windows(const std::vector<analyses::SpeedWindow>& windows, const py::capsule& owner) {
  return View<double>({static_cast<py::ssize_t>(windows.size()), 2}, {sizeof(analyses::SpeedWindow), sizeof(double)},
                      windows.empty() ? nullptr : &windows.front().from, owner);
}

}  // namespace

void BindVibrationResult(py::class_<RunHandle>& run) {
  DefFields(run, "vibration_fields", &pipeline::CaseResults::vibration,
            [](const RunHandle&, const analyses::VibrationResult& result, const py::capsule& owner) {
    py::dict fields;
    fields["rotary_speed"] = VectorView(result.rotary_speeds, owner);
    fields["max_lateral_displacement"] = VectorView(result.max_lateral_displacement, owner);
    fields["max_clearance_ratio"] = VectorView(result.max_clearance_ratio, owner);
    fields["max_bending_stress"] = VectorView(result.max_bending_stress, owner);
    fields["max_contact_force"] = VectorView(result.max_contact_force, owner);
    fields["s_max_displacement"] = VectorView(result.s_max_displacement, owner);
    fields["critical_rotary_speed"] = VectorView(result.critical_rotary_speeds, owner);
    py::list critical;
    for (const analyses::CriticalSpeed& speed : result.critical_speeds) {
      critical.append(py::dict(py::arg("rotary_speed") = speed.rotary_speed, py::arg("severity") = speed.severity,
                               py::arg("displacement") = speed.displacement, py::arg("bending_stress") = speed.bending_stress,
                               py::arg("excitation") = speed.excitation, py::arg("frequency") = speed.frequency));
    }
    fields["critical_speeds"] = critical;
    fields["safe_windows"] = Windows(result.safe_windows, owner);
    fields["quietest_windows"] = Windows(result.quietest_windows, owner);
    fields["clearance_fraction"] = result.clearance_fraction;
    fields["stress_limit"] = result.stress_limit;
    fields["closed_contacts"] = result.closed_contacts;
    fields["excitation_frequencies"] = VectorView(result.excitation_frequencies, owner);
    py::list per_excitation;
    for (const std::vector<double>& curve : result.excitation_displacement) per_excitation.append(VectorView(curve, owner));
    fields["excitation_displacement"] = per_excitation;
    fields["method"] = result.method == analyses::VibrationMethod::Reduced ? "reduced" : "direct";
    fields["basis_size"] = result.basis_size;
    fields["reduced_check_error"] = result.reduced_check_error;
    fields["band_modes"] = result.band_modes;
    fields["method_note"] = result.method_note;
    return fields;
  });
}

}  // namespace drillflex::python
