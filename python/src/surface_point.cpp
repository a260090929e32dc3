#include "surface_point.hpp"

#include "arrays.hpp"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cstdint>
#include <string>

namespace gsp::python {

namespace py = pybind11;

void bind_surface_point(py::module_& m) {
  py::class_<SurfacePoint>(m, "SurfacePoint",
                           "A point inside a face: the face index and the barycentric weights of its corners "
                           "0, 1, 2 (>= 0, summing to 1).")
      .def(py::init([](std::int64_t face, py::object bary) {
             if (face < 0) throw py::value_error("SurfacePoint: face must be >= 0");
             return SurfacePoint::in_face(Index(face), barycentric_from(bary, "SurfacePoint barycentric"));
           }),
           py::arg("face"), py::arg("barycentric"))
      .def_property_readonly("face", [](const SurfacePoint& p) { return p.element; })
      .def_property_readonly("barycentric", [](const SurfacePoint& p) { return py::make_tuple(p.barycentric[0], p.barycentric[1], p.barycentric[2]); })
      .def("__repr__", [](const SurfacePoint& p) {
        return "SurfacePoint(" + std::to_string(p.element) + ", (" + std::string(py::str(py::float_(p.barycentric[0]))) +
               ", " + std::string(py::str(py::float_(p.barycentric[1]))) + ", " +
               std::string(py::str(py::float_(p.barycentric[2]))) + "))";
      })
      .def("__eq__", [](const SurfacePoint& a, const SurfacePoint& b) {
        return a.kind == b.kind && a.element == b.element && a.barycentric == b.barycentric;
      });
}

bool is_index(const py::handle& h) {
  // numpy arrays have __index__ too (for size 1); they are lists here, not one index.
  return PyIndex_Check(h.ptr()) && !PyBool_Check(h.ptr()) && !py::isinstance<py::array>(h);
}

Source source_from(const py::handle& h, const TriangleMesh& mesh, const char* what) {
  if (py::isinstance<SurfacePoint>(h)) {
    const auto& p = h.cast<const SurfacePoint&>();
    if (!p.exists_in(mesh))
      throw py::value_error(std::string(what) + ": face " + std::to_string(p.element) + " does not exist (the mesh has " +
                            std::to_string(mesh.num_faces()) + " faces)");
    return Source::at(p);
  }
  if (!is_index(h))
    throw py::value_error(std::string(what) + ": expected a vertex index (int) or a gsp.SurfacePoint, got " +
                          std::string(py::str(py::type::handle_of(h).attr("__name__"))));
  const std::int64_t v = h.cast<std::int64_t>();
  if (v < 0 || std::uint64_t(v) >= mesh.num_vertices())
    throw py::value_error(std::string(what) + ": vertex " + std::to_string(v) + " does not exist (the mesh has " +
                          std::to_string(mesh.num_vertices()) + " vertices)");
  return Source::at_vertex(Index(v));
}

std::vector<Source> sources_from(const py::handle& h, const TriangleMesh& mesh, const char* what) {
  if (h.is_none()) throw py::value_error(std::string(what) + " is None");
  if (py::isinstance<SurfacePoint>(h) || is_index(h)) return {source_from(h, mesh, what)};
  if (py::isinstance<py::array>(h)) {   // an index array: no per-element Python objects
    const std::vector<Index> v = indices_from(h, mesh.num_vertices(), what);
    std::vector<Source> out;
    for (Index i : v) out.push_back(Source::at_vertex(i));
    if (out.empty()) throw py::value_error(std::string(what) + " is empty");
    return out;
  }
  if (!py::isinstance<py::sequence>(h) || py::isinstance<py::str>(h))
    throw py::value_error(std::string(what) + ": expected a vertex index, a gsp.SurfacePoint or a list of them");
  std::vector<Source> out;
  for (py::handle item : py::reinterpret_borrow<py::sequence>(h)) out.push_back(source_from(item, mesh, what));
  if (out.empty()) throw py::value_error(std::string(what) + " is empty");
  return out;
}

}  // namespace gsp::python
