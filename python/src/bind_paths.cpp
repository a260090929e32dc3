// Geodesic paths: GeodesicSolver.path / .paths and the gsp.Path result.
#include "arrays.hpp"
#include "bindings.hpp"
#include "errors.hpp"
#include "solver.hpp"
#include "surface_point.hpp"

#include <gsp/pathfinding/shortest_path.hpp>

#include <pybind11/stl.h>

namespace gsp::python {

namespace {

struct Path {
  py::array_t<double> points, barycentric;
  py::array_t<std::int64_t> faces;
  double length = 0;
};

Path to_path(const pathfinding::GeodesicPath& p) {
  std::vector<Vec3> points;
  std::vector<std::array<double, 3>> bary;
  std::vector<Index> faces;
  for (const pathfinding::PathPoint& q : p.points) {
    points.push_back(q.position);
    bary.push_back(q.point.barycentric);
    faces.push_back(q.point.element);
  }
  return {to_array(std::move(points)), to_array(std::move(bary)), labels_to_array(faces), p.length};
}

pathfinding::PathMethod method_from(std::string name) {
  std::replace(name.begin(), name.end(), '-', '_');
  if (name == "astar") return pathfinding::PathMethod::astar;
  if (name == "settle") return pathfinding::PathMethod::settle;
  if (name == "full") return pathfinding::PathMethod::full;
  if (name == "dijkstra_edges") return pathfinding::PathMethod::dijkstra_edges;
  if (name == "windows") return pathfinding::PathMethod::windows;
  throw py::value_error("method must be 'astar', 'settle', 'full', 'windows' or 'dijkstra_edges' (got '" + name + "')");
}

std::string describe(const Source& s) {
  return s.kind == Source::Kind::vertex ? "vertex " + std::to_string(s.element)
                                        : "the point in face " + std::to_string(s.element);
}

std::vector<Path> trace(Solver& s, const py::handle& a, const py::handle& ends, const std::string& method,
                        bool both_ends, const std::string& precision) {
  s.require_3d("paths");
  const Source from = source_from(a, s.mesh(), "a");
  const std::vector<Source> to = sources_from(ends, s.mesh(), "b");
  pathfinding::PathQueryOptions o;
  o.method = method_from(method);
  o.both_ends = both_ends;
  o.precision = precision_from(precision);
  const std::vector<pathfinding::Endpoint> targets(to.begin(), to.end());   // the sources' points
  pathfinding::PathQueryResult r;
  {
    py::gil_scoped_release nogil;
    const pathfinding::PathTracer& tracer = s.tracer();
    r = o.method == pathfinding::PathMethod::dijkstra_edges
            ? pathfinding::edge_paths(s.mesh(), tracer, from, targets)
            : pathfinding::shortest_paths(s.solver(), tracer, from, targets, o);
  }
  std::vector<Path> out;
  for (std::size_t i = 0; i < r.paths.size(); ++i) {
    if (!r.paths[i].found()) raise_no_path(describe(to[i]) + " is not reached from " + describe(from) + " (another component)");
    out.push_back(to_path(r.paths[i]));
  }
  return out;
}

}  // namespace

void bind_paths(py::module_& m) {
  py::class_<Path>(m, "Path", "A geodesic path: a polyline on the surface from the start to the end point.")
      .def_readonly("points", &Path::points, "(k, 3) float64 positions, from the start to the end")
      .def_readonly("faces", &Path::faces, "(k,) int64: the face each point is given in")
      .def_readonly("barycentric", &Path::barycentric, "(k, 3) float64: each point in its face")
      .def_readonly("length", &Path::length, "the polyline's 3D length")
      .def("__len__", [](const Path& p) { return p.faces.size(); })
      .def("__repr__", [](const Path& p) {
        return "Path(" + std::to_string(p.faces.size()) + " points, length " + std::string(py::str(py::float_(p.length))) + ")";
      });
}

void add_path_methods(py::class_<Solver>& cls) {
  cls.def(
      "path",
      [](Solver& s, const py::handle& a, const py::handle& b, const std::string& method, bool both_ends,
         const std::string& precision) {
        if (!(py::isinstance<SurfacePoint>(b) || is_index(b)))
          throw py::value_error("b: expected a vertex index or a gsp.SurfacePoint (use paths() for several)");
        return trace(s, a, b, method, both_ends, precision).front();
      },
      py::arg("a"), py::arg("b"), py::kw_only(), py::arg("method") = "windows", py::arg("both_ends") = true,
      py::arg("precision") = "auto",
      R"(The geodesic path from a to b (vertex indices or gsp.SurfacePoint values): a gsp.Path.

method: 'windows' (default: a few windows per face, goal-directed; within 0.01% of exact on the
corpus), 'astar' (GSP, goal-directed: about 7x faster, on meshes with many nearly equal
corridors up to a few % long), 'settle', 'full' or 'dijkstra_edges' (along edges).
both_ends also propagates from b and keeps the shorter taut path. Raises gsp.NoPathError when b
is not reached from a.)");
  cls.def("paths", &trace, py::arg("a"), py::arg("b"), py::kw_only(), py::arg("method") = "windows",
          py::arg("both_ends") = true, py::arg("precision") = "auto",
          R"(Geodesic paths from a to each of the end points b (a list): a list of gsp.Path, one field for all.

Raises gsp.NoPathError naming the first end point not reached.)");
}

}  // namespace gsp::python
