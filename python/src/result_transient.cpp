// A run's transient for drillflex.TransientResult: the samples' series as arrays that view the run's
// own storage, the probes' series (copied: each sample holds its own list), the final state and the
// integration's figures (SI).
#include <pybind11/stl.h>

#include "analyses/limits_envelope.hpp"
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

// Column `limit` of a table of LimitValues (one row a station or a sample): a strided view.
py::array LimitColumn(const std::vector<analyses::LimitValues>& rows, std::size_t limit, const py::capsule& owner) {
  return View<double>({static_cast<py::ssize_t>(rows.size())}, {sizeof(analyses::LimitValues)},
                      rows.empty() ? nullptr : &rows.front()[limit], owner);
}

// The string's limits at every sample (analyses::LimitsEnvelope), SI: per limit name the stations'
// largest utilisation and when, the history along the samples, and the summary entry (None: the limit
// applies nowhere).
py::object TransientLimits(const std::optional<analyses::LimitsEnvelope>& envelope, const py::capsule& owner) {
  if (!envelope) return py::none();
  py::dict largest, when, history, summary;
  for (std::size_t k = 0; k < analyses::kEnvelopeLimits; ++k) {
    const char* name = analyses::EnvelopeLimitName(k);
    largest[name] = LimitColumn(envelope->largest, k, owner);
    when[name] = LimitColumn(envelope->when, k, owner);
    history[name] = LimitColumn(envelope->history, k, owner);
    const analyses::LimitUtilisation& entry = envelope->summary[k];
    if (entry.limit.empty()) {
      summary[name] = py::none();
      continue;
    }
    summary[name] = py::dict(py::arg("limit") = entry.limit, py::arg("utilisation") = entry.utilisation,
                             py::arg("s") = entry.s, py::arg("md") = entry.md, py::arg("component") = entry.component,
                             py::arg("time") = envelope->summary_time[k]);
  }
  const std::size_t closest = envelope->closest();
  py::dict fields;
  fields["design_factor"] = envelope->design_factor;
  fields["s"] = FieldView(envelope->stations, &analyses::NodeLimits::s, owner);
  fields["md"] = FieldView(envelope->stations, &analyses::NodeLimits::md, owner);
  fields["component"] = FieldView(envelope->stations, &analyses::NodeLimits::component, owner);
  fields["times"] = VectorView(envelope->times, owner);
  fields["largest"] = largest;
  fields["when"] = when;
  fields["history"] = history;
  fields["summary"] = summary;
  fields["closest"] = closest < analyses::kEnvelopeLimits ? py::object(py::str(analyses::EnvelopeLimitName(closest)))
                                                          : py::object(py::none());
  return fields;
}

}  // namespace

void BindTransientResult(py::class_<RunHandle>& run) {
  DefFields(run, "transient_fields", &pipeline::CaseResults::transient,
            [](const RunHandle& run, const analyses::TransientResult& result, const py::capsule& owner) {
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
    fields["limits"] = TransientLimits(run.results->transient_limits, owner);
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
