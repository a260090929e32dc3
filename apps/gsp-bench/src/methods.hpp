#pragma once
// The methods gsp-bench compares, and a uniform way to run them: a Runner is one method
// prepared on one mesh (its constructor is the precompute step: solver build, heat
// factorisation, CGAL structures), and run() answers one single-source query, which is what
// gets timed.
#include <gsp/geodesics.hpp>
#include <gsp/mesh.hpp>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace gsp::bench {

enum class Method {
  gsp,                 // GSP as shipped: optimised layout, speed limiter, automatic precision
  gsp_pq,              // priority queue (Dijkstra order on d_T)
  gsp_sl_postpone,     // the speed limiter that postpones entries still beyond its limit
  gsp_bfs,             // topological (BFS) order
  gsp_hybrid,          // hybrid postpone, fat queue
  gsp_double,          // double-precision state
  gsp_random_layout,   // the mesh shuffled in memory, no layout optimisation
  gsp_no_layout,       // the mesh in file order, no layout optimisation
  gsp_input_faces,     // on the input triangles instead of their intrinsic Delaunay flip
  gsp_face_sources,    // the per-face virtual sources (want_face_sources) read at each face's corners
  gsp_fitted_sources,  // ... fitted ones (GeodesicOptions::fitted_face_sources)
  gsp_no_relax,        // without the vertex relaxation (per-face virtual sources alone, the paper's)
  gsp_no_line_test,    // without the update step's straight-line test (rule 8)
  gsp_no_windows,      // without the carried windows (rule 10)
  gsp_no_line,         // without the straight-line bound (the propagation's own values below it)
  gsp_2threads,        // the parallel propagation on 2 threads (GeodesicOptions::threads)
  gsp_4threads,        // ... on 4 threads
  dijkstra,            // edge graph, binary heap
  heat,                // CGAL heat method on the input triangles
  heat_idt,            // CGAL heat method on an intrinsic Delaunay retriangulation
  exact,               // CGAL exact geodesics (the reference)
  points_gsp,          // point-cloud GSP on the mesh's vertices (gsp::pointcloud, local triangles)
  points_graph_gsp,    // point-cloud GSP over the k-NN graph's links (PointMethod::graph_gsp)
  points_dijkstra,     // Dijkstra on the same k-NN graph (the point-cloud baseline)
  gsp_windows,         // experimental: two windows per face (gsp/window_geodesics.hpp)
  gsp_windows3,        // ... three
};

struct MethodInfo {
  Method id;
  const char* name;          // as on the command line and in the reports
  const char* description;
  bool in_default_list;
};

const std::vector<MethodInfo>& all_methods();
std::string default_method_list();   // "gsp,gsp-pq,..."
std::string method_names();          // every name, for --help
const MethodInfo& method_info(Method id);
bool is_gsp(Method id);
bool uses_cgal(Method id);           // refused on meshes CGAL cannot take
bool is_points(Method id);           // runs on the mesh's vertices as a point cloud

// The methods of --domain points: both point-cloud methods, mesh GSP (for the time ratio) and
// the exact reference.
std::string points_method_list();

// "gsp,dijkstra" -> the methods in the order given; duplicates dropped. UsageError for
// unknown names or an empty list.
std::vector<MethodInfo> parse_methods(const std::string& list);

// What one query produced.
struct Outcome {
  std::vector<double> distance;   // per vertex, in the runner's own vertex order
  PropagationStats stats;         // GSP and Dijkstra only
  bool has_stats = false;
};

class Runner {
 public:
  virtual ~Runner() = default;
  virtual Outcome run(Index source) = 0;   // the timed part
  // Distances back in the mesh's vertex order (only the random layout permutes; untimed).
  virtual std::vector<double> to_mesh_order(std::vector<double> d) const { return d; }
  // GSP: bytes of propagation state per query (GeodesicSolver::state_bytes); 0 otherwise.
  virtual std::size_t state_bytes() const { return 0; }
  virtual std::size_t intrinsic_flips() const { return 0; }
  // Runs on several threads: timed by the wall clock even with --cpu-clock (one thread's CPU
  // time would miss the others).
  virtual bool threaded() const { return false; }
};

// Prepares `method` on `mesh` (the precompute step). `seed` shuffles the random layout;
// `neighbours` is k of the point-cloud methods' k-NN graph.
// Throws gsp::TopologyError / gsp::InvalidInput / gsp::Error where the method refuses the mesh.
std::unique_ptr<Runner> make_runner(Method method, const TriangleMesh& mesh, std::uint64_t seed,
                                    unsigned neighbours = 10);

}  // namespace gsp::bench
