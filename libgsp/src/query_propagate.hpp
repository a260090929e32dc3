#pragma once
// A query's second step, shared by full and bounded queries: the wavefront's propagation (the
// chosen queue strategy, the bridge and coincident vertices' rounds) and the vertex relaxation
// along the input's edges with its pseudo-sources. Templates on the scalar type.
#include "parallel_propagation.hpp"
#include "solver_impl.hpp"
#include "vertex_relaxation.hpp"

#include <gsp/intrinsic/edge_relaxation.hpp>

#include <algorithm>

namespace gsp {

// The thread count of a full query (GeodesicOptions::threads). Automatic: every hardware
// thread on meshes of kParallelMinFaces faces or more, outside an already parallel caller
// (compute_many's pool). The threads walk one front in step (parallel_propagation.hpp), so one
// source pays as well as many (docs/performance.md).
inline unsigned query_threads(const GeodesicOptions& options, std::size_t num_faces) {
  if (options.threads > 0) return options.threads;
  if (num_faces < kParallelMinFaces || detail::inside_parallel_region()) return 1;
  // Asked once: glibc reads /sys for it, which costs more than a small bounded query.
  static const unsigned hardware = std::max(1u, std::thread::hardware_concurrency());
  return hardware;
}

template <class Real>
void GeodesicSolver::Impl::propagate(const Triangulation& tri, const GeodesicOptions& options, FaceRecord<Real>* state,
                                     std::vector<QueueEntry<Real>>& queue, detail::TargetSet<Real>* goal,
                                     PropagationStats& stats, std::vector<Index>* seeded,
                                     std::vector<Index>* reached, const float* line_sources,
                                     detail::WindowRecord<Real>* windows, bool every_update) const {
  const std::vector<double>& length = tri.length;
  const double scale = 1.0 / mean_edge;
  const Real inf = std::numeric_limits<Real>::infinity();
  const Real limit = std::isfinite(options.max_distance) ? Real(options.max_distance * scale) : inf;
  detail::StraightLineTest line;
  if (line_sources) line = {tri.triangles().data(), line_positions.data(), line_sources};
  const detail::ProbeTable<Real> probe(heuristic, tri.delaunay);
  detail::UpdateStep<Real> step(state, tri.ring.data(), probe, limit, stats, line);
  step.collect_reached(reached, every_update);
  const std::uint8_t* window_flags = tri.window_flags.empty() ? nullptr : tri.window_flags.data();
  step.carry_windows(windows, window_flags);
  const Real f = Real(options.f), f0 = Real(options.f0), f1 = Real(options.f1);
  const unsigned threads = goal || reached ? 1 : query_threads(options, mesh().num_faces());
  const bool parallel = threads > 1 && !goal && !reached &&
                        (options.strategy == Strategy::speed_limiter ||
                         options.strategy == Strategy::speed_limiter_postpone ||
                         options.strategy == Strategy::hybrid_postpone);
  auto propagate = [&] {
    using detail::Postpone;
    if (goal) return detail::run_targeted(step, queue, *goal, stats);
    if (parallel) {
      detail::run_parallel_speed_limiter(state, mesh().num_faces(), tri.ring.data(), probe,
                                         limit, queue, options.strategy == Strategy::hybrid_postpone ? f0 : f, threads,
                                         stats, options.strategy == Strategy::speed_limiter_postpone,
                                         options.strategy == Strategy::speed_limiter, line, windows, window_flags);
      return;
    }
    switch (options.strategy) {
      case Strategy::speed_limiter:
        detail::run_speed_limiter(step, queue, f, stats, false, true);
        break;
      case Strategy::speed_limiter_postpone: detail::run_speed_limiter(step, queue, f, stats, true); break;
      case Strategy::static_postpone:
      case Strategy::dynamic_postpone:
      case Strategy::hybrid_postpone:
      case Strategy::bfs: {
        const Postpone rule = options.strategy == Strategy::static_postpone    ? Postpone::fixed
                              : options.strategy == Strategy::dynamic_postpone ? Postpone::dynamic
                              : options.strategy == Strategy::hybrid_postpone  ? Postpone::hybrid
                                                                               : Postpone::none;
        detail::run_postpone(step, queue, rule, f, f0, f1, stats);
        break;
      }
      case Strategy::priority_queue: detail::run_priority_queue(step, queue, stats); break;
    }
  };
  propagate();

  // Bridges: a vertex joining fans that share no edge, and a group of coincident vertices
  // (joined by zero-length edges), pass the front on as a virtual source at that point. Each
  // round only lowers distances, so this ends; meshes without either skip it.
  auto pass_on = [&](const Index* begin, const Index* end) {
    Real best = inf;
    Index label = kInvalidIndex;
    for (const Index* v = begin; v != end; ++v)
      for (Index k = tri.corner_begin[*v]; k < tri.corner_begin[*v + 1]; ++k) {
        const Index c = tri.corners[k];
        const FaceRecord<Real>& st = state[face_of(c)];
        if (!st.reached()) continue;
        const Real d = corner_distance(st, corner_of(c));
        if (d < best) best = d, label = st.source();
      }
    if (!(best <= limit)) return false;
    bool changed = false;
    for (const Index* v = begin; v != end; ++v)
      for (Index k = tri.corner_begin[*v]; k < tri.corner_begin[*v + 1]; ++k) {
        const Index c = tri.corners[k];
        const Index fc = face_of(c);
        if (skipped_face[fc]) continue;
        const FaceRecord<Real> before = state[fc];
        if (seed_face(length, fc, kCornerWeights[corner_of(c)], scale, double(best), label, state) &&
            state[fc].dT + state[fc].dT * std::numeric_limits<Real>::epsilon() * 4 < before.dT) {
          queue.push_back({next_halfedge(c), state[fc].dT});
          if (seeded) seeded->push_back(fc);
          changed = true;
        } else {
          state[fc] = before;
        }
      }
    return changed;
  };
  for (bool changed = !bridge_vertices.empty() || !coincident.empty(); changed;) {
    changed = false;
    for (const Index& v : bridge_vertices) changed |= pass_on(&v, &v + 1);
    for (std::size_t g = 0; g + 1 < coincident_begin.size(); ++g)
      changed |= pass_on(coincident.data() + coincident_begin[g], coincident.data() + coincident_begin[g + 1]);
    if (changed) propagate();
  }

}

// Rounds that seed pseudo-sources; the corpus needs at most 2 (docs/gsp-core.md). Past it the
// values are still relaxed (so never above an edge path), only not propagated from.
// (gsp/intrinsic/edge_relaxation.hpp holds both values, shared with the extensions.)
inline constexpr int kMaxRelaxationRounds = intrinsic::kMaxRelaxationRounds;
// A vertex lowered by less than this (relative) keeps its lower value but seeds nothing. An edge
// along the front lowers many vertices by GSP's own error (d(u) + |uv| beats d(v) by a hair
// where uv runs with the geodesic), and seeding all of them costs far more than it gains.
// Lowered by more than this, the face sources round the vertex failed it (CAD parts, poles,
// soups): there a new round pays (docs/gsp-core.md, "Vertices as pseudo-sources").
inline constexpr double kPseudoSourceGain = intrinsic::kPseudoSourceGain;

template <class Real, class Value>
void GeodesicSolver::Impl::seed_pseudo_sources(const Triangulation& tri, const std::vector<Index>& vertices,
                                               const std::vector<Value>& d, double to_normalised,
                                               const std::vector<Index>& label, FaceRecord<Real>* state,
                                               std::vector<QueueEntry<Real>>& queue, std::vector<Index>& changed,
                                               std::vector<Index>* touched) const {
  const double scale = 1.0 / mean_edge;
  queue.clear();
  changed.clear();
  for (Index v : vertices)
    for (Index k = tri.corner_begin[v]; k < tri.corner_begin[v + 1]; ++k) {
      const Index c = tri.corners[k];
      const Index f = face_of(c);
      if (skipped_face[f]) continue;
      if (touched) touched->push_back(f);
      if (seed_face(tri.length, f, kCornerWeights[corner_of(c)], scale, double(d[v]) * to_normalised, label[v],
                    state)) {
        queue.push_back({next_halfedge(c), state[f].dT});
        changed.push_back(f);
      }
    }
}

template <class Real>
void GeodesicSolver::Impl::relax_vertices(const Triangulation& tri, const GeodesicOptions& options,
                                          FaceRecord<Real>* state, std::vector<QueueEntry<Real>>& queue,
                                          std::vector<Real>& vmin, std::vector<Index>& vlabel,
                                          PropagationStats& stats, const float* line_sources,
                                          detail::WindowRecord<Real>* windows, unsigned threads) const {
  const double scale = 1.0 / mean_edge;
  const Real limit = std::isfinite(options.max_distance) ? Real(options.max_distance * scale)
                                                         : std::numeric_limits<Real>::infinity();
  std::vector<Index> changed_faces, changed_vertices;
  const std::vector<Index>* from = nullptr;   // the first round looks at every edge
  for (int round = 0;; ++round) {
    std::size_t relaxed = 0;
    const std::vector<Index> lowered = detail::relax_along_edges<Real>(
        input.triangles(), input.length, scale, skipped_face, input.corner_begin, input.corners, from, limit,
        Real(kPseudoSourceGain), vmin, vlabel, relaxed, nullptr, threads);
    stats.relaxed_vertices += relaxed;
    if (lowered.empty() || round >= kMaxRelaxationRounds) return;
    ++stats.relaxation_rounds;
    stats.pseudo_sources += lowered.size();
    seed_pseudo_sources(tri, lowered, vmin, 1.0, vlabel, state, queue, changed_faces, nullptr);
    if (queue.empty()) return;
    propagate<Real>(tri, options, state, queue, nullptr, stats, nullptr, &changed_faces, line_sources, windows,
                    /*every_update=*/true);
    // The changed faces' corners, and the vertices they lower: where the next round starts.
    changed_vertices.clear();
    for (Index f : changed_faces)
      for (Index i = 0; i < 3; ++i) {
        const Index v = tri.triangles()[f][i];
        const Real d = corner_distance(state[f], i);
        if (d < vmin[v] && corner_sees_source(state[f], i))   // corner_values.hpp
          vmin[v] = d, vlabel[v] = state[f].source(), changed_vertices.push_back(v);
      }
    from = &changed_vertices;
  }
}

}  // namespace gsp
