#pragma once
// The module's parts, one bind_* per file; module.cpp calls them in order.
#include <pybind11/pybind11.h>

#include <string>

namespace gsp::python {

namespace py = pybind11;

void bind_io(py::module_& m);
void bind_solver(py::module_& m);
void bind_paths(py::module_& m);
void bind_lines(py::module_& m);
void bind_metric(py::module_& m);
void bind_pointcloud(py::module_& m);
void bind_sampling(py::module_& m);
void bind_cvt(py::module_& m);
void bind_windows(py::module_& m);

// A str or os.PathLike as a file name.
std::string path_string(const py::object& path);

}  // namespace gsp::python
