// Bounded queries (GeodesicSolver::compute_local): the propagation of compute() on a state that
// persists in a workspace and is put back only where the query touched it. The faces touched
// are the seeded ones and those the update step reached for the first time (it lists them),
// so nothing scans the whole mesh.
#include "query_gather.hpp"
#include "query_propagate.hpp"
#include "query_seed.hpp"
#include "solver_impl.hpp"
#include "source_edges.hpp"
#include "straight_line_bound.hpp"
#include "validate_options.hpp"
#include "validate_sources.hpp"
#include "vertex_relaxation.hpp"
#include "virtual_source.hpp"

#include <gsp/errors.hpp>

namespace gsp {

template <class Real>
struct LocalBuffers {
  detail::RecordArray<Real> state;   // pristine outside the last query's faces
  std::vector<QueueEntry<Real>> queue;
  detail::WindowStore<Real> windows;   // carried windows: none written outside the last query's faces either
};

struct LocalWorkspace::State {
  const void* owner = nullptr;   // the solver's Impl the buffers were made for
  LocalBuffers<float> single;
  LocalBuffers<double> twice;
  std::vector<double> vdist;     // +inf outside the last query's vertices
  std::vector<Index> vlabel;
  std::vector<std::uint8_t> face_mark;
  std::vector<Index> faces, vertices, seeded;
  std::vector<VertexSeed> vertex_seeds;
};

LocalWorkspace::LocalWorkspace() : state_(std::make_unique<State>()) {}
LocalWorkspace::~LocalWorkspace() = default;
LocalWorkspace::LocalWorkspace(LocalWorkspace&&) noexcept = default;
LocalWorkspace& LocalWorkspace::operator=(LocalWorkspace&&) noexcept = default;

LocalWorkspace GeodesicSolver::make_workspace() const {
  LocalWorkspace w;
  LocalWorkspace::State& s = *w.state_;
  s.owner = impl_.get();
  s.vdist.assign(impl_->mesh().num_vertices(), std::numeric_limits<double>::infinity());
  s.vlabel.assign(impl_->mesh().num_vertices(), kInvalidIndex);
  s.face_mark.assign(impl_->mesh().num_faces(), 0);
  return w;
}

LocalField GeodesicSolver::compute_local(const std::vector<Source>& sources, const GeodesicOptions& options,
                                         LocalWorkspace& workspace) const {
  if (!workspace.state_ || workspace.state_->owner != impl_.get())
    throw InvalidInput("compute_local: the workspace was made by another solver (use make_workspace())");
  detail::validate_options(options, detail::QueryKind::local, impl_->custom_lengths, impl_->mesh().num_vertices());
  detail::validate_sources(sources, impl_->mesh());
  if (resolved_precision(options.precision, /*input_faces=*/true) == Precision::single)
    return impl_->run_local<float>(sources, options, workspace);
  return impl_->run_local<double>(sources, options, workspace);
}

template <class Real>
void GeodesicSolver::Impl::relax_local(const GeodesicOptions& options, FaceRecord<Real>* state,
                                       std::vector<QueueEntry<Real>>& queue, LocalValues values,
                                       PropagationStats& stats, const float* line_sources,
                                       detail::WindowRecord<Real>* windows) const {
  const double scale = 1.0 / mean_edge;
  std::vector<Index> changed_faces, from = values.vertices;
  for (int round = 0;; ++round) {
    std::size_t relaxed = 0;
    const std::vector<Index> lowered = detail::relax_along_edges<double>(
        input.triangles(), input.length, 1.0, skipped_face, input.corner_begin, input.corners, &from,
        options.max_distance, kPseudoSourceGain, values.vdist, values.vlabel, relaxed, &values.vertices);
    stats.relaxed_vertices += relaxed;
    if (lowered.empty() || round >= kMaxRelaxationRounds) return;
    ++stats.relaxation_rounds;
    stats.pseudo_sources += lowered.size();
    // Every face offered a seed is reset after the query, whether or not it took it.
    seed_pseudo_sources(input, lowered, values.vdist, scale, values.vlabel, state, queue, changed_faces, &values.seeded);
    if (queue.empty()) return;
    propagate<Real>(input, options, state, queue, nullptr, stats, nullptr, &changed_faces, line_sources, windows,
                    /*every_update=*/true);
    from.clear();
    for (Index f : changed_faces) {
      if (!values.face_mark[f]) values.face_mark[f] = 1, values.faces.push_back(f);
      for (Index i = 0; i < 3; ++i) {
        const Index v = input.triangles()[f][i];
        const double d = double(corner_distance(state[f], i)) * mean_edge;
        if (!(d < values.vdist[v]) || !corner_sees_source(state[f], i)) continue;   // corner_values.hpp
        if (values.vdist[v] == std::numeric_limits<double>::infinity()) values.vertices.push_back(v);
        values.vdist[v] = d, values.vlabel[v] = state[f].source(), from.push_back(v);
      }
    }
  }
}

template <class Real>
LocalField GeodesicSolver::Impl::run_local(const std::vector<Source>& sources, const GeodesicOptions& options,
                                           LocalWorkspace& workspace) const {
  LocalWorkspace::State& ws = *workspace.state_;
  LocalBuffers<Real>& buf = [&]() -> LocalBuffers<Real>& {
    if constexpr (std::is_same_v<Real, float>) return ws.single;
    else return ws.twice;
  }();
  const Triangulation& tri = input;
  const double scale = 1.0 / mean_edge;
  if (buf.state.empty()) buf.state = tri.initial_records<Real>(scale, vertex_kind);   // first query of this precision

  LocalField result;
  result.stats.mean_edge_length = mean_edge;
  result.stats.double_precision = std::is_same_v<Real, double>;
  ws.seeded.clear();
  ws.vertex_seeds.clear();
  buf.queue.clear();
  // Whatever happens below, the workspace is put back for the next query.
  struct Restore {
    LocalWorkspace::State& ws;
    LocalBuffers<Real>& buf;
    // Only the source fields change in a query (lengths and corner bits stay): writing
    // their initial values back needs no read of the pristine records (cold in cache).
    void reset(Index f) {
      FaceRecord<Real>& r = buf.state[f];
      r.sx = r.sy = 0;
      r.sigma = r.dT = std::numeric_limits<Real>::infinity();
      r.tag = (r.tag & ~detail::kSourceMask) | detail::kNoSource;
      ws.face_mark[f] = 0;
      if (buf.windows) buf.windows.get()[f].written = false;
    }
    ~Restore() {
      for (Index f : ws.faces) reset(f);
      for (Index f : ws.seeded) reset(f);
      for (Index v : ws.vertices) ws.vdist[v] = std::numeric_limits<double>::infinity(), ws.vlabel[v] = kInvalidIndex;
      ws.faces.clear(), ws.vertices.clear(), ws.seeded.clear();
    }
  } restore{ws, buf};

  seed<Real>(tri, sources, buf.state.data(), buf.queue, ws.vertex_seeds, nullptr, &ws.seeded);
  result.stats.enqueued = buf.queue.size();
  const std::vector<detail::SourcePoint> points = source_points_for(sources, options);
  const std::vector<float> line_sources = line_sources_for(points, options);
  const float* lines = line_sources.empty() ? nullptr : line_sources.data();
  detail::WindowRecord<Real>* windows = nullptr;
  if (window_corner_count > 0 && options.carried_windows) {
    if (!buf.windows) buf.windows = window_records<Real>(options);   // first such query
    windows = buf.windows.get();
  }
  propagate<Real>(tri, options, buf.state.data(), buf.queue, nullptr, result.stats, &ws.seeded, &ws.faces, lines,
                  windows);

  const LocalValues values{ws.vdist, ws.vlabel, ws.vertices, ws.faces, ws.face_mark, ws.seeded};
  gather_reached<Real>(buf.state.data(), ws.vertex_seeds, values);
  if (options.vertex_relaxation) relax_local<Real>(options, buf.state.data(), buf.queue, values, result.stats, lines, windows);
  result.stats.faces_reached = ws.faces.size();
  if (options.straight_line_bound && line_scale > 0) {
    result.stats.raised_to_line = detail::raise_to_straight_line<Real>(
        ws.vertices.size(), ws.vertices.data(), line_bound_positions(), ws.vdist.data(), ws.vlabel.data(), mean_edge,
        false, points);
    // A vertex source's own value is exact and wins, as in compute().
    for (const VertexSeed& vs : ws.vertex_seeds) values.touch(vs.vertex, vs.value, vs.label);
  }
  // The source's edges in double, as in compute() (source_edges.hpp).
  if (options.vertex_relaxation)
    for (const VertexSeed& e : detail::source_edge_values(input, skipped_face, ws.vertex_seeds)) {
      double& d = values.vdist[e.vertex];
      if (!(e.value <= options.max_distance) || !detail::settles_to_edge<Real>(d, e.value)) continue;
      if (d == std::numeric_limits<double>::infinity()) values.vertices.push_back(e.vertex);
      d = e.value;
      values.vlabel[e.vertex] = e.label;
    }

  gather_local<Real>(buf.state.data(), values, options, result);
  return result;
}

}  // namespace gsp
