// gsp.cvt and gsp.remesh: geodesic centroidal Voronoi tessellation and its restricted
// Delaunay remesh, as gsp-cvt does them.
#include "arrays.hpp"
#include "bindings.hpp"
#include "errors.hpp"
#include "progress.hpp"

#include <gsp/cvt/cvt.hpp>
#include <gsp/cvt/remesh.hpp>
#include <gsp/cvt/surface.hpp>
#include <gsp/errors.hpp>

namespace gsp::python {

namespace {

struct Cvt {
  py::array_t<double> sites, barycentric, energy_curve;
  py::array_t<std::int64_t> faces, labels;
  double energy = 0;
  int iterations = 0;
  bool converged = false;
};

cvt::CvtOptions cvt_options(const TriangleMesh& mesh, const py::object& sites, const py::object& edge_length,
                            int iterations, std::uint64_t seed, const std::string& init, double feature_angle,
                            double cone_angle, unsigned threads, const py::object& progress,
                            const char* count_name) {
  if (mesh.num_faces() == 0) throw py::value_error("F is empty: a CVT needs faces");
  if (sites.is_none() == edge_length.is_none())
    throw py::value_error(std::string("give exactly one of ") + count_name + "= and edge_length=");
  cvt::CvtOptions o;
  if (!sites.is_none()) {
    const long long n = sites.cast<long long>();
    if (n <= 0) throw py::value_error(std::string(count_name) + " must be > 0");
    o.sites = std::size_t(n);
  } else {
    o.edge_length = edge_length.cast<double>();
    if (!(o.edge_length > 0) || !std::isfinite(o.edge_length)) throw py::value_error("edge_length must be > 0");
  }
  if (iterations < 0) throw py::value_error("iterations must be >= 0");
  o.max_iterations = iterations;
  o.seed = seed;
  o.threads = threads;
  if (!(feature_angle >= 0 && feature_angle <= 180)) throw py::value_error("feature_angle must be in [0, 180] degrees");
  o.feature_angle = feature_angle;
  if (!(cone_angle >= 0 && cone_angle <= 360)) throw py::value_error("cone_angle must be in [0, 360] degrees");
  o.cone_angle = cone_angle;
  if (init == "poisson") o.initial = cvt::InitialSites::poisson;
  else if (init == "farthest") o.initial = cvt::InitialSites::farthest;
  else if (init == "random") o.initial = cvt::InitialSites::random;
  else throw py::value_error("init must be 'poisson', 'farthest' or 'random'");
  auto tick = interruptible(progress);
  o.on_iteration = [tick](const cvt::IterationInfo& info) {
    tick(info.max_iterations ? double(info.iteration) / info.max_iterations : 1.0);
  };
  return o;
}

Cvt run_cvt(const py::handle& V, const py::handle& F, const py::object& sites, const py::object& edge_length,
            int iterations, std::uint64_t seed, const std::string& init, double feature_angle, unsigned threads,
            const py::object& progress, double cone_angle) {
  const TriangleMesh mesh = mesh_from_arrays(V, F);
  const cvt::CvtOptions o =
      cvt_options(mesh, sites, edge_length, iterations, seed, init, feature_angle, cone_angle, threads, progress, "sites");
  cvt::CvtResult r;
  {
    py::gil_scoped_release nogil;
    r = cvt::compute_cvt(mesh, o);
  }
  std::vector<Vec3> positions;
  std::vector<std::array<double, 3>> bary;
  std::vector<Index> faces;
  for (const cvt::Site& s : r.sites) positions.push_back(s.position), bary.push_back(s.point.barycentric), faces.push_back(s.point.element);
  return {to_array(std::move(positions)), to_array(std::move(bary)), to_array(std::move(r.energy_curve)),
          labels_to_array(faces), labels_to_array(r.vertex_label), r.energy, r.stats.iterations, r.stats.converged};
}

py::tuple remesh(const py::handle& V, const py::handle& F, const py::object& vertices, const py::object& edge_length,
                 int iterations, std::uint64_t seed, bool flip, bool smooth, double feature_angle, unsigned threads,
                 const py::object& progress, const std::string& method, double cone_angle, double sizing_angle) {
  const TriangleMesh mesh = mesh_from_arrays(V, F);
  if (!(sizing_angle >= 0 && sizing_angle <= 180)) throw py::value_error("sizing_angle must be in [0, 180] degrees");
  const cvt::RemeshMethod how = cvt::remesh_method(method);
  const cvt::CvtOptions o =
      cvt_options(mesh, vertices, edge_length, iterations, seed, "poisson", feature_angle, cone_angle, threads, progress,
                  "vertices");
  cvt::SurfaceRemeshResult r;
  {
    py::gil_scoped_release nogil;
    cvt::SurfaceRemeshOptions so;
    so.cvt = o;
    so.method = how;
    so.edge_sizing_angle = sizing_angle;
    so.remesh.flip_edges = flip;
    so.remesh.smooth = smooth;
    r = cvt::remesh_surface(mesh, so);
  }
  // As gsp-cvt: nothing remeshed is an error; some components kept as they were, a warning.
  const std::vector<std::string> kept = cvt::kept_components(r);
  if (!kept.empty() && kept.size() == r.components.size())
    throw TopologyError("no component could be remeshed; " + kept.front() + (kept.size() > 1 ? "; ..." : ""));
  if (!kept.empty()) {
    std::string message = "kept " + std::to_string(kept.size()) + " of " + std::to_string(r.components.size()) +
                          " components as they were: " + kept.front();
    for (std::size_t i = 1; i < kept.size() && i < 5; ++i) message += "; " + kept[i];
    if (kept.size() > 5) message += "; ...";
    warn_remesh(message);
  }
  return py::make_tuple(to_array(std::move(r.mesh.positions)), to_array(r.mesh.triangles));
}

}  // namespace

void bind_cvt(py::module_& m) {
  py::class_<Cvt>(m, "Cvt", "A geodesic centroidal Voronoi tessellation (gsp.cvt).")
      .def_readonly("sites", &Cvt::sites, "(k, 3) float64 site positions")
      .def_readonly("faces", &Cvt::faces, "(k,) int64 input face of each site")
      .def_readonly("barycentric", &Cvt::barycentric, "(k, 3) float64 each site in its face")
      .def_readonly("labels", &Cvt::labels, "(n,) int64 per input vertex: its region (site index; -1 unreached)")
      .def_readonly("energy", &Cvt::energy, "the CVT energy of the final sites")
      .def_readonly("energy_curve", &Cvt::energy_curve, "energy per accepted iteration (0 = initial sites)")
      .def_readonly("iterations", &Cvt::iterations)
      .def_readonly("converged", &Cvt::converged)
      .def("__repr__", [](const Cvt& c) {
        return "Cvt(" + std::to_string(c.faces.size()) + " sites, " + std::to_string(c.iterations) + " iterations)";
      });
  m.def("cvt", &run_cvt, py::arg("V"), py::arg("F"), py::kw_only(), py::arg("sites") = py::none(),
        py::arg("edge_length") = py::none(), py::arg("iterations") = 50, py::arg("seed") = 1u,
        py::arg("init") = "poisson", py::arg("feature_angle") = cvt::CvtOptions{}.feature_angle,
        py::arg("threads") = 0u, py::arg("progress") = py::none(), py::arg("cone_angle") = cvt::CvtOptions{}.cone_angle,
        R"(Geodesic centroidal Voronoi tessellation by Lloyd iterations with GSP: a gsp.Cvt.

Exactly one of sites (count) and edge_length (model units). Regions that are not disks are
repaired by adding sites, so len(result.sites) may exceed `sites` slightly. feature_angle
(degrees, 0 = off): crease curves sharper than this get fixed sites at even steps along them
(counted in `sites`). cone_angle (degrees, 0 = off, the default; 240 is a good value): spike
tips, interior vertices whose angles sum to less than this but not less than half of it, get
fixed sites too (gsp-cvt --cone-angle). threads: of the propagations (0 = automatic; 1 = the same result on
every run, see gsp-cvt --threads). progress(fraction) is called per iteration; Ctrl-C stops it.)");
  m.def("remesh", &remesh, py::arg("V"), py::arg("F"), py::kw_only(), py::arg("vertices") = py::none(),
        py::arg("edge_length") = py::none(), py::arg("iterations") = 50, py::arg("seed") = 1u, py::arg("flip") = true,
        py::arg("smooth") = true, py::arg("feature_angle") = cvt::CvtOptions{}.feature_angle,
        py::arg("threads") = 0u, py::arg("progress") = py::none(), py::arg("method") = "cvt",
        py::arg("cone_angle") = cvt::CvtOptions{}.cone_angle,
        py::arg("sizing_angle") = cvt::SurfaceRemeshOptions{}.edge_sizing_angle,
        R"(Isotropic remesh (gsp-cvt): the restricted Delaunay dual of a geodesic CVT, as (V2, F2).

Exactly one of vertices (about that many output vertices) and edge_length. Each connected
component is remeshed on its own (vertices by area); one whose CVT dual lacks its topology
(handles or walls thinner than the spacing) is remeshed by edge operations instead (split,
collapse, flip, smooth, project: docs/cvt.md). One that cannot be (non-manifold edges, not
orientable, too small a share, neither remesh with its topology) is returned as it is, with
a gsp.RemeshWarning naming it and the reason; ValueError when no component could be
remeshed (as gsp-cvt). flip and smooth are the angle-raising post-passes. feature_angle
(degrees, 0 = off): edges whose faces' normals differ by more than this form crease curves,
kept in the remesh as chains of edges with their corners as vertices (gsp-cvt --feature-angle).
cone_angle (degrees, 0 = off, the default; 240 is a good value): spike tips (interior vertices
whose angles sum to less than it, at least half of it) are vertices of the remesh instead of
being cut off (gsp-cvt --cone-angle). sizing_angle (degrees, 0 = one spacing everywhere):
edge operations make edges shorter where the surface bends tightly, each spanning at most this
much of a bend, down to a quarter of the spacing (gsp-cvt --sizing-angle).
threads: of the propagations (0 = automatic, where ties make large meshes vary slightly from
run to run; 1 = the same output every run); components are remeshed side by side on them, with
the one-thread result. progress(fraction) per Lloyd iteration; Ctrl-C stops it.
method: "cvt" (default) or "edges": edge operations first (several times faster, no CVT;
the CVT where that remesh is not kept or is below 20 degrees), as gsp-cvt --method;
ValueError for other names.)");
}

}  // namespace gsp::python
