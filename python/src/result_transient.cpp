// A run's transient for drillflex.TransientResult: the samples' series as arrays that view the run's
// own storage, the probes' series (copied: each sample holds its own list), the final state and the
// integration's figures (SI).
#include <pybind11/stl.h>

#include "analyses/transient_analysis.hpp"
#include "arrays.hpp"

namespace drillflex::python {
namespace {

using analyses::ProbeSample;
using analyses::TransientSample;

// One probe quantity per sample and probe: an (samples, probes) array.
py::array ProbeSeries(const std::vector<TransientSample>& samples, std::size_t probes, double ProbeSample::*field) {
  py::array_t<double> series = Matrix(samples.size(), probes);
  for (std::size_t i = 0; i < samples.size(); ++i) {
    for (std::size_t k = 0; k < probes; ++k) {
      const auto& row = samples[i].probes;
      series.mutable_at(static_cast<py::ssize_t>(i), static_cast<py::ssize_t>(k)) = k < row.size() ? row[k].*field : 0.0;
    }
  }
  return series;
}

}  // namespace

void BindTransientResult(py::class_<RunHandle>& run) {
  DefFields(run, "transient_fields", &pipeline::CaseResults::transient,
            [](const RunHandle&, const analyses::TransientResult& result, const py::capsule& owner) {
    const std::vector<TransientSample>& samples = result.samples;
    py::dict series;
    series["time"] = FieldView(samples, &TransientSample::time, owner);
    series["surface_speed"] = FieldView(samples, &TransientSample::surface_speed, owner);
    series["surface_torque"] = FieldView(samples, &TransientSample::surface_torque, owner);
    series["hook_load"] = FieldView(samples, &TransientSample::hook_load, owner);
    series["bit_speed"] = FieldView(samples, &TransientSample::bit_speed, owner);
    series["weight_on_bit"] = FieldView(samples, &TransientSample::weight_on_bit, owner);
    series["torque_on_bit"] = FieldView(samples, &TransientSample::torque_on_bit, owner);
    series["kinetic_energy"] = FieldView(samples, &TransientSample::kinetic_energy, owner);
    series["potential_energy"] = FieldView(samples, &TransientSample::potential_energy, owner);
    const std::size_t probes = result.probe_s.size();
    py::dict probe_series;
    probe_series["lateral_y"] = ProbeSeries(samples, probes, &ProbeSample::lateral_y);
    probe_series["lateral_z"] = ProbeSeries(samples, probes, &ProbeSample::lateral_z);
    probe_series["whirl_angle"] = ProbeSeries(samples, probes, &ProbeSample::whirl_angle);
    probe_series["contact_force"] = ProbeSeries(samples, probes, &ProbeSample::contact_force);
    probe_series["bending_moment"] = ProbeSeries(samples, probes, &ProbeSample::bending_moment);
    const solvers::GeneralizedAlphaStatistics& statistics = result.statistics;
    py::dict fields;
    fields["samples"] = series;
    fields["probe_s"] = VectorView(result.probe_s, owner);
    fields["probes"] = probe_series;
    fields["final_q"] = VectorView(result.final_q, owner);
    fields["final_v"] = VectorView(result.final_v, owner);
    fields["frame_times"] = VectorView(result.frame_times, owner);
    fields["energy_drift"] = result.energy_drift;
    fields["rho_infinity"] = result.rho_infinity;
    fields["statistics"] = py::dict(py::arg("steps") = statistics.steps, py::arg("error_rejections") = statistics.error_rejections,
                                    py::arg("newton_failures") = statistics.newton_failures,
                                    py::arg("newton_iterations") = statistics.newton_iterations,
                                    py::arg("factorizations") = statistics.factorizations,
                                    py::arg("residual_evaluations") = statistics.residual_evaluations,
                                    py::arg("smallest_step") = statistics.smallest_step,
                                    py::arg("largest_step") = statistics.largest_step);
    return fields;
  });
}

}  // namespace drillflex::python
