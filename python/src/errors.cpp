// drillflex's errors raised as the Python package's own (python/drillflex/errors.py): an InputError
// keeps the command line's message and its file, line, column and key; a SolverError is a
// ConvergenceError; a UnitError (units.convert) a UnitError.
#include "bindings.hpp"
#include "core/error.hpp"

namespace drillflex::python {
namespace {

// Raises drillflex.errors.<name>(*arguments) as the current Python error.
template <class... Arguments>
void Raise(const char* name, Arguments&&... arguments) {
  const py::object type = py::module_::import("drillflex.errors").attr(name);
  const py::object error = type(std::forward<Arguments>(arguments)...);
  PyErr_SetObject(type.ptr(), error.ptr());
}

}  // namespace

void BindErrors(py::module_&) {
  py::register_exception_translator([](std::exception_ptr thrown) {
    try {
      if (thrown) std::rethrow_exception(thrown);
    } catch (const InputError& error) {
      const SourceLocation& at = error.location();
      Raise("InputError", std::string(error.what()), at.file, at.line, at.column, error.key_path(), error.message());
    } catch (const UnitError& error) {
      Raise("UnitError", std::string(error.what()));
    } catch (const SolverError& error) {
      Raise("ConvergenceError", std::string(error.what()));
    }
  });
}

}  // namespace drillflex::python
