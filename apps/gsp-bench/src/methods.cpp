#include "methods.hpp"

#include <gsp/cli/app.hpp>
#include <gsp/dijkstra.hpp>
#include <gsp/layout.hpp>
#include <gsp/pointcloud/point_cloud_geodesics.hpp>
#include <gsp/reference/exact_geodesics.hpp>
#include <gsp/reference/heat_method.hpp>
#include <gsp/window_geodesics.hpp>

#include <algorithm>
#include <sstream>

namespace gsp::bench {

const std::vector<MethodInfo>& all_methods() {
  static const std::vector<MethodInfo> methods = {
      {Method::gsp, "gsp", "GSP: optimised layout, speed limiter, automatic precision, vertex relaxation (the defaults)", true},
      {Method::gsp_pq, "gsp-pq", "GSP with a priority queue (Dijkstra order on d_T)", true},
      {Method::gsp_sl_postpone, "gsp-sl-postpone", "GSP with the speed limiter that postpones entries still beyond its limit", false},
      {Method::gsp_bfs, "gsp-bfs", "GSP in topological (BFS) order", true},
      {Method::gsp_hybrid, "gsp-hybrid", "GSP with hybrid postpone (fat queue)", true},
      {Method::gsp_double, "gsp-double", "GSP with double-precision state", true},
      {Method::gsp_random_layout, "gsp-random-layout", "GSP on a randomly shuffled mesh, layout optimisation off", true},
      {Method::gsp_no_layout, "gsp-no-layout", "GSP on the file's order, layout optimisation off", true},
      {Method::gsp_input_faces, "gsp-input-faces", "GSP on the input triangles (no intrinsic Delaunay flips)", false},
      {Method::gsp_face_sources, "gsp-face-sources", "GSP's per-face virtual sources (the input faces' run: what paths and CVT read) at the faces' corners, per vertex the mean over its faces", false},
      {Method::gsp_fitted_sources, "gsp-fitted-sources", "the same for the fitted per-face sources (fitted_face_sources: the sources Python's distance_at reads)", false},
      {Method::gsp_no_relax, "gsp-no-relax", "GSP without the vertex relaxation (per-face virtual sources alone)", false},
      {Method::gsp_no_line_test, "gsp-no-line-test", "GSP without the update step's straight-line test (rule 8; the final bound kept)", false},
      {Method::gsp_no_windows, "gsp-no-windows", "GSP without the carried windows (rule 10)", false},
      {Method::gsp_no_line, "gsp-no-line", "GSP without the straight-line bound (values below the segment kept)", false},
      {Method::gsp_2threads, "gsp-2threads", "GSP's parallel propagation on 2 threads (time is wall time)", false},
      {Method::gsp_4threads, "gsp-4threads", "GSP's parallel propagation on 4 threads (time is wall time)", false},
      {Method::dijkstra, "dijkstra", "Dijkstra on the edge graph (binary heap)", true},
      {Method::heat, "heat", "CGAL heat method on the input triangles", true},
      {Method::heat_idt, "heat-idt", "CGAL heat method on an intrinsic Delaunay retriangulation", true},
      {Method::exact, "exact", "CGAL exact geodesics (Xin-Wang), the reference", true},
      {Method::points_gsp, "points-gsp", "point-cloud GSP on the mesh's vertices (local triangles of the k-NN graph, normals by PCA)", false},
      {Method::points_graph_gsp, "points-graph-gsp", "point-cloud GSP over the links of the same k-NN graph (virtual sources in tangent planes)", false},
      {Method::points_dijkstra, "points-dijkstra", "Dijkstra on the same k-NN graph of the mesh's vertices", false},
      {Method::gsp_windows, "gsp-windows", "experimental: two windows per face instead of one virtual source (input triangles, priority queue, double)", false},
      {Method::gsp_windows3, "gsp-windows3", "experimental: three windows per face", false},
  };
  return methods;
}

std::string default_method_list() {
  std::string out;
  for (const MethodInfo& m : all_methods())
    if (m.in_default_list) out += (out.empty() ? "" : ",") + std::string(m.name);
  return out;
}

std::string method_names() {
  std::string out;
  for (const MethodInfo& m : all_methods()) out += (out.empty() ? "" : ", ") + std::string(m.name);
  return out;
}

const MethodInfo& method_info(Method id) {
  for (const MethodInfo& m : all_methods())
    if (m.id == id) return m;
  return all_methods().front();   // unreachable: every enumerator is listed
}

bool is_gsp(Method id) { return id <= Method::gsp_no_line; }
bool uses_cgal(Method id) { return id == Method::heat || id == Method::heat_idt || id == Method::exact; }
bool is_points(Method id) {
  return id == Method::points_gsp || id == Method::points_graph_gsp || id == Method::points_dijkstra;
}
std::string points_method_list() { return "points-gsp,points-graph-gsp,points-dijkstra,gsp,exact"; }

std::vector<MethodInfo> parse_methods(const std::string& list) {
  std::vector<MethodInfo> out;
  std::stringstream in(list);
  for (std::string name; std::getline(in, name, ',');) {
    name.erase(0, name.find_first_not_of(' '));
    name.erase(name.find_last_not_of(' ') + 1);
    if (name.empty()) continue;
    const auto& all = all_methods();
    auto it = std::find_if(all.begin(), all.end(), [&](const MethodInfo& m) { return name == m.name; });
    if (it == all.end())
      throw cli::UsageError("--methods: \"" + name + "\" is not one of " + method_names());
    if (std::none_of(out.begin(), out.end(), [&](const MethodInfo& m) { return m.id == it->id; }))
      out.push_back(*it);
  }
  if (out.empty()) throw cli::UsageError("--methods: no method given");
  return out;
}

namespace {

class GspRunner : public Runner {
 public:
  GspRunner(const TriangleMesh& mesh, const SolverOptions& so, const GeodesicOptions& go)
      : solver_(mesh, so), options_(go) {}
  Outcome run(Index source) override {
    GeodesicResult r = solver_.compute({Source::at_vertex(source)}, options_);
    return {std::move(r.vertex_distance), r.stats, true};
  }
  std::size_t state_bytes() const override { return solver_.state_bytes(options_.precision); }
  std::size_t intrinsic_flips() const override { return solver_.intrinsic_flips(); }
  bool threaded() const override { return options_.threads != 1; }

