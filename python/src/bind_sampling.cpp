// gsp.sample: geodesic Poisson-disk and farthest-point sampling.
#include "arrays.hpp"
#include "bindings.hpp"
#include "progress.hpp"

#include <gsp/sampling/sampler.hpp>

namespace gsp::python {

namespace {

struct Samples {
  py::array_t<double> points, barycentric, normals, coverage;
  py::array_t<std::int64_t> faces;
  double radius = 0;
  bool count_met = true;
};

Samples sample(const py::handle& V, const py::handle& F, const py::object& count, const py::object& radius,
               const std::string& mode, std::uint64_t seed, bool exact, bool fill, const py::object& progress) {
  const TriangleMesh mesh = mesh_from_arrays(V, F);
  if (mesh.num_faces() == 0) throw py::value_error("F is empty: sampling needs faces");
  sampling::SamplingOptions o;
  if (count.is_none() == radius.is_none()) throw py::value_error("give exactly one of count= and radius=");
  if (!count.is_none()) {
    const long long c = count.cast<long long>();
    if (c <= 0) throw py::value_error("count must be > 0");
    o.count = std::size_t(c);
  } else {
    o.radius = radius.cast<double>();
    if (!(o.radius > 0) || !std::isfinite(o.radius)) throw py::value_error("radius must be a finite number > 0");
  }
  if (mode != "poisson" && mode != "farthest") throw py::value_error("mode must be 'poisson' or 'farthest'");
  o.mode = mode == "farthest" ? sampling::Mode::farthest : sampling::Mode::poisson;
  o.seed = seed;
  o.exact_count = exact;
  o.fill_vertices = fill;
  o.progress = interruptible(progress);
  sampling::SamplingResult r;
  {
    py::gil_scoped_release nogil;
    const sampling::Sampler sampler(mesh);
    r = sampler.sample(o);
  }
  std::vector<Vec3> points, normals;
  std::vector<std::array<double, 3>> bary;
  std::vector<Index> faces;
  for (const sampling::Sample& s : r.samples) {
    points.push_back(s.position), normals.push_back(s.normal), bary.push_back(s.point.barycentric), faces.push_back(s.point.element);
  }
  return {to_array(std::move(points)), to_array(std::move(bary)), to_array(std::move(normals)),
          to_array(std::move(r.coverage)), labels_to_array(faces), r.radius,
          r.stats.count_met};
}

}  // namespace

void bind_sampling(py::module_& m) {
  py::class_<Samples>(m, "Samples", "Samples on a mesh (gsp.sample).")
      .def_readonly("points", &Samples::points, "(k, 3) float64 positions")
      .def_readonly("faces", &Samples::faces, "(k,) int64 face of each sample")
      .def_readonly("barycentric", &Samples::barycentric, "(k, 3) float64 weights in the face")
      .def_readonly("normals", &Samples::normals, "(k, 3) float64 unit face normals")
      .def_readonly("radius", &Samples::radius,
                    "poisson: the disc radius (samples are at least this far apart geodesically); farthest: the "
                    "last sample's distance to the earlier ones")
      .def_readonly("coverage", &Samples::coverage, "(n,) per vertex: distance to the nearest sample (+inf beyond the runs)")
      .def_readonly("count_met", &Samples::count_met, "count= was met (exactly, with exact=True)")
      .def("__len__", [](const Samples& s) { return s.faces.size(); })
      .def("__repr__", [](const Samples& s) {
        return "Samples(" + std::to_string(s.faces.size()) + " points, radius " + std::string(py::str(py::float_(s.radius))) + ")";
      });
  m.def("sample", &sample, py::arg("V"), py::arg("F"), py::kw_only(), py::arg("count") = py::none(),
        py::arg("radius") = py::none(), py::arg("mode") = "poisson", py::arg("seed") = 1u, py::arg("exact") = true,
        py::arg("fill") = true, py::arg("progress") = py::none(),
        R"(Geodesic blue-noise samples on a mesh: a gsp.Samples.

Exactly one of count and radius (model units). mode 'poisson': dart throwing with geodesic
discs (count: the radius is searched; exact=True returns exactly `count` samples, dropping the
last-added surplus of the closest run above it); 'farthest': farthest-point sampling (exactly
`count`). fill adds samples at vertices still uncovered after dart throwing. Same seed, same
samples. progress(fraction) is called as it goes; Ctrl-C stops it.)");
}

}  // namespace gsp::python
