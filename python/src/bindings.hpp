// What the files of the Python extension drillflex._core share: the handles Python holds and the
// functions that add each part to the module (docs/python.md).
#pragma once

#include <memory>

#include <pybind11/pybind11.h>

#include "io/case.hpp"
#include "pipeline/case_run.hpp"

namespace drillflex::python {

namespace py = pybind11;

// The analyses in the order a run makes them (the command line's `run`).
inline constexpr pipeline::Analysis kAnalyses[] = {pipeline::Analysis::Static, pipeline::Analysis::Modes,
                                                   pipeline::Analysis::Vibration, pipeline::Analysis::Buckling,
                                                   pipeline::Analysis::Transient, pipeline::Analysis::Tendency};

// A case as Python holds it: immutable once read, shared by the runs made from it.
struct CaseHandle {
  std::shared_ptr<const io::Case> c;
};

// A finished run: the case it ran and everything it computed. The typed results' arrays are views of
// `results` and keep it alive (ResultOwner).
struct RunHandle {
  std::shared_ptr<const io::Case> c;
  std::shared_ptr<const pipeline::CaseResults> results;
};

// InputError, UnitError and SolverError raised as drillflex.InputError, drillflex.UnitError and
// drillflex.ConvergenceError (python/drillflex/errors.py).
void BindErrors(py::module_& m);
void BindUnits(py::module_& m);
void BindCase(py::module_& m);
// run(case, analyses, progress) and the RunHandle's summaries and results.json.
void BindRun(py::module_& m);
// roadmap(case, jobs, progress): the torque-and-drag roadmap (roadmap.cpp).
void BindRoadmap(py::module_& m);
// calibrate(case, readings, fit, model, jobs): friction factors fitted to the rig's readings (calibrate.cpp).
void BindCalibrate(py::module_& m);
// The RunHandle's typed results, one function per analysis (result_*.cpp).
void BindStaticResult(py::class_<RunHandle>& run);
void BindModesResult(py::class_<RunHandle>& run);
void BindVibrationResult(py::class_<RunHandle>& run);
void BindBucklingResult(py::class_<RunHandle>& run);
void BindTendencyResult(py::class_<RunHandle>& run);
void BindTransientResult(py::class_<RunHandle>& run);

}  // namespace drillflex::python
