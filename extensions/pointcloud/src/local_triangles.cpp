// Local Delaunay one-rings in tangent planes, merged into one soup with votes.
#include "local_triangles.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

namespace gsp::pointcloud::detail {
namespace {

struct P2 {
  double x, y;
};

// One-ring candidates per point at most (k = 10 gives about 10-20 in the symmetric graph).
constexpr std::size_t kMaxCandidates = 40;

double cross2(P2 a, P2 b) { return a.x * b.y - a.y * b.x; }
double sq(P2 a) { return a.x * a.x + a.y * a.y; }

// > 0 when d lies strictly inside the circle through a, b, c (counter-clockwise).
double incircle(P2 a, P2 b, P2 c, P2 d) {
  const P2 ad{a.x - d.x, a.y - d.y}, bd{b.x - d.x, b.y - d.y}, cd{c.x - d.x, c.y - d.y};
  return sq(ad) * cross2(bd, cd) - sq(bd) * cross2(ad, cd) + sq(cd) * cross2(ad, bd);
}

}  // namespace

LocalTriangles local_triangles(const std::vector<Vec3>& points, const TangentFrames& frames,
                               const std::vector<Index>& begin, const std::vector<Index>& neighbours,
                               double steep_slope) {
  const std::size_t n = points.size();
  std::vector<std::array<Index, 3>> all;
  all.reserve(6 * n);
  std::vector<P2> uv;
  std::vector<Index> id;
  for (Index i = 0; i < n; ++i) {
    uv.clear();
    id.clear();
    double scale2 = 0;
    for (Index k = begin[i]; k < begin[i + 1]; ++k) {
      const Index j = neighbours[k];
      const Vec3 d = points[j] - points[i];
      // A link that leaves either tangent plane steeply joins two sheets across a gap (the
      // graph propagation's steep links): not in the one-ring. The
      // graph's gap rule (steep at both ends at a lower slope) is not applied: it also cuts
      // links across sharp creases, and the holes it leaves cost more than it saves
      // (docs/pointcloud.md, "Local triangles").
      const double len = norm(d);
      if (std::max(std::abs(dot(d, frames.normal[i])), std::abs(dot(d, frames.normal[j]))) > steep_slope * len) continue;
      const P2 p{dot(d, frames.t1[i]), dot(d, frames.t2[i])};
      if (sq(p) <= 0) continue;   // a duplicate (merged before) or a neighbour along the normal
      uv.push_back(p);
      id.push_back(j);
      scale2 = std::max(scale2, sq(p));
    }
    // The test below is cubic in the candidates: a point many others list (a hub next to a
    // sparse region) keeps its nearest kMaxCandidates only.
    if (uv.size() > kMaxCandidates) {
      std::vector<std::size_t> order(uv.size());
      for (std::size_t a = 0; a < order.size(); ++a) order[a] = a;
      std::nth_element(order.begin(), order.begin() + kMaxCandidates, order.end(),
                       [&](std::size_t a, std::size_t b) { return sq(uv[a]) < sq(uv[b]); });
      order.resize(kMaxCandidates);
      std::vector<P2> keep_uv;
      std::vector<Index> keep_id;
      for (std::size_t a : order) keep_uv.push_back(uv[a]), keep_id.push_back(id[a]);
      uv.swap(keep_uv);
      id.swap(keep_id);
    }
    const std::size_t m = uv.size();
    const P2 o{0, 0};
    // A triangle (i, a, b) is in i's one-ring when no other neighbour lies strictly inside its
    // circumcircle (co-circular neighbours keep both diagonals: an overlap, not a hole).
    const double area_eps = 1e-9 * scale2, circle_eps = 1e-9 * scale2 * scale2;
    for (std::size_t a = 0; a < m; ++a) {
      for (std::size_t b = a + 1; b < m; ++b) {
        P2 pa = uv[a], pb = uv[b];
        Index ia = id[a], ib = id[b];
        const double area = cross2(pa, pb);
        if (std::abs(area) <= area_eps) continue;
        if (area < 0) std::swap(pa, pb), std::swap(ia, ib);
        bool empty = true;
        for (std::size_t c = 0; c < m && empty; ++c)
          if (c != a && c != b && incircle(o, pa, pb, uv[c]) > circle_eps) empty = false;
        if (!empty) continue;
        std::array<Index, 3> t{i, ia, ib};
        std::sort(t.begin(), t.end());
        all.push_back(t);
      }
    }
  }
  std::sort(all.begin(), all.end());
  LocalTriangles out;
  for (std::size_t s = 0; s < all.size();) {
    std::size_t e = s;
    while (e < all.size() && all[e] == all[s]) ++e;
    out.triangles.push_back(all[s]);
    out.votes.push_back(static_cast<std::uint8_t>(std::min<std::size_t>(e - s, 3)));
    s = e;
  }
  return out;
}

std::vector<Triangle> consistent_triangles(const LocalTriangles& local) {
  using Edge = std::pair<Index, Index>;
  auto edges = [](const Triangle& t) { return std::array<Edge, 3>{Edge{t[0], t[1]}, Edge{t[0], t[2]}, Edge{t[1], t[2]}}; };
  std::vector<Triangle> out;
  std::vector<Edge> agreed_edges;
  for (std::size_t t = 0; t < local.triangles.size(); ++t) {
    if (local.votes[t] < 2) continue;
    out.push_back(local.triangles[t]);
    for (const Edge& e : edges(local.triangles[t])) agreed_edges.push_back(e);
  }
  std::sort(agreed_edges.begin(), agreed_edges.end());
  // An edge of the agreed set is open when exactly one agreed triangle has it.
  auto open = [&](const Edge& e) {
    const auto range = std::equal_range(agreed_edges.begin(), agreed_edges.end(), e);
    return range.second - range.first == 1;
  };
  for (std::size_t t = 0; t < local.triangles.size(); ++t) {
    if (local.votes[t] != 1) continue;
    const auto es = edges(local.triangles[t]);
    if (open(es[0]) || open(es[1]) || open(es[2])) out.push_back(local.triangles[t]);
  }
  return out;
}

}  // namespace gsp::pointcloud::detail
