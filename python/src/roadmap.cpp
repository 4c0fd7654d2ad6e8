// drillflex._core.roadmap: a case's torque-and-drag roadmap through pipeline::RunRoadmap (the command
// line's `drillflex roadmap`) with the GIL released, its points in SI and roadmap.json / roadmap.csv
// as the command line writes them (pipeline::ComposeRoadmapFiles).
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "pipeline/roadmap.hpp"

namespace drillflex::python {
namespace {

py::array_t<double> Column(const std::vector<pipeline::RoadmapPoint>& points, double pipeline::RoadmapPoint::*field) {
  py::array_t<double> column(static_cast<py::ssize_t>(points.size()));
  auto out = column.mutable_unchecked<1>();
  for (std::size_t i = 0; i < points.size(); ++i) out(static_cast<py::ssize_t>(i)) = points[i].*field;
  return column;
}

// `jobs` points at once; progress("roadmap", done, total) after each point.
py::dict Roadmap(const CaseHandle& c, int jobs, const py::object& progress) {
  if (jobs < 1) throw py::value_error("jobs must be at least 1");
  analyses::RoadmapSettings settings;
  std::vector<pipeline::RoadmapPoint> points;
  io::ResultFiles files("", "roadmap.json");
  {
    pipeline::RoadmapOptions options;
    options.jobs = jobs;
    // The callback holds a reference only: a py::object is not copied without the GIL.
    if (!progress.is_none()) {
      options.progress = [&progress](int done, int total, int, double) {
        py::gil_scoped_acquire gil;
        progress("roadmap", static_cast<double>(done), static_cast<double>(total));
      };
    }
    py::gil_scoped_release release;
    settings = pipeline::CompleteRoadmapSettings(*c.c, c.c->analyses.roadmap.value_or(analyses::RoadmapSettings{}));
    points = pipeline::RunRoadmap(*c.c, settings, options);
    files = pipeline::ComposeRoadmapFiles(*c.c, settings, points, "", false, 0.0);
  }
  py::dict result;
  result["bit_md"] = Column(points, &pipeline::RoadmapPoint::bit_md);
  result["friction"] = Column(points, &pipeline::RoadmapPoint::friction);
  result["pick_up"] = Column(points, &pipeline::RoadmapPoint::pick_up);
  result["slack_off"] = Column(points, &pipeline::RoadmapPoint::slack_off);
  result["rotating"] = Column(points, &pipeline::RoadmapPoint::rotating);
  result["off_bottom_torque"] = Column(points, &pipeline::RoadmapPoint::off_bottom_torque);
  result["on_bottom_torque"] = Column(points, &pipeline::RoadmapPoint::on_bottom_torque);
  std::vector<std::string> messages;
  for (const pipeline::RoadmapPoint& point : points) messages.push_back(point.message);
  result["message"] = messages;
  py::dict used;
  used["from_md"] = settings.from_md;
  used["step"] = settings.step;
  used["friction"] = settings.friction;
  used["rotary_speed"] = settings.rotary_speed;
  used["trip_speed"] = settings.trip_speed;
  result["settings"] = used;
  result["json"] = files.json().dump();
  result["tables"] = files.files();
  return result;
}

}  // namespace

void BindRoadmap(py::module_& m) {
  m.def("roadmap", &Roadmap, py::arg("case"), py::arg("jobs") = 1, py::arg("progress") = py::none(),
        "The case's torque-and-drag roadmap (its analyses.roadmap settings): the points in SI, the settings "
        "used, and roadmap.json's text with [(roadmap.csv, its text)] as the command line writes them.");
}

}  // namespace drillflex::python