 private:
  GeodesicSolver solver_;
  GeodesicOptions options_;
};

// What the face sources give (GeodesicOptions::want_face_sources): each face's sigma + |x - S|
// at its corners x, per vertex the mean over its reached faces (a vertex of no reached face
// keeps the solver's value).
class FaceSourceRunner : public Runner {
 public:
  FaceSourceRunner(const TriangleMesh& mesh, bool fitted) : mesh_(mesh), solver_(mesh) {
    options_.threads = 1;
    options_.want_face_distances = false;
    options_.want_face_sources = true;
    options_.fitted_face_sources = fitted;
  }
  Outcome run(Index source) override {
    GeodesicResult r = solver_.compute({Source::at_vertex(source)}, options_);
    std::vector<double> sum(mesh_.num_vertices(), 0);
    std::vector<int> count(mesh_.num_vertices(), 0);
    for (std::size_t f = 0; f < mesh_.num_faces(); ++f) {
      const VirtualSource& s = r.face_sources[f];
      if (!s.reached()) continue;
      for (Index v : mesh_.triangles[f]) sum[v] += s.sigma + distance(mesh_.positions[v], s.position), ++count[v];
    }
    for (std::size_t v = 0; v < sum.size(); ++v)
      if (count[v] > 0) r.vertex_distance[v] = sum[v] / count[v];
    return {std::move(r.vertex_distance), r.stats, true};
  }
  std::size_t state_bytes() const override { return solver_.state_bytes(options_.precision); }
  std::size_t intrinsic_flips() const override { return solver_.intrinsic_flips(); }

 private:
  const TriangleMesh& mesh_;
  GeodesicSolver solver_;
  GeodesicOptions options_;
};

// The mesh is permuted by a random layout before the solver sees it; sources are mapped in
// and distances out, both outside the timed call.
class RandomLayoutRunner : public Runner {
 public:
  RandomLayoutRunner(const TriangleMesh& mesh, std::uint64_t seed)
      : layout_(random_layout(mesh, seed)), solver_(apply_layout(mesh, layout_), no_layout()) {}
  Outcome run(Index source) override {
    GeodesicOptions options;
    options.threads = 1;
    options.want_face_distances = false;   // as make_runner's GSP variants
    GeodesicResult r = solver_.compute({Source::at_vertex(layout_.vertex_rank[source])}, options);
    return {std::move(r.vertex_distance), r.stats, true};
  }
  std::vector<double> to_mesh_order(std::vector<double> d) const override {
    std::vector<double> out(d.size());
    for (std::size_t v = 0; v < d.size(); ++v) out[v] = d[layout_.vertex_rank[v]];
    return out;
  }
  std::size_t state_bytes() const override { return solver_.state_bytes(Precision::single); }
  std::size_t intrinsic_flips() const override { return solver_.intrinsic_flips(); }

 private:
  static SolverOptions no_layout() {
    SolverOptions so;
    so.optimize_layout = false;
    return so;
  }
  Layout layout_;
  GeodesicSolver solver_;
};

class DijkstraRunner : public Runner {
 public:
  explicit DijkstraRunner(const TriangleMesh& mesh) : solver_(mesh) {}
  Outcome run(Index source) override {
    GeodesicResult r = solver_.compute({Source::at_vertex(source)});
    return {std::move(r.vertex_distance), r.stats, true};
  }

 private:
  DijkstraSolver solver_;
};

class HeatRunner : public Runner {
 public:
  HeatRunner(const TriangleMesh& mesh, reference::HeatMethodMode mode) : solver_(mesh, mode) {}
  Outcome run(Index source) override { return {solver_.solve({source}), {}, false}; }

