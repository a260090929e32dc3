// gsp.GeodesicSolver, gsp.geodesic_distance's engine: distances from vertices and surface
// points, labels, distance matrices, distances at surface points.
#include "solver.hpp"

#include "core_slots.hpp"

#include "arrays.hpp"
#include "bindings.hpp"
#include "metric.hpp"
#include "progress.hpp"
#include "surface_point.hpp"

#include <gsp/batch.hpp>
#include <gsp/layout.hpp>
#include <gsp/strategy_names.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace gsp::python {

namespace {

bool same_sources(const std::vector<Source>& a, const std::vector<Source>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i].kind != b[i].kind || a[i].element != b[i].element || a[i].barycentric != b[i].barycentric ||
        a[i].offset != b[i].offset)
      return false;
  return true;
}

bool same_query(const GeodesicOptions& a, const GeodesicOptions& b) {
  return a.strategy == b.strategy && a.precision == b.precision && a.max_distance == b.max_distance &&
         a.vertex_relaxation == b.vertex_relaxation;
}

Strategy strategy_from(const std::string& name) {
  if (const auto s = strategy_from_name(name)) return *s;
  throw py::value_error("strategy must be one of " + strategy_names() + " (got '" + name + "')");
}

py::object with_labels(py::array_t<double> distance, const std::vector<Index>& label, bool labels) {
  if (!labels) return std::move(distance);
  return py::make_tuple(std::move(distance), labels_to_array(label));
}

// Row values at the targets: vertex distances, or the field at a surface point.
void fill_row(const Solver& s, const GeodesicResult& r, const std::vector<Source>& targets, double* row) {
  for (std::size_t j = 0; j < targets.size(); ++j) {
    const Source& t = targets[j];
    row[j] = t.kind == Source::Kind::vertex ? r.vertex_distance[t.element]
                                            : r.distance_at(s.mesh(), t.element, t.barycentric);
  }
}

py::array_t<double> distance_matrix(Solver& s, const py::handle& points, const py::handle& targets, double max_distance,
                                    const std::string& strategy, unsigned threads, const std::string& precision,
                                    bool relax, const py::object& progress) {
  const std::vector<Source> rows = sources_from(points, s.mesh(), "points");
  std::vector<Source> cols;
  if (targets.is_none()) {
    cols = rows;
  } else if (py::isinstance<py::str>(targets)) {
    if (targets.cast<std::string>() != "vertices") throw py::value_error("targets must be None, 'vertices' or points");
    for (Index v = 0; v < s.mesh().num_vertices(); ++v) cols.push_back(Source::at_vertex(v));
  } else {
    cols = sources_from(targets, s.mesh(), "targets");
  }
  GeodesicOptions o = query_options(max_distance, strategy, threads, precision, relax);
  o.want_face_distances = false;
  o.want_face_sources = std::any_of(cols.begin(), cols.end(), [](const Source& t) { return t.kind != Source::Kind::vertex; });
  o.fitted_face_sources = o.want_face_sources;
  if (o.want_face_sources) s.require_3d("distances at surface points");
  const unsigned workers = resolve_threads(threads, rows.size());
  o.threads = 1;   // one query per worker
  const std::size_t chunk = std::max<std::size_t>(8, 4 * workers);
  py::array_t<double> out({py::ssize_t(rows.size()), py::ssize_t(cols.size())});
  double* data = out.mutable_data();
  const auto tick = interruptible(progress);
  {
    py::gil_scoped_release nogil;
    for (std::size_t begin = 0; begin < rows.size(); begin += chunk) {
      const std::size_t end = std::min(rows.size(), begin + chunk);
      std::vector<std::vector<Source>> queries;
      for (std::size_t i = begin; i < end; ++i) queries.push_back({rows[i]});
      const std::vector<GeodesicResult> fields = compute_many(s.solver(), queries, o, workers);
      for (std::size_t i = begin; i < end; ++i) fill_row(s, fields[i - begin], cols, data + i * cols.size());
      tick(double(end) / double(rows.size()));
    }
  }
  return out;
}

}  // namespace

Precision precision_from(const std::string& name) {
  if (name == "auto" || name == "automatic") return Precision::automatic;
  if (name == "single") return Precision::single;
  if (name == "double") return Precision::double_precision;
  throw py::value_error("precision must be 'auto', 'single' or 'double' (got '" + name + "')");
}

GeodesicOptions query_options(double max_distance, const std::string& strategy, unsigned threads,
                              const std::string& precision, bool relax) {
  if (std::isnan(max_distance) || max_distance < 0) throw py::value_error("max_distance must be >= 0 (inf: no bound)");
  GeodesicOptions o;
  o.max_distance = max_distance;
  o.strategy = strategy_from(strategy);
  o.threads = threads;
  o.precision = precision_from(precision);
  o.vertex_relaxation = relax;
  return o;
}

Solver::Solver(TriangleMesh mesh, const SolverOptions& options, bool metric)
    : mesh_(std::make_shared<const TriangleMesh>(std::move(mesh))),
      solver_(mesh_, options),
      metric_(metric),
      layout_(options.optimize_layout) {}

