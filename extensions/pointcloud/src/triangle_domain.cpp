// GSP on the local triangles, the fallback over the neighbour graph, and surface points for
// position sources.
#include "triangle_domain.hpp"

#include <gsp/closest_point.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <queue>

namespace gsp::pointcloud::detail {
namespace {

Index find(std::vector<Index>& parent, Index a) {
  while (parent[a] != a) a = parent[a] = parent[parent[a]];
  return a;
}

}  // namespace

TriangleDomain::TriangleDomain(const std::vector<Vec3>& position, std::vector<Triangle> triangles) {
  mesh_.positions = position;
  mesh_.triangles = std::move(triangles);
  const std::size_t n = position.size();
  face_begin_.assign(n + 1, 0);
  for (const Triangle& t : mesh_.triangles)
    for (Index v : t) ++face_begin_[v + 1];
  for (std::size_t v = 0; v < n; ++v) face_begin_[v + 1] += face_begin_[v];
  faces_.resize(face_begin_[n]);
  std::vector<Index> fill(face_begin_.begin(), face_begin_.end() - 1);
  for (Index f = 0; f < mesh_.triangles.size(); ++f)
    for (Index v : mesh_.triangles[f]) faces_[fill[v]++] = f;

  std::vector<Index> parent(n);
  std::iota(parent.begin(), parent.end(), Index{0});
  for (const Triangle& t : mesh_.triangles) {
    parent[find(parent, t[1])] = find(parent, t[0]);
    parent[find(parent, t[2])] = find(parent, t[0]);
  }
  component_.assign(n, kInvalidIndex);
  std::vector<Index> id_of_root(n, kInvalidIndex);
  for (Index v = 0; v < n; ++v) {
    if (face_begin_[v] == face_begin_[v + 1]) {
      ++without_face_;
      continue;
    }
    Index& id = id_of_root[find(parent, v)];
    if (id == kInvalidIndex) id = static_cast<Index>(component_count_++);
    component_[v] = id;
  }
  if (!mesh_.triangles.empty()) solver_ = std::make_unique<GeodesicSolver>(mesh_);
}

bool TriangleDomain::closest_point(Vec3 x, const Index* near, std::size_t count, Source& out) const {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t a = 0; a < count; ++a) {
    const Index v = near[a];
    for (Index k = face_begin_[v]; k < face_begin_[v + 1]; ++k) {
      const Index f = faces_[k];
      const Triangle& t = mesh_.triangles[f];
      const Vec3 A = mesh_.positions[t[0]], B = mesh_.positions[t[1]], C = mesh_.positions[t[2]];
      const std::array<double, 3> w = closest_point_on_triangle(x, A, B, C);
      const double d = distance(x, w[0] * A + w[1] * B + w[2] * C);
      if (d < best) best = d, out = Source::in_face(f, w);
    }
  }
  return std::isfinite(best);
}

void TriangleDomain::run_core(const std::vector<TriangleSource>& sources, const GeodesicOptions& options,
                              PointState& state, PointPropagationStats& stats) const {
  if (!solver_ || sources.empty()) return;
  std::vector<Source> core;
  core.reserve(sources.size());
  for (const TriangleSource& s : sources) core.push_back(s.source);
  const GeodesicResult r = solver_->compute(core, options);
  for (std::size_t v = 0; v < r.vertex_distance.size(); ++v) {
    const double d = r.vertex_distance[v];
    if (!(d < state.distance[v])) continue;
    state.distance[v] = state.sigma[v] = d;
    state.sx[v] = state.sy[v] = 0;
    state.label[v] = sources[r.vertex_source[v]].label;
  }
  stats.update_steps += r.stats.update_steps;
  stats.updates += r.stats.face_updates;
  stats.enqueued += r.stats.enqueued;
  stats.stale_skipped += r.stats.stale_skipped;
  stats.iterations += r.stats.iterations;
}

void TriangleDomain::propagate(const std::vector<TriangleSource>& sources, const NeighbourGraph& graph,
                               const GeodesicOptions& options, PointState& state, PointPropagationStats& stats) const {
  const double max_distance = options.max_distance;
  // Vertex sources on points without a face: the propagation cannot start from them, the
  // fallback below does (their distance is set here).
  for (const TriangleSource& s : sources) {
    if (s.source.kind != Source::Kind::vertex) continue;
    const Index v = s.source.element;
    if (s.source.offset < state.distance[v]) {
      state.distance[v] = state.sigma[v] = s.source.offset;
      state.label[v] = s.label;
    }
  }
  run_core(sources, options, state, stats);

  // Fallback: points the triangles left unreached get Dijkstra distances over the graph's
  // links from every reached point (reached points keep theirs). A soup component entered
  // this way then gets one GSP run of its own from its nearest entry point.
  const std::size_t n = state.distance.size();
  std::vector<std::uint8_t> by_gsp(n);
  using Item = std::pair<double, Index>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> heap;
  for (Index v = 0; v < n; ++v) {
    by_gsp[v] = std::isfinite(state.distance[v]);
    if (by_gsp[v] && state.distance[v] <= max_distance) heap.push({state.distance[v], v});
  }
  std::vector<Index> entry(component_count_, kInvalidIndex);
  std::vector<std::uint8_t> component_reached(component_count_, 0);
  for (Index v = 0; v < n; ++v)
    if (by_gsp[v] && component_[v] != kInvalidIndex) component_reached[component_[v]] = 1;
  while (!heap.empty()) {
    const auto [d, p] = heap.top();
    heap.pop();
    if (d != state.distance[p]) continue;
    if (!by_gsp[p]) {
      ++stats.points_reached_over_links;
      const Index c = component_[p];
      if (c != kInvalidIndex && !component_reached[c] && (entry[c] == kInvalidIndex || d < state.distance[entry[c]]))
        entry[c] = p;
    }
    for (Index k = graph.begin[p]; k < graph.begin[p + 1]; ++k) {
      const Index q = graph.neighbour[k];
      if (by_gsp[q]) continue;
      const double cand = d + graph.length[k];
      if (cand < state.distance[q] && cand <= max_distance) {
        state.distance[q] = state.sigma[q] = cand;
        state.sx[q] = state.sy[q] = 0;
        state.label[q] = state.label[p];
        heap.push({cand, q});
      }
    }
  }
  std::vector<TriangleSource> entries;
  for (Index c = 0; c < component_count_; ++c)
    if (entry[c] != kInvalidIndex)
      entries.push_back({Source::at_vertex(entry[c], state.distance[entry[c]]), state.label[entry[c]]});
  run_core(entries, options, state, stats);
}

}  // namespace gsp::pointcloud::detail