 private:
  reference::HeatMethodSolver solver_;
};

class ExactRunner : public Runner {
 public:
  explicit ExactRunner(const TriangleMesh& mesh) : solver_(mesh) {}
  Outcome run(Index source) override { return {solver_.distances_from_vertex(source), {}, false}; }

 private:
  reference::ExactGeodesicSolver solver_;
};

// The mesh's vertices as a bare point cloud: positions only (a scan without normals), so
// the tangent frames come from local PCA. The k-d tree, graph, frames and (points-gsp) the
// local triangles are the precompute.
class PointCloudRunner : public Runner {
 public:
  PointCloudRunner(const TriangleMesh& mesh, unsigned neighbours, pointcloud::PointMethod method)
      : solver_(mesh.positions, {}, cloud_options(neighbours, method)) {
    options_.method = method;
  }
  Outcome run(Index source) override {
    pointcloud::PointCloudResult r = solver_.compute({pointcloud::PointSource::at_point(source)}, options_);
    return {std::move(r.distance), {}, false};
  }

 private:
  static pointcloud::PointCloudOptions cloud_options(unsigned neighbours, pointcloud::PointMethod method) {
    pointcloud::PointCloudOptions o;
    o.neighbours.k = neighbours;
    o.local_triangles = method == pointcloud::PointMethod::gsp;   // only that method uses them
    return o;
  }
  pointcloud::PointCloudGeodesics solver_;
  pointcloud::PointGeodesicOptions options_;
};

class WindowRunner : public Runner {
 public:
  WindowRunner(const TriangleMesh& mesh, unsigned windows) : solver_(mesh) { options_.windows = windows; }
  Outcome run(Index source) override { return {solver_.distances_from_vertex(source, options_), {}, false}; }

 private:
  WindowGeodesics solver_;
  WindowOptions options_;
};

}  // namespace

std::unique_ptr<Runner> make_runner(Method method, const TriangleMesh& mesh, std::uint64_t seed, unsigned neighbours) {
  SolverOptions so;
  GeodesicOptions go;
  go.threads = 1;   // every GSP variant on one thread unless it says otherwise
  // Every method delivers what Dijkstra and the heat method do: per-vertex distances (and
  // labels); GSP's per-face arrays would be extra work none of the others pays for.
  go.want_face_distances = false;
  switch (method) {
    case Method::gsp: break;
    case Method::gsp_2threads: go.threads = 2; break;
    case Method::gsp_4threads: go.threads = 4; break;
    case Method::gsp_pq: go.strategy = Strategy::priority_queue; break;
    case Method::gsp_sl_postpone: go.strategy = Strategy::speed_limiter_postpone; break;
    case Method::gsp_bfs: go.strategy = Strategy::bfs; break;
    case Method::gsp_hybrid: go.strategy = Strategy::hybrid_postpone; break;
    case Method::gsp_double: go.precision = Precision::double_precision; break;
    case Method::gsp_no_layout: so.optimize_layout = false; break;
    case Method::gsp_input_faces: so.intrinsic_delaunay = false; break;
    case Method::gsp_face_sources: return std::make_unique<FaceSourceRunner>(mesh, false);
    case Method::gsp_fitted_sources: return std::make_unique<FaceSourceRunner>(mesh, true);
    case Method::gsp_no_relax: go.vertex_relaxation = false; break;
    case Method::gsp_no_line: go.straight_line_bound = false; break;
    case Method::gsp_no_line_test: go.straight_line_test = false; break;
    case Method::gsp_no_windows: go.carried_windows = false; break;
    case Method::gsp_random_layout: return std::make_unique<RandomLayoutRunner>(mesh, seed);
    case Method::dijkstra: return std::make_unique<DijkstraRunner>(mesh);
    case Method::heat: return std::make_unique<HeatRunner>(mesh, reference::HeatMethodMode::direct);
    case Method::heat_idt: return std::make_unique<HeatRunner>(mesh, reference::HeatMethodMode::intrinsic_delaunay);
    case Method::exact: return std::make_unique<ExactRunner>(mesh);
    case Method::points_gsp: return std::make_unique<PointCloudRunner>(mesh, neighbours, pointcloud::PointMethod::gsp);
    case Method::points_graph_gsp:
      return std::make_unique<PointCloudRunner>(mesh, neighbours, pointcloud::PointMethod::graph_gsp);
    case Method::points_dijkstra:
      return std::make_unique<PointCloudRunner>(mesh, neighbours, pointcloud::PointMethod::dijkstra);
    case Method::gsp_windows: return std::make_unique<WindowRunner>(mesh, 2);
    case Method::gsp_windows3: return std::make_unique<WindowRunner>(mesh, 3);
  }
  return std::make_unique<GspRunner>(mesh, so, go);
}

}  // namespace gsp::bench
