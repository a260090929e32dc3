// gsp.PointCloudSolver: geodesics on point clouds (k-nearest-neighbour graph, local triangles).
#include "arrays.hpp"
#include "bindings.hpp"

#include <gsp/pointcloud/point_cloud_geodesics.hpp>

#include <limits>
#include <memory>

namespace gsp::python {

namespace {

using pointcloud::PointCloudGeodesics;

pointcloud::PointMethod method_from(std::string name) {
  std::replace(name.begin(), name.end(), '-', '_');
  if (name == "gsp") return pointcloud::PointMethod::gsp;
  if (name == "graph_gsp") return pointcloud::PointMethod::graph_gsp;
  if (name == "dijkstra") return pointcloud::PointMethod::dijkstra;
  throw py::value_error("method must be 'gsp', 'graph_gsp' or 'dijkstra' (got '" + name + "')");
}

py::object distance(const PointCloudGeodesics& s, const py::handle& sources, const py::handle& positions,
                    const std::string& method, double max_distance, bool labels) {
  std::vector<pointcloud::PointSource> src;
  if (!sources.is_none())
    for (Index i : indices_from(sources, s.num_points(), "sources")) src.push_back(pointcloud::PointSource::at_point(i));
  if (!positions.is_none()) {
    auto a = py::module_::import("numpy").attr("asarray")(positions, "float64");
    const std::vector<Vec3> p = points_from_array(py::array(a).ndim() == 1 ? a.attr("reshape")(1, -1) : a, "positions");
    for (const Vec3& q : p) src.push_back(pointcloud::PointSource::at_position(q));
  }
  if (src.empty()) throw py::value_error("give sources= (point indices) and/or positions= (k, 3)");
  if (std::isnan(max_distance) || max_distance < 0) throw py::value_error("max_distance must be >= 0");
  pointcloud::PointGeodesicOptions o;
  o.method = method_from(method);
  o.max_distance = max_distance;
  pointcloud::PointCloudResult r;
  {
    py::gil_scoped_release nogil;
    r = s.compute(src, o);
  }
  auto d = to_array(std::move(r.distance));
  if (!labels) return std::move(d);
  return py::make_tuple(std::move(d), labels_to_array(r.source));
}

// Row i: the field from points[i] at the targets (the same points by default), the GIL released.
py::array_t<double> distance_matrix(const PointCloudGeodesics& s, const py::handle& points, const py::handle& targets,
                                    const std::string& method, unsigned threads) {
  const std::vector<Index> rows = indices_from(points, s.num_points(), "points");
  const std::vector<Index> cols = targets.is_none() ? rows : indices_from(targets, s.num_points(), "targets");
  if (rows.empty()) throw py::value_error("points is empty");
  pointcloud::PointGeodesicOptions o;
  o.method = method_from(method);
  std::vector<double> matrix;
  {
    py::gil_scoped_release nogil;
    matrix = pointcloud::distance_matrix(s, rows, cols, o, threads);
  }
  return to_array(std::move(matrix)).reshape({py::ssize_t(rows.size()), py::ssize_t(cols.size())});
}

}  // namespace

void bind_pointcloud(py::module_& m) {
  py::class_<PointCloudGeodesics>(m, "PointCloudSolver", R"(A point cloud prepared once for geodesic queries.

PointCloudSolver(P, *, k=10, normals=None): P (n, 3); k nearest neighbours per point; normals
(n, 3) or None (estimated by local PCA). Duplicated points are merged. Queries release the GIL.)")
      .def(py::init([](const py::handle& P, unsigned k, const py::handle& normals) {
             std::vector<Vec3> points = points_from_array(P, "P");
             std::vector<Vec3> n;
             if (!normals.is_none()) n = points_from_array(normals, "normals");
             if (k < 1) throw py::value_error("k must be >= 1");
             pointcloud::PointCloudOptions o;
             o.neighbours.k = k;
             py::gil_scoped_release nogil;
             return std::make_unique<PointCloudGeodesics>(points, n, o);
           }),
           py::arg("P"), py::kw_only(), py::arg("k") = 10u, py::arg("normals") = py::none())
      .def_property_readonly("num_points", &PointCloudGeodesics::num_points)
      .def_property_readonly("components", [](const PointCloudGeodesics& s) { return s.stats().components; },
                             "connected components of the neighbour graph")
      .def_property_readonly("normals", [](const PointCloudGeodesics& s) { return to_array(s.normals()); },
                             "(n, 3) unit normals as used (unoriented where estimated)")
      .def("distance", &distance, py::arg("sources") = py::none(), py::kw_only(), py::arg("positions") = py::none(),
           py::arg("method") = "gsp", py::arg("max_distance") = std::numeric_limits<double>::infinity(),
           py::arg("labels") = false,
           R"(Geodesic distance to every point: an (n,) float64 array (+inf on other components).

sources: point indices; positions: (k, 3) points in space (their nearest points are seeded at
their straight distance). method: 'gsp' (default), 'graph_gsp' or 'dijkstra' (along the
graph's links). labels=True returns (distance, label) with the nearest source's index.)")
      .def("distance_matrix", &distance_matrix, py::arg("points"), py::kw_only(), py::arg("targets") = py::none(),
           py::arg("method") = "gsp", py::arg("threads") = 0u,
           R"(Distances between points of the cloud: a (k, t) float64 array, row i the field from points[i].

points: point indices; targets: None (the same points: k x k) or other point indices. Rows run
in parallel on `threads` (0: all cores), the GIL released. Not exactly symmetric (each row is
its own propagation); (D + D.T) / 2 is.)");
}

}  // namespace gsp::python
