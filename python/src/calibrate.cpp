// drillflex._core.calibrate: the friction factors, hook-load offset and bit torque coefficient fitted to
// the rig's readings through pipeline::Calibrate (the command line's `drillflex calibrate`) with the GIL
// released; results.json's text and calibration.csv as the command line writes them
// (pipeline::ComposeCalibrationFiles).
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "io/rig_readings.hpp"
#include "pipeline/calibration.hpp"

namespace drillflex::python {
namespace {

py::dict Calibrate(const CaseHandle& c, const std::string& readings_path, const std::vector<std::string>& fit,
                   const std::string& model, int jobs) {
  if (jobs < 1) throw py::value_error("jobs must be at least 1");
  pipeline::CalibrationSettings settings;
  for (const std::string& name : fit) {
    const auto parameter = pipeline::CalibrationParameterOf(name);
    if (!parameter) throw py::value_error("unknown parameter '" + name + "'");
    settings.fit.push_back(*parameter);
  }
  if (model == "soft") settings.model.kind = pipeline::ReadingsModelKind::kSoft;
  else if (model != "stiff") throw py::value_error("model must be 'stiff' or 'soft'");
  settings.model.jobs = jobs;
  settings.model.roadmap = c.c->analyses.roadmap.value_or(analyses::RoadmapSettings{});
  io::ResultFiles files("");
  {
    py::gil_scoped_release release;
    io::RigReadingsOptions options;
    if (c.c->input.well) options.deepest_md = c.c->input.well->trajectory.end_md();
    const io::RigReadings readings = io::ReadRigReadings(readings_path, options);
    const pipeline::CalibrationResult result = pipeline::Calibrate(*c.c, readings, settings);
    files = pipeline::ComposeCalibrationFiles(*c.c, readings, result, "", false, 0.0);
  }
  py::dict out;
  out["json"] = files.json().dump();
  out["tables"] = files.files();
  return out;
}

}  // namespace

void BindCalibrate(py::module_& m) {
  m.def("calibrate", &Calibrate, py::arg("case"), py::arg("readings"), py::arg("fit") = std::vector<std::string>{},
        py::arg("model") = "stiff", py::arg("jobs") = 1,
        "The case's torque-and-drag model fitted to the rig's readings: results.json's text (its `calibration`) "
        "and [(calibration.csv, its text)] as the command line writes them.");
}

}  // namespace drillflex::python
