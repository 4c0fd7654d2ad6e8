// drillflex.Case: a case read from a file or text (io::ReadCase, io::ParseCase) and changed copies of
// it (io::WithValues). drillflex/case.py adds from_dict.
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "units/units.hpp"

namespace drillflex::python {
namespace {

CaseHandle Hold(io::Case c) { return {std::make_shared<const io::Case>(std::move(c))}; }

// A value for a key path as YAML text: a str as given, True/False as true/false, a number as Python
// writes it (repr: every digit kept).
std::string ValueText(const py::handle& value) {
  if (py::isinstance<py::str>(value)) return value.cast<std::string>();
  if (py::isinstance<py::bool_>(value)) return value.cast<bool>() ? "true" : "false";
  return py::repr(value).cast<std::string>();
}

}  // namespace

void BindCase(py::module_& m) {
  py::class_<CaseHandle>(m, "Case", "A drillflex case (docs/case-format.md), read and checked; immutable.")
      .def_static("from_file", [](const std::string& path) { return Hold(io::ReadCase(path)); }, py::arg("path"),
                  "Reads a case file (InputError with its file, line and key when it is not a valid case).")
      .def_static(
          "from_yaml",
          [](const std::string& text, const std::string& file, const std::string& directory) {
            return Hold(io::ParseCase(text, file, directory));
          },
          py::arg("text"), py::arg("file") = "<yaml>", py::arg("directory") = ".",
          "Reads a case from YAML text; `file` names it in errors, `directory` resolves survey_file.")
      .def(
          "with_values",
          [](const CaseHandle& self, const py::dict& values) {
            std::vector<io::CaseValue> changes;
            for (const auto& [key, value] : values) changes.push_back({key.cast<std::string>(), ValueText(value)});
            return Hold(io::WithValues(*self.c, changes));
          },
          py::arg("values"),
          "A copy with values set by key path ({'operation.wob': '30 klbf', 'string[4].length': '40 ft'}), in "
          "order; values are YAML in the case's syntax (a bare number in the case's units).")
      .def_property_readonly("name", [](const CaseHandle& self) { return self.c->name; })
      .def_property_readonly("file", [](const CaseHandle& self) { return self.c->file; })
      .def_property_readonly("directory", [](const CaseHandle& self) { return self.c->directory; })
      .def_property_readonly("text", [](const CaseHandle& self) { return self.c->text; },
                             "The YAML text the case was read from (without with_values' values).")
      .def_property_readonly("units", [](const CaseHandle& self) { return std::string(units::SystemName(self.c->units)); })
      .def_property_readonly("output_units",
                             [](const CaseHandle& self) { return std::string(units::SystemName(self.c->output_units)); })
      .def_property_readonly(
          "analyses",
          [](const CaseHandle& self) {
            std::vector<std::string> names;
            // None listed: [] here, where CaseAnalyses would throw.
            if (!self.c->analyses.static_analysis && !self.c->analyses.modes && !self.c->analyses.vibration &&
                !self.c->analyses.buckling && !self.c->analyses.transient) {
              return names;
            }
            const pipeline::AnalysisRequest listed = pipeline::CaseAnalyses(*self.c);
            for (const auto analysis : kAnalyses) {
              if (listed.Has(analysis)) names.emplace_back(pipeline::AnalysisName(analysis));
            }
            return names;
          },
          "The analyses the case lists (what drillflex.run('run', case) runs).")
      .def("__repr__", [](const CaseHandle& self) { return "<drillflex.Case '" + self.c->name + "' from " + self.c->file + ">"; });
}

}  // namespace drillflex::python
