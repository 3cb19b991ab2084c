// The library's typed exceptions as the Python classes of subdiv._errors
// (which add the standard bases: ValueError, OSError), with the same
// one-line messages.

#include <exception>

#include "bindings.h"
#include "subdiv/core/error.h"
#include "subdiv/mesh/validation.h"

namespace subdiv::python {

namespace {

py::object error_class(const char* name) { return py::module_::import("subdiv._errors").attr(name); }

void raise(const char* name, const std::exception& e) {
  PyErr_SetObject(error_class(name).ptr(), py::str(e.what()).ptr());
}

}  // namespace

void bind_errors(py::module_& m) {
  static_cast<void>(m);
  // Most derived first: the first matching handler wins.
  py::register_exception_translator([](std::exception_ptr thrown) {
    try {
      if (thrown) std::rethrow_exception(thrown);
    } catch (const ParseError& e) {
      const py::object error = error_class("ParseError")(e.what(), e.path(), e.line());
      PyErr_SetObject(error.get_type().ptr(), error.ptr());
    } catch (const ValidationError& e) {
      py::list issues;
      for (const ValidationIssue& issue : e.report().issues) issues.append(format_issue(issue, {}));
      const py::object error = error_class("ValidationError")(e.what(), issues);
      PyErr_SetObject(error.get_type().ptr(), error.ptr());
    } catch (const IoError& e) {
      raise("IoError", e);
    } catch (const ParameterError& e) {
      raise("ParameterError", e);
    } catch (const TopologyError& e) {
      raise("TopologyError", e);
    } catch (const InvalidInputError& e) {
      raise("InvalidInputError", e);
    } catch (const Error& e) {
      raise("Error", e);
    }
  });
}

}  // namespace subdiv::python
