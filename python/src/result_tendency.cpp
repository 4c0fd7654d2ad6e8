// A run's tendency for drillflex.TendencyResult: the steady build and turn rates and the search's
// statics (SI: curvatures in 1/m, forces in N, angles in rad).
#include <pybind11/stl.h>

#include "analyses/tendency_analysis.hpp"
#include "arrays.hpp"

namespace drillflex::python {

void BindTendencyResult(py::class_<RunHandle>& run) {
  DefFields(run, "tendency_fields", &pipeline::CaseResults::tendency,
            [](const RunHandle& handle, const analyses::TendencyResult& result, const py::capsule&) {
    py::dict fields;
    fields["build_rate"] = result.build_rate;
    fields["turn_rate"] = result.turn_rate;
    fields["right_curvature"] = result.curvature.right;
    fields["dogleg_severity"] = result.dogleg_severity;
    fields["inclination"] = result.inclination;
    fields["azimuth"] = result.azimuth;
    fields["steerability"] = result.steerability;
    fields["weight_on_bit"] = result.weight_on_bit;
    fields["arc_length"] = result.arc_length;
    fields["steady_index"] = result.steady_index;
    fields["toolfaces"] = result.toolfaces;
    fields["statics"] = result.statics;
    if (result.steering) {
      const analyses::SteeringRates& steering = *result.steering;
      py::dict fields_steering(py::arg("steer") = steering.steer, py::arg("natural_build") = steering.natural.build,
                               py::arg("natural_right") = steering.natural.right,
                               py::arg("full_build") = steering.full.build, py::arg("full_right") = steering.full.right);
      // The system as the case set it: a push-the-bit's pads' force (N), a point-the-bit's offset (rad).
      const auto& tendency = handle.c->analyses.tendency;
      if (tendency && tendency->rss) {
        const bool point = tendency->rss->type == analyses::RssType::Point;
        fields_steering["type"] = point ? "point" : "push";
        fields_steering["toolface"] = tendency->rss->toolface;
        fields_steering["offset"] = point ? tendency->rss->offset : 0.0;
        fields_steering["force"] = point ? 0.0 : tendency->rss->force;
      }
      fields["steering"] = fields_steering;
    } else {
      fields["steering"] = py::none();
    }
    py::list trace;
    for (const analyses::TendencyPoint& point : result.trace) {
      trace.append(py::dict(py::arg("build_curvature") = point.curvature.build,
                            py::arg("right_curvature") = point.curvature.right,
                            py::arg("build_force") = point.bit.build_force, py::arg("walk_force") = point.bit.walk_force,
                            py::arg("side_force") = point.bit.side_force, py::arg("tilt") = point.bit.tilt,
                            py::arg("tilt_right") = point.bit.tilt_right,
                            py::arg("deviation_build") = point.deviation_build,
                            py::arg("deviation_right") = point.deviation_right, py::arg("method") = point.method));
    }
    fields["trace"] = trace;
    return fields;
  });
}

}  // namespace drillflex::python
