#include "progress.hpp"

namespace gsp::python {

namespace py = pybind11;

std::function<void(double)> interruptible(py::object progress) {
  if (!progress.is_none() && !PyCallable_Check(progress.ptr()))
    throw py::type_error("progress must be a callable taking the fraction done (0..1), or None");
  // Shared so the std::function stays copyable; released with the GIL held.
  auto callback = std::shared_ptr<py::object>(new py::object(std::move(progress)), [](py::object* o) {
    py::gil_scoped_acquire gil;
    delete o;
  });
  return [callback](double fraction) {
    py::gil_scoped_acquire gil;
    if (PyErr_CheckSignals() != 0) throw py::error_already_set();
    if (!callback->is_none()) (*callback)(fraction);
  };
}

}  // namespace gsp::python