GeodesicResult Solver::compute(const std::vector<Source>& sources, GeodesicOptions options) const {
  struct InFlight {
    std::atomic<int>& n;
    int before;
    explicit InFlight(std::atomic<int>& count) : n(count), before(count.fetch_add(1)) {}
    ~InFlight() { n.fetch_sub(1); }
  } guard(in_flight_);
  if (options.threads == 0 && guard.before > 0) options.threads = 1;
  const CoreSlot slot;
  return solver_.compute(sources, options);
}

const pathfinding::PathTracer& Solver::tracer() const {
  std::call_once(tracer_once_, [this] { tracer_ = std::make_unique<pathfinding::PathTracer>(*mesh_); });
  return *tracer_;
}

void Solver::require_3d(const char* what) const {
  if (metric_) throw py::value_error(std::string(what) + " need the 3D metric: not available on a solver built with metric=");
}

void Solver::remember(const std::vector<Source>& sources, const GeodesicOptions& options) {
  std::lock_guard<std::mutex> lock(memo_mutex_);
  last_sources_ = sources, last_options_ = options, have_last_ = true;
}

std::shared_ptr<const GeodesicResult> Solver::field_with_sources(const std::vector<Source>* sources,
                                                                 const GeodesicOptions* options) {
  std::vector<Source> want_sources;
  GeodesicOptions want;
  {
    std::lock_guard<std::mutex> lock(memo_mutex_);
    if (!sources && !have_last_)
      throw py::value_error("distance_at: no field yet; call distance() first or pass sources=");
    want_sources = sources ? *sources : last_sources_;
    want = options ? *options : last_options_;
    if (field_ && same_sources(want_sources, field_sources_) && same_query(want, field_options_)) return field_;
  }
  want.want_face_sources = true;
  want.fitted_face_sources = true;   // readings, no walk: the sources closest to the vertex values
  want.want_face_distances = false;
  auto field = std::make_shared<const GeodesicResult>(compute(want_sources, want));
  std::lock_guard<std::mutex> lock(memo_mutex_);
  field_sources_ = want_sources, field_options_ = want, field_ = field;
  return field;
}

namespace {

// optimize_layout: True, False or "auto" (gsp::order_coherence decides, as gsp-geodesic's
// --layout auto for one field: a scattered file gets the cheap Z-order, a file with coherent
// vertices and scattered faces only its faces sorted, a coherent one nothing).
void layout_from(const py::handle& value, const TriangleMesh& mesh, SolverOptions& options) {
  if (py::isinstance<py::str>(value)) {
    if (value.cast<std::string>() != "auto")
      throw py::value_error("optimize_layout must be True, False or \"auto\", not \"" + value.cast<std::string>() + "\"");
    const OrderCoherence order = order_coherence(mesh);
    options.optimize_layout = !order.coherent || order.sort_faces;
    options.spatial_layout = !order.coherent;
    options.faces_only_layout = order.sort_faces;
    return;
  }
  if (!py::isinstance<py::bool_>(value)) throw py::type_error("optimize_layout must be True, False or \"auto\"");
  options.optimize_layout = value.cast<bool>();
}

}  // namespace

