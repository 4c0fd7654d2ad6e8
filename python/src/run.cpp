// drillflex._core.run: a case through pipeline::RunCase with the GIL released (a Python callback for
// progress and notes takes it back only while it runs), and the finished run's summaries and
// results.json (pipeline::ComposeResultFiles, what the command line writes).
#include <sstream>

#include <pybind11/stl.h>

#include "bindings.hpp"
#include "pipeline/case_files.hpp"
#include "pipeline/summary.hpp"

namespace drillflex::python {
namespace {

pipeline::Analysis ParseAnalysis(const std::string& name) {
  for (const pipeline::Analysis analysis : kAnalyses) {
    if (name == pipeline::AnalysisName(analysis)) return analysis;
  }
  throw py::value_error("unknown analysis '" + name + "': expected static, modes, vibration, buckling, transient or tendency");
}

// `analyses`: names of analyses, or ["run"] for those the case lists.
pipeline::AnalysisRequest Request(const io::Case& c, const std::vector<std::string>& analyses) {
  if (analyses.size() == 1 && analyses.front() == "run") return pipeline::CaseAnalyses(c);
  pipeline::AnalysisRequest request;
  for (const std::string& name : analyses) {
    switch (ParseAnalysis(name)) {
      case pipeline::Analysis::Static: request.static_analysis = true; break;
      case pipeline::Analysis::Modes: request.modes = true; break;
      case pipeline::Analysis::Buckling: request.buckling = true; break;
      case pipeline::Analysis::Vibration: request.vibration = true; break;
      case pipeline::Analysis::Transient: request.transient = true; break;
      case pipeline::Analysis::Tendency: request.tendency = true; break;
    }
  }
  if (!request.Any()) throw py::value_error("no analysis to run");
  return request;
}

RunHandle Run(const CaseHandle& c, const std::vector<std::string>& analyses, const py::object& progress,
              const py::object& log, bool keep_finished) {
  const pipeline::AnalysisRequest request = Request(*c.c, analyses);
  pipeline::RunOptions options;
  options.keep_finished = keep_finished;
  // The callbacks hold references only: a py::object is not copied without the GIL.
  if (!progress.is_none()) {
    options.observer.progress = [&progress](pipeline::Analysis analysis, double done, double total) {
      py::gil_scoped_acquire gil;
      progress(pipeline::AnalysisName(analysis), done, total);
    };
  }
  if (!log.is_none()) {
    options.observer.note = [&log](const std::string& line) {
      py::gil_scoped_acquire gil;
      log(line);
    };
  }
  py::gil_scoped_release release;
  return {c.c, std::make_shared<const pipeline::CaseResults>(pipeline::RunCase(*c.c, request, options))};
}

}  // namespace

void BindRun(py::module_& m) {
  py::class_<RunHandle> run(m, "Run", "A finished run of a case: its typed results, summaries and results.json.");
  run.def(
         "summary",
         [](const RunHandle& self, const std::string& analysis) {
           std::ostringstream out;
           pipeline::WriteSummary(out, *self.c, ParseAnalysis(analysis), *self.results);
           return out.str();
         },
         py::arg("analysis"), "The command line's summary of one analysis, in the case's units.")
      .def(
          "results_json",
          [](const RunHandle& self) {
            std::string json;
            std::vector<std::pair<std::string, std::string>> tables;
            {
              py::gil_scoped_release release;
              const io::ResultFiles files = pipeline::ComposeResultFiles(*self.c, *self.results, {});
              json = files.json().dump();
              tables = files.files();
            }
            return std::pair(py::str(json), tables);
          },
          "(results.json's text, [(CSV file name, its text)]): what the command line writes for this run.")
      .def_property_readonly(
          "failures",
          [](const RunHandle& self) {
            std::vector<std::pair<std::string, std::string>> failures;
            for (const pipeline::AnalysisFailure& failure : self.results->failures) {
              failures.emplace_back(pipeline::AnalysisName(failure.analysis), failure.message);
            }
            return failures;
          },
          "[(analysis, why)]: the analyses of a run with keep_finished that did not finish.")
      .def_property_readonly("analyses", [](const RunHandle& self) {
        std::vector<std::string> names;
        for (const pipeline::Analysis analysis : kAnalyses) {
          if (self.results->requested.Has(analysis)) names.emplace_back(pipeline::AnalysisName(analysis));
        }
        return names;
      });
  BindStaticResult(run);
  BindModesResult(run);
  BindVibrationResult(run);
  BindBucklingResult(run);
  BindTransientResult(run);
  BindTendencyResult(run);

  m.def("run", &Run, py::arg("case"), py::arg("analyses"), py::arg("progress") = py::none(), py::arg("log") = py::none(),
        py::arg("keep_finished") = false,
        "Runs `analyses` (names, or ['run'] for the case's own) of a case. `progress(analysis, done, total)` and "
        "`log(line)` (the run's notes) are called from the run, which holds the GIL only while they run. "
        "`keep_finished`: a solver's failure is kept in `failures` and the other analyses run on "
        "(pipeline::RunOptions::keep_finished); else it raises.");
}

}  // namespace drillflex::python
