#include "errors.hpp"

#include <gsp/errors.hpp>
#include <gsp/pathfinding/path.hpp>

namespace gsp::python {

namespace py = pybind11;

namespace {
// Kept alive by the module (py::exception stores the type in the module's namespace).
PyObject* no_path_type = nullptr;
PyObject* remesh_warning_type = nullptr;
}  // namespace

void register_errors(py::module_& m) {
  static py::exception<gsp::Error> error(m, "Error", PyExc_RuntimeError);
  static py::exception<pathfinding::NoPath> no_path(m, "NoPathError", error.ptr());
  no_path_type = no_path.ptr();
  remesh_warning_type = PyErr_NewExceptionWithDoc(
      "gsp.RemeshWarning",
      "gsp.remesh kept some components as they were (non-manifold, too small, or their remesh lost the "
      "topology); the message names each with its reason.",
      PyExc_UserWarning, nullptr);
  if (!remesh_warning_type) throw py::error_already_set();
  m.attr("RemeshWarning") = py::handle(remesh_warning_type);
  error.doc() = "Base of the errors gsp raises itself (besides ValueError and OSError).";
  no_path.doc() = "The end point is not reached from the source: another component, or beyond max_distance.";
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const pathfinding::NoPath& e) {
      PyErr_SetString(no_path_type, e.what());
    } catch (const InvalidInput& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const TopologyError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const IoError& e) {
      PyErr_SetString(PyExc_OSError, e.what());
    } catch (const gsp::Error& e) {
      PyErr_SetString(error.ptr(), e.what());
    }
  });
}

void warn_remesh(const std::string& message) {
  if (PyErr_WarnEx(remesh_warning_type, message.c_str(), 1) < 0) throw py::error_already_set();
}

void raise_no_path(const std::string& message) { throw pathfinding::NoPath(message); }

}  // namespace gsp::python