void bind_solver(py::module_& m) {
  py::class_<Solver> cls(m, "GeodesicSolver", R"(A triangle mesh prepared once for any number of geodesic queries.

GeodesicSolver(V, F, *, intrinsic_delaunay=True, metric=None, optimize_layout=True)

V (n, 3) float, F (m, 3) int. Non-manifold, degenerate and soup meshes are accepted (faces
that repeat a vertex are left out). intrinsic_delaunay propagates on the intrinsic Delaunay
triangulation (same surface, better-shaped triangles); metric is a gsp.metric.Metric (or a
(3,3) tensor, or (n,3,3) / (m,3,3) tensors) to measure lengths in; optimize_layout reorders
the faces for the cache (results keep the input's order): True, False, or "auto" (reorder
unless the arrays' own order is already coherent, only the faces where only they are not:
what pays for a single query, the default of gsp.geodesic_distance; see docs/scale.md). Every method releases the GIL, so threads can query
one solver in parallel.)");
  cls.def(py::init([](const py::handle& V, const py::handle& F, bool intrinsic_delaunay, const py::handle& metric,
                      const py::handle& optimize_layout) {
            TriangleMesh mesh = mesh_from_arrays(V, F);
            if (mesh.num_faces() == 0) throw py::value_error("F is empty: a GeodesicSolver needs faces (see PointCloudSolver)");
            SolverOptions options = metric_solver_options(mesh, metric);
            options.intrinsic_delaunay = intrinsic_delaunay;
            layout_from(optimize_layout, mesh, options);
            py::gil_scoped_release nogil;
            return std::make_unique<Solver>(std::move(mesh), options, !options.edge_lengths.empty());
          }),
          py::arg("V"), py::arg("F"), py::kw_only(), py::arg("intrinsic_delaunay") = true, py::arg("metric") = py::none(),
          py::arg("optimize_layout") = true);
  cls.def_property_readonly("optimize_layout", &Solver::layout_applied,
                            "whether the faces were reordered for the cache (\"auto\" resolved)");
  cls.def_property_readonly("num_vertices", [](const Solver& s) { return s.mesh().num_vertices(); });
  cls.def_property_readonly("num_faces", [](const Solver& s) { return s.mesh().num_faces(); });
  cls.def(
      "distance",
      [](Solver& s, const py::handle& sources, double max_distance, const std::string& strategy, unsigned threads,
         bool labels, const std::string& precision, bool relax) {
        const std::vector<Source> src = sources_from(sources, s.mesh(), "sources");
        GeodesicOptions o = query_options(max_distance, strategy, threads, precision, relax);
        o.want_face_distances = false;
        s.remember(src, o);
        GeodesicResult r;
        {
          py::gil_scoped_release nogil;
          r = s.compute(src, o);
        }
        return with_labels(to_array(std::move(r.vertex_distance)), r.vertex_source, labels);
      },
      py::arg("sources"), py::kw_only(), py::arg("max_distance") = std::numeric_limits<double>::infinity(),
      py::arg("strategy") = "speed_limiter", py::arg("threads") = 0u, py::arg("labels") = false,
      py::arg("precision") = "auto", py::arg("relax") = true,
      R"(Geodesic distance from the sources to every vertex: an (n,) float64 array, +inf where unreachable.

sources: a vertex index, a gsp.SurfacePoint, or a list / array of them (mixed lists allowed);
the distance is to the nearest one. labels=True returns (distance, label) with label the index
of the nearest source (int64, -1 where unreached). max_distance bounds the propagation (vertices
beyond are +inf). strategy: the queue strategy (speed_limiter, priority_queue, ...). threads: 0
chooses (several only on large meshes), 1 is sequential. precision: 'auto' (double where faces
are too thin for float), 'single' or 'double'. relax: vertices as pseudo-sources (never above
the shortest edge path).)");
  cls.def(
      "distance_at",
      [](Solver& s, const py::handle& faces, const py::handle& barycentric, const py::handle& sources,
         double max_distance, const std::string& strategy, const std::string& precision, bool relax) {
        s.require_3d("distances at surface points");
        const std::vector<Index> f = indices_from(faces, s.mesh().num_faces(), "faces");
        auto b = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(
            py::module_::import("numpy").attr("asarray")(barycentric));
        if (!b || b.size() != py::ssize_t(3 * f.size()))
          throw py::value_error("barycentric must have shape (k, 3) with k = len(faces)");
        std::vector<std::array<double, 3>> bary(f.size());
        for (std::size_t i = 0; i < f.size(); ++i)
          bary[i] = barycentric_from(py::make_tuple(b.data()[3 * i], b.data()[3 * i + 1], b.data()[3 * i + 2]), "barycentric");
        std::shared_ptr<const GeodesicResult> field;
        if (sources.is_none()) {
          py::gil_scoped_release nogil;
          field = s.field_with_sources(nullptr, nullptr);
        } else {
          const std::vector<Source> src = sources_from(sources, s.mesh(), "sources");
          const GeodesicOptions o = query_options(max_distance, strategy, 0, precision, relax);
          py::gil_scoped_release nogil;
          field = s.field_with_sources(&src, &o);
        }
        std::vector<double> out(f.size());
        for (std::size_t i = 0; i < f.size(); ++i) out[i] = field->distance_at(s.mesh(), f[i], bary[i]);
        return to_array(std::move(out));
      },
      py::arg("faces"), py::arg("barycentric"), py::kw_only(), py::arg("sources") = py::none(),
      py::arg("max_distance") = std::numeric_limits<double>::infinity(), py::arg("strategy") = "speed_limiter",
      py::arg("precision") = "auto", py::arg("relax") = true,
      R"(Geodesic distance at surface points (faces (k,), barycentric (k, 3)): a (k,) float64 array.

Evaluates the field of `sources` (same keywords as distance()), or, without sources, the field
of this solver's last distance() call, through each face's virtual source: exact inside a face
for what the face's source explains, unlike interpolating vertex values. The sources are fitted
to distance()'s vertex values from the run on the intrinsic Delaunay faces, and never read below
the straight line from the source.)");
  cls.def("distance_matrix", &distance_matrix, py::arg("points"), py::kw_only(), py::arg("targets") = py::none(),
          py::arg("max_distance") = std::numeric_limits<double>::infinity(), py::arg("strategy") = "speed_limiter",
          py::arg("threads") = 0u, py::arg("precision") = "auto", py::arg("relax") = true,
          py::arg("progress") = py::none(),
          R"(Distances between surface points: a (k, t) float64 array, row i the field from points[i].

points: vertex indices and/or gsp.SurfacePoint values. targets: None (the same points: a
k x k matrix), 'vertices' (every vertex: k x n) or another list of points. Rows run in
parallel on `threads` (0: all cores). The matrix is not exactly symmetric (each row is its own
propagation); (D + D.T) / 2 is. progress(fraction) is called after each batch of rows; Ctrl-C
stops the call.)");
  add_path_methods(cls);
}

}  // namespace gsp::python
