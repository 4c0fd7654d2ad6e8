// drillflex._core's unit functions: the C++ unit layer (units/units.hpp) for drillflex.units.
#include <utility>

#include "bindings.hpp"
#include "units/units.hpp"

namespace drillflex::python {

void BindUnits(py::module_& m) {
  m.def("convert", [](double value, const std::string& from, const std::string& to) { return units::Convert(value, from, to); },
        py::arg("value"), py::arg("from_unit"), py::arg("to_unit"), "`value` in `from_unit` converted to `to_unit`.");
  // units::Convert multiplies by the first and divides by the second: drillflex.units.convert does the
  // same to an array, so an array's elements convert as the numbers alone would.
  m.def(
      "unit_scales",
      [](const std::string& from, const std::string& to) {
        units::Convert(1.0, from, to);  // throws UnitError when the dimensions differ
        return std::pair(units::ParseUnit(from).to_si, units::ParseUnit(to).to_si);
      },
      py::arg("from_unit"), py::arg("to_unit"), "(SI per `from_unit`, SI per `to_unit`); UnitError when they differ in kind.");
}

}  // namespace drillflex::python
