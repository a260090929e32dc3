#include "feature_sites.hpp"

#include <gsp/cvt/features.hpp>
#include <gsp/intrinsic/vertex_kinds.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>
#include <utility>

namespace gsp::cvt::detail {

namespace {

// The chain positions nearest to `steps` even arc-length steps (both ends for an open chain),
// without repeats.
std::vector<std::size_t> even_samples(const std::vector<double>& arc, std::size_t steps, bool closed) {
  std::vector<std::size_t> picked;
  const double length = arc.back();
  std::size_t i = 0;
  const std::size_t last = closed ? steps - 1 : steps;
  for (std::size_t j = 0; j <= last; ++j) {
    const double target = length * double(j) / double(steps);
    while (i + 1 < arc.size() && std::abs(arc[i + 1] - target) <= std::abs(arc[i] - target)) ++i;
    if (picked.empty() || picked.back() != i) picked.push_back(i);
  }
  if (closed && picked.size() > 1 && picked.back() == arc.size() - 1) picked.pop_back();   // the start again
  return picked;
}

bool is_boundary_edge(const WorkingGeometry& g, Index a, Index b) {
  for (Index i = g.conn.vertex_corner_begin[a]; i < g.conn.vertex_corner_begin[a + 1]; ++i) {
    const Index f = face_of(g.conn.vertex_corners[i]);
    for (Index h = 3 * f; h < 3 * f + 3; ++h)
      if (g.boundary_halfedge[h] && std::minmax(from_vertex(g.mesh, h), to_vertex(g.mesh, h)) == std::minmax(a, b))
        return true;
  }
  return false;
}

// Dijkstra along the mesh edges from the vertices with an owner: every vertex reached takes the
// owner of its nearest seed and the distance to it. Stops at `radius`, and at vertices where
// `within` (when given) is infinite.
void flood(const WorkingGeometry& g, std::vector<Index>& owner, std::vector<double>& dist, double radius,
           const std::vector<double>* within) {
  const TriangleMesh& m = g.mesh;
  dist.assign(m.num_vertices(), std::numeric_limits<double>::infinity());
  using Entry = std::pair<double, Index>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;
  for (Index v = 0; v < m.num_vertices(); ++v)
    if (owner[v] != kInvalidIndex) dist[v] = 0, queue.push({0.0, v});
  while (!queue.empty()) {
    const auto [d, v] = queue.top();
    queue.pop();
    if (d > dist[v]) continue;
    for (Index i = g.conn.vertex_corner_begin[v]; i < g.conn.vertex_corner_begin[v + 1]; ++i) {
      const Index face = face_of(g.conn.vertex_corners[i]);
      for (Index w : m.triangles[face]) {
        const double dw = d + distance(m.positions[v], m.positions[w]);
        if (w == v || dw > radius || dw >= dist[w] || (within && !std::isfinite((*within)[w]))) continue;
        dist[w] = dw;
        owner[w] = owner[v];
        queue.push({dw, w});
      }
    }
  }
}

// The band: the vertices within `radius` of a curve; then each of them belongs to the sample
// nearest it through the band (a Voronoi diagram of the samples on the band's vertices, so every
// sample's part is connected and two samples' parts meet along one border, as in the plane).
// Each face with a corner in the band goes to the sample, of its corners' ones, nearest its
// centroid. Once per run: the band does not depend on the free sites.
void grow_band(const WorkingGeometry& g, double radius, std::vector<Index> on_curve, FeatureSites& f) {
  std::vector<double> to_curve;
  flood(g, on_curve, to_curve, radius, nullptr);
  std::vector<Index> owner(g.mesh.num_vertices(), kInvalidIndex);
  for (Index s = 0; s < f.sites.size(); ++s) owner[f.site_vertex[s]] = s;
  std::vector<double> to_sample;
  flood(g, owner, to_sample, std::numeric_limits<double>::infinity(), &to_curve);
  for (Index face = 0; face < g.mesh.num_faces(); ++face) {
    Index best_owner = kInvalidIndex;
    double best = std::numeric_limits<double>::infinity();
    for (Index v : g.mesh.triangles[face]) {
      const Index o = owner[v];
      if (o == kInvalidIndex || o == best_owner) continue;
      const double d = distance(f.sites[o].position, g.centroid[face]);
      if (d < best) best = d, best_owner = o;
    }
    if (best_owner != kInvalidIndex) f.band_faces.push_back({face, best_owner});
  }
}

// A fixed site at working vertex v, appended to f (its index is f.sites.size() before).
void add_fixed_site(const WorkingGeometry& g, Index v, FeatureSites& f) {
  const Index corner = g.conn.vertex_corners[g.conn.vertex_corner_begin[v]];
  std::array<double, 3> bary{0, 0, 0};
  bary[corner_of(corner)] = 1;
  SurfaceSite s = g.at(face_of(corner), bary);
  s.fixed = true;
  f.sites.push_back(s);
  f.site_vertex.push_back(v);
}

}  // namespace

std::size_t add_cone_sites(const WorkingGeometry& g, double max_angle_deg, double spacing, std::size_t cap,
                           FeatureSites& f) {
  const TriangleMesh& m = g.mesh;
  const intrinsic::CornerAngleSums sums = intrinsic::corner_angle_sums(m, std::vector<bool>(m.num_faces(), false));
  // Boundary vertices are left to the boundary sites (a jagged scan boundary turns at every
  // other vertex), and fixed sites already placed are not placed again.
  std::vector<bool> excluded(m.num_vertices(), false);
  for (Index h = 0; h < Index(g.boundary_halfedge.size()); ++h)
    if (g.boundary_halfedge[h]) excluded[from_vertex(m, h)] = excluded[to_vertex(m, h)] = true;
  for (Index v : f.site_vertex) excluded[v] = true;
  const double bound = max_angle_deg * M_PI / 180;
  std::vector<Index> candidates;
  for (Index v = 0; v < m.num_vertices(); ++v)
    if (sums.used[v] && !excluded[v] && sums.angle[v] < bound && sums.angle[v] >= 0.5 * bound &&
        g.conn.vertex_corner_begin[v + 1] > g.conn.vertex_corner_begin[v])
      candidates.push_back(v);
  std::stable_sort(candidates.begin(), candidates.end(), [&](Index a, Index b) { return sums.angle[a] < sums.angle[b]; });
  std::vector<Vec3> taken;
  for (Index v : f.site_vertex) taken.push_back(m.positions[v]);
  std::size_t added = 0;
  for (Index v : candidates) {
    if (added >= cap) break;
    const Vec3 p = m.positions[v];
    if (std::any_of(taken.begin(), taken.end(), [&](const Vec3& q) { return distance(p, q) < spacing; })) continue;
    add_fixed_site(g, v, f);
    taken.push_back(p);
    ++added;
  }
  return added;
}

FeatureSites feature_sites(const WorkingGeometry& g, double angle_deg, double spacing, double band_width) {
  FeatureSites out;
  const TriangleMesh& m = g.mesh;
  std::vector<Index> on_curve(m.num_vertices(), kInvalidIndex);   // 0: the band grows from here
  FeatureOptions fo;
  fo.angle = angle_deg;
  const Features features = detect_features(m, fo);
  std::vector<Index> site_at(m.num_vertices(), kInvalidIndex);
  auto site_of = [&](Index v) {
    if (site_at[v] == kInvalidIndex) {
      site_at[v] = Index(out.sites.size());
      add_fixed_site(g, v, out);
    }
    return site_at[v];
  };
  for (const std::vector<Index>& chain : features.curves) {
    std::vector<double> arc(chain.size(), 0.0);
    for (std::size_t i = 1; i < chain.size(); ++i)
      arc[i] = arc[i - 1] + distance(m.positions[chain[i - 1]], m.positions[chain[i]]);
    const bool closed = chain.size() > 2 && chain.front() == chain.back();
    const bool on_boundary = is_boundary_edge(g, chain[0], chain[1]);
    if (!(arc.back() >= spacing)) {
      if (!on_boundary) ++out.dropped_curves;
      continue;
    }
    if (on_boundary) {
      // Boundary sites already follow the boundary; what they cut is its corners.
      if (!closed)
        for (Index v : {chain.front(), chain.back()}) site_of(v), on_curve[v] = 0;
      continue;
    }
    ++out.curves;
    const std::size_t steps =
        std::max<std::size_t>(closed ? 3 : 1, std::size_t(std::llround(arc.back() / spacing)));
    const std::vector<std::size_t> picked = even_samples(arc, steps, closed);
    for (std::size_t i : picked) site_of(chain[i]);
    for (Index v : chain) on_curve[v] = 0;
  }
  grow_band(g, band_width * spacing, on_curve, out);
  return out;
}

std::size_t claim_feature_band(const FeatureSites& f, std::vector<Index>& label) {
  std::size_t changed = 0;
  for (const auto& [face, owner] : f.band_faces)
    if (label[face] != owner) label[face] = owner, ++changed;
  return changed;
}

}  // namespace gsp::cvt::detail
