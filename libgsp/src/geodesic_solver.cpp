// GeodesicSolver's queries: compute() validates at the API boundary, picks the triangulation
// and the precision, then run() seeds (query_seed.hpp), propagates (query_propagate.hpp) and
// gathers (query_gather.hpp). The constructor's preparation is in solver_build.cpp, bounded
// queries in local_query.cpp.
#include "query_gather.hpp"
#include "query_propagate.hpp"
#include "query_seed.hpp"
#include "solver_impl.hpp"
#include "straight_line_bound.hpp"
#include "validate_options.hpp"
#include "validate_sources.hpp"

#include <gsp/errors.hpp>
#include <gsp/geodesics.hpp>

#include <algorithm>
#include <optional>
#include <vector>

namespace gsp {

GeodesicSolver::~GeodesicSolver() = default;
GeodesicSolver::GeodesicSolver(GeodesicSolver&&) noexcept = default;
GeodesicSolver& GeodesicSolver::operator=(GeodesicSolver&&) noexcept = default;

std::size_t GeodesicSolver::num_vertices() const { return impl_->mesh().num_vertices(); }
std::size_t GeodesicSolver::num_faces() const { return impl_->mesh().num_faces(); }
Index GeodesicSolver::face_memory_rank(Index face) const { return impl_->maps.face_to_layout(face); }
const SolverTimings& GeodesicSolver::timings() const { return impl_->timings; }
std::size_t GeodesicSolver::intrinsic_flips() const { return impl_->flips; }
std::size_t GeodesicSolver::window_corners() const { return impl_->window_corner_count; }
std::size_t GeodesicSolver::duplicate_faces() const { return impl_->duplicate_faces; }
bool GeodesicSolver::face_takes_part(Index face) const {
  return face < impl_->mesh().num_faces() && !impl_->skipped_face[impl_->maps.face_to_layout(face)];
}

bool GeodesicSolver::needs_double() const {
  return (impl_->delaunay ? *impl_->delaunay : impl_->input).needs_double;
}

Precision GeodesicSolver::resolved_precision(Precision requested, bool input_faces) const {
  return impl_->precision_on(input_faces || !impl_->delaunay ? impl_->input : *impl_->delaunay, requested);
}

std::size_t GeodesicSolver::state_bytes(Precision precision) const {
  // Per face one record (source, distances, edge lengths); per halfedge one radial link.
  const std::size_t nf = impl_->mesh().num_faces();
  const std::size_t record =
      resolved_precision(precision) == Precision::single ? sizeof(FaceRecord<float>) : sizeof(FaceRecord<double>);
  return nf * record + impl_->input.ring.size() * sizeof(Index);
}

GeodesicResult GeodesicSolver::compute(const std::vector<Source>& sources,
                                       const GeodesicOptions& options) const {
  detail::validate_options(options, detail::QueryKind::full, impl_->custom_lengths, impl_->mesh().num_vertices());
  detail::validate_sources(sources, impl_->mesh());
  // On the intrinsic Delaunay faces when there are any; a point given in an input face is
  // found on them (query_seed.hpp). The per-face virtual sources are the input faces' own run,
  // or fitted from the flipped faces' to the vertex values (GeodesicOptions::
  // fitted_face_sources, fitted_face_sources.hpp); not for a targeted run, which stops before
  // most vertices are final.
  const bool fit_sources = options.want_face_sources && options.fitted_face_sources && options.targets.empty();
  const bool use_delaunay = impl_->delaunay && (fit_sources || !options.want_face_sources);
  const Triangulation& tri = use_delaunay ? *impl_->delaunay : impl_->input;
  if (impl_->precision_on(tri, options.precision) == Precision::single) return impl_->run<float>(tri, sources, options);
  return impl_->run<double>(tri, sources, options);
}

template <class Real>
GeodesicResult GeodesicSolver::Impl::run(const Triangulation& tri, const std::vector<Source>& sources,
                                         const GeodesicOptions& options) const {
  const std::size_t nf = mesh().num_faces(), nv = mesh().num_vertices();
  const double scale = 1.0 / mean_edge;
  // Targeted runs stop early on one thread; the others run every pass on `threads`.
  const unsigned threads = options.targets.empty() ? query_threads(options, nf) : 1;
  detail::RecordArray<Real> state = take_state<Real>(tri, threads);   // this query's copy

  GeodesicResult result;
  result.stats.mean_edge_length = mean_edge;
  result.stats.double_precision = std::is_same_v<Real, double>;
  std::vector<QueueEntry<Real>> queue;
  queue.reserve(std::max<std::size_t>(64, nf / 4));
  std::optional<detail::TargetSet<Real>> goal;   // only for runs with targets
  if (!options.targets.empty()) {
    std::vector<Index> targets(options.targets.size());
    for (std::size_t i = 0; i < targets.size(); ++i) targets[i] = maps.vertex_to_layout(options.targets[i]);
    goal.emplace(state.data(), tri.triangles(), mesh().positions, tri.corner_begin, tri.corners, targets, scale,
                 options.goal_directed);
  }

  std::vector<VertexSeed> vertex_seeds;
  seed<Real>(tri, sources, state.data(), queue, vertex_seeds, goal ? &*goal : nullptr, nullptr);
  result.stats.enqueued = queue.size();
  const std::vector<detail::SourcePoint> points = source_points_for(sources, options);
  const std::vector<float> line_sources = line_sources_for(points, options);
  const float* lines = line_sources.empty() ? nullptr : line_sources.data();
  const detail::WindowStore<Real> window_store = window_records<Real>(options);
  detail::WindowRecord<Real>* windows = window_store.get();
  propagate<Real>(tri, options, state.data(), queue, goal ? &*goal : nullptr, result.stats, nullptr, nullptr, lines,
                  windows);

  std::vector<Real> vmin;
  std::vector<Index> vlabel;
  result.stats.faces_reached = vertex_minima<Real>(tri, state.data(), vmin, vlabel, threads);
  // A targeted run stops once its targets are final: a resumed propagation would not.
  const bool relax = !goal && options.vertex_relaxation;
  if (relax) {
    // The vertex sources are where the edge paths start.
    for (const VertexSeed& vs : vertex_seeds)
      if (Real(vs.value * scale) < vmin[vs.vertex])
        vmin[vs.vertex] = Real(vs.value * scale), vlabel[vs.vertex] = vs.label;
    relax_vertices<Real>(tri, options, state.data(), queue, vmin, vlabel, result.stats, lines, windows, threads);
  }
  // Last on the values: nothing below the straight line (straight_line_bound.hpp), in layout
  // order (positions and values read in sequence).
  if (options.straight_line_bound && line_scale > 0)
    result.stats.raised_to_line = detail::raise_to_straight_line<Real>(
        nv, nullptr, line_bound_positions(), vmin.data(), vlabel.data(), mean_edge, true, points, threads);
  gather<Real>(tri, state.data(), vertex_seeds, relax, options, vmin, vlabel, result, threads, &points);
  return_state(std::move(state));
  return result;
}

std::vector<detail::SourcePoint> GeodesicSolver::Impl::source_points_for(const std::vector<Source>& sources,
                                                                         const GeodesicOptions& options) const {
  if (!(line_scale > 0) || !(options.straight_line_bound || options.straight_line_test)) return {};
  std::vector<detail::SourcePoint> points = detail::source_points(mesh(), maps, sources);
  if (line_scale != 1)
    for (detail::SourcePoint& p : points) p.position = line_scale * p.position;   // as line_bound_positions()
  return points;
}

std::vector<float> GeodesicSolver::Impl::line_sources_for(const std::vector<detail::SourcePoint>& points,
                                                          const GeodesicOptions& options) const {
  if (!options.straight_line_test || line_positions.empty()) return {};
  return detail::scaled_sources(points, 1.0 / mean_edge, line_centre);
}

GeodesicResult geodesic_distances(const TriangleMesh& mesh, const std::vector<Source>& sources,
                                  const GeodesicOptions& options, const SolverOptions& solver_options) {
  return GeodesicSolver(mesh, solver_options).compute(sources, options);
}

}  // namespace gsp
