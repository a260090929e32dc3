#include <gsp/connectivity.hpp>
#include <gsp/dijkstra.hpp>
#include <gsp/errors.hpp>

#include <algorithm>
#include <cmath>
#include <queue>
#include <string>
#include <utility>

namespace gsp {

DijkstraSolver::DijkstraSolver(const TriangleMesh& mesh) : mesh_(mesh) {
  validate(mesh);
  const Connectivity conn = build_connectivity(mesh);
  const std::size_t nv = mesh.num_vertices();
  begin_.assign(nv + 1, 0);
  for (Index e = 0; e < conn.num_edges(); ++e) {
    const Index h = conn.edge_halfedge[e];
    ++begin_[from_vertex(mesh, h) + 1];
    ++begin_[to_vertex(mesh, h) + 1];
  }
  for (std::size_t v = 0; v < nv; ++v) begin_[v + 1] += begin_[v];
  neighbour_.resize(begin_[nv]);
  length_.resize(begin_[nv]);
  std::vector<Index> fill(begin_.begin(), begin_.end() - 1);
  for (Index e = 0; e < conn.num_edges(); ++e) {
    const Index h = conn.edge_halfedge[e];
    const Index a = from_vertex(mesh, h), b = to_vertex(mesh, h);
    const double l = distance(mesh.positions[a], mesh.positions[b]);
    neighbour_[fill[a]] = b, length_[fill[a]++] = l;
    neighbour_[fill[b]] = a, length_[fill[b]++] = l;
  }
}

GeodesicResult DijkstraSolver::compute(const std::vector<Source>& sources, double max_distance) const {
  const std::size_t nv = num_vertices();
  GeodesicResult r;
  r.vertex_distance.assign(nv, std::numeric_limits<double>::infinity());
  r.vertex_source.assign(nv, kInvalidIndex);
  using Item = std::pair<double, Index>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> heap;
  auto relax = [&](Index v, double d, Index label) {
    if (d < r.vertex_distance[v] && d <= max_distance) {
      r.vertex_distance[v] = d;
      r.vertex_source[v] = label;
      heap.emplace(d, v);
    }
  };
  for (std::size_t s = 0; s < sources.size(); ++s) {
    const Source& src = sources[s];
    const Index label = static_cast<Index>(s);
    // This baseline's messages leave out the counts GSP's give.
    if (!src.exists_in(mesh_))
      throw InvalidInput("source " + std::string(src.is_vertex() ? "vertex " : "face ") + std::to_string(src.element) +
                         " does not exist");
    if (src.is_vertex()) {
      relax(src.element, src.offset, label);
    } else {
      const Vec3 p = src.position(mesh_);
      for (Index v : mesh_.triangles[src.element]) relax(v, src.offset + distance(p, mesh_.positions[v]), label);
    }
  }
  while (!heap.empty()) {
    const auto [d, v] = heap.top();
    heap.pop();
    ++r.stats.iterations;
    if (d > r.vertex_distance[v]) continue;   // stale
    for (Index k = begin_[v]; k < begin_[v + 1]; ++k) {
      ++r.stats.update_steps;
      relax(neighbour_[k], d + length_[k], r.vertex_source[v]);
    }
  }
  return r;
}

GeodesicResult dijkstra_distances(const TriangleMesh& mesh, const std::vector<Source>& sources,
                                  double max_distance) {
  return DijkstraSolver(mesh).compute(sources, max_distance);
}

}  // namespace gsp
