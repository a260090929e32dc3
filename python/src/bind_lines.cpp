// gsp.line_distance: distances from polylines, mesh edges or the boundary.
#include "arrays.hpp"
#include "bindings.hpp"

#include <gsp/lines/line_distances.hpp>

#include <limits>

namespace gsp::python {

namespace {

py::object line_distance(const py::handle& V, const py::handle& F, const py::handle& polylines, const py::handle& edges,
                         bool boundary, double max_distance, bool labels) {
  const TriangleMesh mesh = mesh_from_arrays(V, F);
  if (std::isnan(max_distance) || max_distance < 0) throw py::value_error("max_distance must be >= 0");
  std::vector<lines::Polyline> lines_in;
  if (!polylines.is_none()) {
    if (py::isinstance<py::array>(polylines) && py::array(py::reinterpret_borrow<py::array>(polylines)).ndim() == 2)
      lines_in.push_back(points_from_array(polylines, "polylines"));   // one polyline as an (k,3) array
    else
      for (py::handle p : py::reinterpret_borrow<py::sequence>(polylines)) lines_in.push_back(points_from_array(p, "polylines[i]"));
  }
  std::vector<std::array<Index, 2>> pairs;
  if (!edges.is_none()) {
    const std::vector<Index> flat = indices_from(
        py::module_::import("numpy").attr("asarray")(edges).attr("reshape")(-1), mesh.num_vertices(), "edges");
    if (flat.size() % 2) throw py::value_error("edges must have shape (e, 2)");
    for (std::size_t i = 0; i < flat.size(); i += 2) pairs.push_back({flat[i], flat[i + 1]});
  }
  if (lines_in.empty() && pairs.empty() && !boundary)
    throw py::value_error("line_distance needs polylines=, edges= or boundary=True");
  lines::LineOptions options;
  options.max_distance = max_distance;
  lines::LineResult r;
  {
    py::gil_scoped_release nogil;
    lines::LineSource source;
    if (!lines_in.empty()) lines::append(source, lines::polyline_source(mesh, lines_in));
    if (!pairs.empty()) lines::append(source, lines::edge_source(mesh, pairs));
    if (boundary) lines::append(source, lines::boundary_source(mesh));
    r = lines::line_distances(mesh, source, options);
  }
  auto d = to_array(std::move(r.vertex_distance));
  if (!labels) return std::move(d);
  return py::make_tuple(std::move(d), labels_to_array(r.vertex_segment));
}

}  // namespace

void bind_lines(py::module_& m) {
  m.def("line_distance", &line_distance, py::arg("V"), py::arg("F"), py::kw_only(), py::arg("polylines") = py::none(),
        py::arg("edges") = py::none(), py::arg("boundary") = false,
        py::arg("max_distance") = std::numeric_limits<double>::infinity(), py::arg("labels") = false,
        R"(Geodesic distance from curves on the surface: an (n,) float64 array (+inf where unreachable).

polylines: a list of (k, 3) point arrays (snapped onto the surface; closed when the last point
equals the first). edges: (e, 2) vertex pairs that are mesh edges. boundary=True: every
boundary edge. Any combination; the distance is to the nearest segment (exact on planes).
labels=True returns (distance, segment) with the nearest segment's index (polylines' segments
first, then edges, then boundary edges; -1 where unreached).)");
}

}  // namespace gsp::python
