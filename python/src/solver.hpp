#pragma once
// gsp.GeodesicSolver: a mesh prepared once (GeodesicSolver) plus what the Python methods
// share: the path tracer (built on first use), and the last distance() query, so that
// distance_at() without sources evaluates that field.
#include <gsp/geodesics.hpp>
#include <gsp/pathfinding/path_tracer.hpp>

#include <pybind11/pybind11.h>

#include <atomic>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace gsp::python {

// The query keywords every distance method takes, as GeodesicOptions.
GeodesicOptions query_options(double max_distance, const std::string& strategy, unsigned threads,
                              const std::string& precision, bool relax);
Precision precision_from(const std::string& name);

class Solver {
 public:
  Solver(TriangleMesh mesh, const SolverOptions& options, bool metric);

  const TriangleMesh& mesh() const { return *mesh_; }
  const GeodesicSolver& solver() const { return solver_; }
  bool has_metric() const { return metric_; }
  bool layout_applied() const { return layout_; }
  // Connectivity for tracing paths; built once, on the first path query (thread-safe).
  const pathfinding::PathTracer& tracer() const;
  // Per-face virtual sources are a 3D construction: not available with a metric.
  void require_3d(const char* what) const;

  void remember(const std::vector<Source>& sources, const GeodesicOptions& options);
  // A query with threads = 0 (automatic) while another runs on this solver in another Python
  // thread: the caller already runs queries in parallel, so this one takes one thread (as the
  // library does inside compute_many) instead of competing for the cores.
  GeodesicResult compute(const std::vector<Source>& sources, GeodesicOptions options) const;
  // The field of `sources` (or of the last remembered query) with per-face virtual sources,
  // computed once per query.
  std::shared_ptr<const GeodesicResult> field_with_sources(const std::vector<Source>* sources,
                                                           const GeodesicOptions* options);

 private:
  std::shared_ptr<const TriangleMesh> mesh_;   // the solver shares it (no copy without a layout); the tracer refers to it
  GeodesicSolver solver_;
  bool metric_ = false;
  bool layout_ = true;
  mutable std::atomic<int> in_flight_{0};
  mutable std::once_flag tracer_once_;
  mutable std::unique_ptr<pathfinding::PathTracer> tracer_;
  std::mutex memo_mutex_;
  bool have_last_ = false;
  std::vector<Source> last_sources_;
  GeodesicOptions last_options_;
  std::vector<Source> field_sources_;
  GeodesicOptions field_options_;
  std::shared_ptr<const GeodesicResult> field_;
};

void add_path_methods(pybind11::class_<Solver>& cls);

}  // namespace gsp::python
