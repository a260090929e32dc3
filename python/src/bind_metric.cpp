// gsp.metric: the Metric type, its constructors from tensors, a direction field, principal
// curvature or a file, and the edge lengths a metric gives.
#include "arrays.hpp"
#include "bindings.hpp"
#include "metric.hpp"

#include <gsp/anisotropic/metric_sources.hpp>

#include <algorithm>
#include <cmath>

namespace gsp::python {

namespace {

using anisotropic::MetricField;
using anisotropic::MetricLocation;
using anisotropic::SymmetricTensor;

// The library's name with Python's spelling ("per_face").
std::string python_location_name(MetricLocation l) {
  std::string name = anisotropic::location_name(l);
  std::replace(name.begin(), name.end(), '-', '_');
  return name;
}

MetricLocation location_from(const std::string& name) {
  if (name == "constant") return MetricLocation::constant;
  if (name == "per_face" || name == "face") return MetricLocation::per_face;
  if (name == "per_vertex" || name == "vertex") return MetricLocation::per_vertex;
  throw py::value_error("location must be 'constant', 'per_face' or 'per_vertex' (got '" + name + "')");
}

// (3,3), (k,3,3) or (k,6) "xx xy xz yy yz zz"; a 3x3 must be symmetric.
std::vector<SymmetricTensor> tensors_from(const py::handle& h) {
  auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(
      py::module_::import("numpy").attr("asarray")(h, "float64"));
  if (!a) throw py::value_error("tensors must be numbers");
  std::vector<SymmetricTensor> out;
  const double* p = a.data();
  if ((a.ndim() == 2 && a.shape(0) == 3 && a.shape(1) == 3) || (a.ndim() == 3 && a.shape(1) == 3 && a.shape(2) == 3)) {
    const std::size_t k = a.ndim() == 2 ? 1 : std::size_t(a.shape(0));
    for (std::size_t i = 0; i < k; ++i) {
      const double* t = p + 9 * i;
      const double scale = std::abs(t[0]) + std::abs(t[4]) + std::abs(t[8]);
      if (std::abs(t[1] - t[3]) > 1e-9 * scale || std::abs(t[2] - t[6]) > 1e-9 * scale ||
          std::abs(t[5] - t[7]) > 1e-9 * scale)
        throw py::value_error("tensor " + std::to_string(i) + " is not symmetric");
      out.push_back({t[0], t[1], t[2], t[4], t[5], t[8]});
    }
  } else if (a.ndim() == 2 && a.shape(1) == 6) {
    for (py::ssize_t i = 0; i < a.shape(0); ++i) {
      const double* t = p + 6 * i;
      out.push_back({t[0], t[1], t[2], t[3], t[4], t[5]});
    }
  } else {
    throw py::value_error("tensors must have shape (3, 3), (k, 3, 3) or (k, 6)");
  }
  return out;
}

py::array_t<double> tensors_to_array(const std::vector<SymmetricTensor>& tensors) {
  py::array_t<double> out({py::ssize_t(tensors.size()), py::ssize_t(3), py::ssize_t(3)});
  double* p = out.mutable_data();
  for (const SymmetricTensor& t : tensors) {
    const double m[9] = {t.xx, t.xy, t.xz, t.xy, t.yy, t.yz, t.xz, t.yz, t.zz};
    std::copy(m, m + 9, p);
    p += 9;
  }
  return out;
}

MetricField field_from(const py::handle& tensors, const std::string& location) {
  MetricField f;
  f.tensors = tensors_from(tensors);
  f.location = location_from(location);
  if (f.location == MetricLocation::constant && f.tensors.size() != 1)
    throw py::value_error("a constant metric has one tensor, got " + std::to_string(f.tensors.size()));
  for (std::size_t i = 0; i < f.tensors.size(); ++i)
    if (!f.tensors[i].is_positive_definite())
      throw py::value_error("tensor " + std::to_string(i) + " is not finite and positive definite");
  return f;
}

// A tensor array without a location: the count decides.
MetricField field_for(const TriangleMesh& mesh, const py::handle& h) {
  if (py::isinstance<MetricField>(h)) return h.cast<MetricField>();
  const std::vector<SymmetricTensor> t = tensors_from(h);
  const bool faces = t.size() == mesh.num_faces(), vertices = t.size() == mesh.num_vertices();
  if (t.size() == 1 && !(faces || vertices)) return field_from(h, "constant");
  if (faces && vertices)
    throw py::value_error("metric: as many tensors as faces and vertices; pass gsp.metric.Metric(T, 'per_face') or 'per_vertex'");
  if (faces) return field_from(h, "per_face");
  if (vertices) return field_from(h, "per_vertex");
  throw py::value_error("metric: " + std::to_string(t.size()) + " tensors, but the mesh has " +
                        std::to_string(mesh.num_faces()) + " faces and " + std::to_string(mesh.num_vertices()) + " vertices");
}

}  // namespace

SolverOptions metric_solver_options(const TriangleMesh& mesh, const py::handle& metric) {
  if (metric.is_none()) return {};
  const MetricField field = field_for(mesh, metric);
  py::gil_scoped_release nogil;
  return anisotropic::with_metric(mesh, field);
}

void bind_metric(py::module_& top) {
  py::module_ m = top.def_submodule("metric", "Riemannian metrics: lengths measured by a tensor per mesh, face or vertex.");
  py::class_<MetricField>(m, "Metric", R"(A metric: one tensor for the mesh, one per face or one per vertex.

Metric(tensors, location='constant'|'per_face'|'per_vertex'); tensors (3,3), (k,3,3) or (k,6)
as xx xy xz yy yz zz, symmetric positive definite. A step e costs sqrt(e^T M e).)")
      .def(py::init(&field_from), py::arg("tensors"), py::arg("location") = "constant")
      .def_property_readonly("location", [](const MetricField& f) { return python_location_name(f.location); })
      .def_property_readonly("tensors", [](const MetricField& f) { return tensors_to_array(f.tensors); },
                             "(k, 3, 3) float64")
      .def("__repr__", [](const MetricField& f) {
        return "Metric(" + python_location_name(f.location) + ", " + std::to_string(f.tensors.size()) + " tensors)";
      });
  m.def("constant", [](const py::handle& t) { return field_from(t, "constant"); }, py::arg("tensor"),
        "One (3,3) tensor for the whole mesh.");
  m.def("per_face", [](const py::handle& t) { return field_from(t, "per_face"); }, py::arg("tensors"),
        "One tensor per face: (m,3,3) or (m,6).");
  m.def("per_vertex", [](const py::handle& t) { return field_from(t, "per_vertex"); }, py::arg("tensors"),
        "One tensor per vertex: (n,3,3) or (n,6) (a face uses the mean of its corners').");
  m.def(
      "direction",
      [](const py::handle& V, const py::handle& F, const py::handle& direction, double ratio) {
        const TriangleMesh mesh = mesh_from_arrays(V, F);
        const std::vector<double> d = values_from(direction, 3, "direction");
        py::gil_scoped_release nogil;
        return anisotropic::direction_metric(mesh, {d[0], d[1], d[2]}, ratio);
      },
      py::arg("V"), py::arg("F"), py::arg("direction"), py::arg("ratio"),
      R"(Per face: a unit step along `direction` (projected into the face) costs `ratio`, across it 1.)");
  m.def(
      "curvature",
      [](const py::handle& V, const py::handle& F, double ratio, int smoothing_rounds) {
        const TriangleMesh mesh = mesh_from_arrays(V, F);
        py::gil_scoped_release nogil;
        return anisotropic::curvature_metric(mesh, ratio, smoothing_rounds);
      },
      py::arg("V"), py::arg("F"), py::arg("ratio"), py::kw_only(), py::arg("smoothing_rounds") = 3,
      R"(Per vertex: a step along the direction of largest principal curvature costs `ratio`
(directions smoothed over `smoothing_rounds` one-ring averages).)");
  m.def(
      "read",
      [](const py::object& path, std::size_t num_vertices, std::size_t num_faces) {
        return anisotropic::read_metric_file(path_string(path), num_vertices, num_faces);
      },
      py::arg("path"), py::arg("num_vertices"), py::arg("num_faces"),
      "A metric from the text format of docs/anisotropic.md (raises OSError).");
  m.def(
      "edge_lengths",
      [](const py::handle& V, const py::handle& F, const py::handle& metric) {
        const TriangleMesh mesh = mesh_from_arrays(V, F);
        const MetricField field = field_for(mesh, metric);
        std::vector<double> lengths;
        {
          py::gil_scoped_release nogil;
          lengths = anisotropic::metric_edge_lengths(mesh, field);
        }
        return to_array(std::move(lengths)).reshape({py::ssize_t(mesh.num_faces()), py::ssize_t(3)});
      },
      py::arg("V"), py::arg("F"), py::arg("metric"),
      "(m, 3) float64: per face, the metric length of the edge from corner i to corner i+1.");
}

}  // namespace gsp::python
