// A run's buckling result for drillflex.BucklingResult: the critical multiplier and load, the
// frequency-against-load table and the buckled shape as arrays that view the run's own storage (SI).
#include <pybind11/stl.h>

#include "analyses/buckling_analysis.hpp"
#include "arrays.hpp"

namespace drillflex::python {

void BindBucklingResult(py::class_<RunHandle>& run) {
  DefFields(run, "buckling_fields", &pipeline::CaseResults::buckling,
            [](const RunHandle&, const analyses::BucklingResult& result, const py::capsule& owner) {
    using analyses::FrequencyLoadPoint;
    py::dict fields;
    fields["scaled_wob"] = result.scaled_wob;
    fields["about_equilibrium"] = result.about_equilibrium;
    fields["lower_bound"] = result.lower_bound;
    fields["buckled_at_case_loads"] = result.buckled_at_case_loads;
    fields["onset_above_model"] = result.onset_above_model;
    fields["critical_wob"] = result.critical_wob;
    fields["load_factor"] = result.load_factor;
    fields["critical_load"] = result.critical_load;
    fields["load_factors"] = VectorView(result.load_factors, owner);
    fields["reference_load_factor"] = result.reference_load_factor;
    fields["reference_compression"] = result.reference_compression;
    fields["frequency_method_converged"] = result.frequency_method_converged;
    fields["frequency_load_factor"] = result.frequency_load_factor;
    fields["frequency_critical_load"] = result.frequency_critical_load;
    fields["unloaded_frequency_hz"] = result.unloaded_frequency_hz;
    const std::vector<FrequencyLoadPoint>& table = result.frequency_table;
    fields["frequency_table"] = py::dict(py::arg("load_factor") = FieldView(table, &FrequencyLoadPoint::load_factor, owner),
                                         py::arg("compression") = FieldView(table, &FrequencyLoadPoint::compression, owner),
                                         py::arg("frequency_hz") = FieldView(table, &FrequencyLoadPoint::frequency_hz, owner));
    fields["s"] = VectorView(result.s, owner);
    fields["mode_displacement"] = Vec3View(result.mode_displacement, owner);
    fields["mode_rotation"] = Vec3View(result.mode_rotation, owner);
    const analyses::SinusoidalBucklingScreen& screen = result.sinusoidal;
    fields["sinusoidal"] =
        screen.computed ? py::object(py::dict(py::arg("load_factor") = screen.load_factor, py::arg("s") = screen.s,
                                              py::arg("md") = screen.md, py::arg("compression") = screen.compression,
                                              py::arg("sinusoidal_load") = screen.sinusoidal_load,
                                              py::arg("helical_load") = screen.helical_load,
                                              py::arg("largest_ratio") = screen.largest_ratio))
                        : py::object(py::none());
    return fields;
  });
}

}  // namespace drillflex::python
