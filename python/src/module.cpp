// The Python extension drillflex._core (docs/python.md): cases, runs through the pipeline, typed
// results over the run's own storage, units and errors. The package drillflex (python/drillflex) is
// its public face.
#include "bindings.hpp"

PYBIND11_MODULE(_core, m) {
  m.doc() = "drillflex's C++ engine: cases, runs through pipeline::RunCase, typed results, units.";
  drillflex::python::BindErrors(m);
  drillflex::python::BindUnits(m);
  drillflex::python::BindCase(m);
  drillflex::python::BindRun(m);
  drillflex::python::BindRoadmap(m);
  drillflex::python::BindCalibrate(m);
}
