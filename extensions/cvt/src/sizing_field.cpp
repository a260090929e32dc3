#include "sizing_field.hpp"

#include "point_grid.hpp"

#include <gsp/connectivity.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <queue>
#include <unordered_set>

namespace gsp::cvt::detail {

namespace {

std::uint64_t edge_key(Index a, Index b) {
  if (a > b) std::swap(a, b);
  return (std::uint64_t(a) << 32) | std::uint64_t(b);
}

}  // namespace

std::vector<double> curvature_sizing(const TriangleMesh& input, const std::vector<std::pair<Index, Index>>& features,
                                     double spacing, const SizingOptions& options) {
  const std::size_t nv = input.num_vertices(), nf = input.num_faces();
  std::vector<double> share(nv, 1.0);
  if (nv == 0 || !(spacing > 0)) return share;

  std::unordered_set<std::uint64_t> feature;
  feature.reserve(features.size());
  for (const auto& [a, b] : features) feature.insert(edge_key(a, b));

  std::vector<Vec3> unit(nf);
  std::vector<double> area(nf), vertex_area(nv, 0.0);
  for (std::size_t f = 0; f < nf; ++f) {
    const Triangle& t = input.triangles[f];
    const Vec3 n = cross(input.positions[t[1]] - input.positions[t[0]], input.positions[t[2]] - input.positions[t[0]]);
    const double l = norm(n);
    area[f] = 0.5 * l;
    unit[f] = l > 0 ? (1 / l) * n : Vec3{0, 0, 0};
    for (Index v : t) vertex_area[v] += area[f] / 3;
  }

  // The largest bend across a vertex's edges, and its neighbours (for the grading).
  const Connectivity c = build_connectivity(input);
  std::vector<double> bend(nv, 0.0);
  std::vector<std::vector<Index>> neighbours(nv);
  for (std::size_t e = 0; e < c.num_edges(); ++e) {
    const Index h = c.edge_halfedge[e], o = c.radial_next[h];
    const Index a = from_vertex(input, h), b = to_vertex(input, h);
    neighbours[a].push_back(b);
    neighbours[b].push_back(a);
    if (o == h || feature.count(edge_key(a, b))) continue;   // a boundary edge, or a crease
    const Index f1 = face_of(h), f2 = face_of(o);
    const double width = area[f1] + area[f2];
    if (!(width > 0)) continue;
    const double theta = std::atan2(norm(cross(unit[f1], unit[f2])), dot(unit[f1], unit[f2]));
    const double kappa = theta * distance(input.positions[a], input.positions[b]) / width;
    bend[a] = std::max(bend[a], kappa);
    bend[b] = std::max(bend[b], kappa);
  }

  // Averaged over the input within half a spacing, and turned into a share of the spacing.
  const double radius = 0.5 * spacing;
  const PointGrid grid(input.positions, radius);
  for (std::size_t v = 0; v < nv; ++v) {
    double sum = 0, weight = 0;
    grid.near(input.positions[v], radius, [&](Index w) {
      sum += vertex_area[w] * bend[w];
      weight += vertex_area[w];
    });
    const double kappa = weight > 0 ? sum / weight : bend[v];
    if (kappa > 0) share[v] = std::clamp(options.radians_per_edge / (kappa * spacing), options.min_share, 1.0);
  }

  // Graded from the smallest shares outwards (Dijkstra on the input's edges).
  using Item = std::pair<double, Index>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
  for (std::size_t v = 0; v < nv; ++v)
    if (share[v] < 1) queue.emplace(share[v], Index(v));
  while (!queue.empty()) {
    const auto [s, v] = queue.top();
    queue.pop();
    if (s != share[v]) continue;
    for (Index w : neighbours[v]) {
      const double limit = s + options.gradation * distance(input.positions[v], input.positions[w]) / spacing;
      if (limit < share[w]) {
        share[w] = limit;
        queue.emplace(limit, w);
      }
    }
  }
  return share;
}

void refine_around(const TriangleMesh& input, const std::vector<Index>& far, double spacing, double factor,
                   double gradation, double min_share, std::vector<double>& share) {
  if (share.empty()) share.assign(input.num_vertices(), 1.0);
  if (far.empty() || !(spacing > 0) || !(gradation > 0)) return;
  std::vector<double> target(far.size());   // the new share at each far vertex, from the old shares
  for (std::size_t i = 0; i < far.size(); ++i) target[i] = std::max(min_share, factor * share[far[i]]);
  const PointGrid grid(input.positions, spacing);
  for (std::size_t i = 0; i < far.size(); ++i) {
    const Vec3 p = input.positions[far[i]];
    const double reach = (1 - target[i]) / gradation * spacing;
    grid.near(p, reach, [&](Index w) {
      share[w] = std::min(share[w], target[i] + gradation * distance(p, input.positions[w]) / spacing);
    });
  }
}

}  // namespace gsp::cvt::detail
