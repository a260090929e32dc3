#include "prefetch_corners.hpp"
#include "ring_links.hpp"

#include <gsp/intrinsic/coplanar_faces.hpp>
#include <gsp/intrinsic/saddle_creases.hpp>

#include <array>
#include <cmath>

namespace gsp::intrinsic {

void apply_crease_rules(const TriangleMesh& mesh, const std::vector<double>& angle,
                        const std::vector<std::uint8_t>& interior, const std::vector<bool>& skipped_face,
                        const std::vector<Index>& links, const std::vector<std::array<float, 3>>& face_normal_of,
                        const std::vector<Index>& lone, std::vector<std::uint8_t>& kind) {
  constexpr double kPi = 3.14159265358979323846;
  const std::size_t nv = mesh.num_vertices();
  bool any_flat = !lone.empty();
  for (std::size_t v = 0; v < nv && !any_flat; ++v) any_flat = kind[v] == kFlatVertex;
  if (!any_flat) return;
  // Which interior vertices are flat or saddles.
  constexpr std::uint8_t kFlat = 1, kSaddle = 2;
  std::vector<std::uint8_t> type(nv, 0);
  for (std::size_t v = 0; v < nv; ++v) {
    if (!interior[v]) continue;
    const double excess = angle[v] - 2 * kPi;
    type[v] = std::abs(excess) <= 2 * kPi * kFlatAngleTolerance ? kFlat : excess > 0 ? kSaddle : 0;
  }
  const std::vector<Triangle>& tris = mesh.triangles;
  auto has_flat_corner = [&](Index f) {
    const Triangle& t = tris[f];
    return !skipped_face[f] && (type[t[0]] == kFlat || type[t[1]] == kFlat || type[t[2]] == kFlat);
  };
  // Unit normals of the faces with a flat corner: the caller's (the angle sums' pass computes
  // them on the way), or here. An edge reads the normal across and, from its link, whether the
  // two faces walk it the same way: one cache miss, where the face's triangle and a partner
  // reached through a function call per halfedge cost more (docs/scale.md, session 43).
  std::vector<std::array<float, 3>> own_normal;
  if (face_normal_of.size() != tris.size()) {
    own_normal.assign(tris.size(), {0, 0, 0});
    for (Index f = 0; f < Index(tris.size()); ++f) {
      detail::prefetch_corners(tris, mesh.positions, f);
      if (has_flat_corner(f)) own_normal[f] = unit_normal(face_normal(tris, mesh.positions, f));
    }
  }
  const std::vector<std::array<float, 3>>& normal = own_normal.empty() ? face_normal_of : own_normal;
  // Each flat vertex's crease edges: up to two other ends, and how many (3 for more).
  static const float cos_min = float(std::cos(kCoplanarDegrees * kPi / 180));
  std::vector<std::array<Index, 2>> crease(nv);
  std::vector<std::uint8_t> count(nv, 0);
  for (Index f = 0; f < Index(tris.size()); ++f) {
    if (f + detail::kFacesAhead < tris.size())   // the normals across the edges ahead
      for (Index i = 0; i < 3; ++i)
        __builtin_prefetch(&normal[face_of(links[3 * (f + Index(detail::kFacesAhead)) + i] & detail::kRingIndexMask)]);
    if (!has_flat_corner(f)) continue;
    const Triangle& t = tris[f];
    for (Index i = 0; i < 3; ++i) {
      const Index h = 3 * f + i, a = t[i], b = t[i == 2 ? 0 : i + 1];
      if (type[a] != kFlat && type[b] != kFlat) continue;
      const Index link = links[h], g = link & detail::kRingIndexMask;
      if (!(link & detail::kRingPair) || g <= h) continue;   // each edge of two faces once, from its lower halfedge
      const std::array<float, 3>&m = normal[f], &n = normal[face_of(g)];
      float c = m[0] * n[0] + m[1] * n[1] + m[2] * n[2];
      if (bool(link & detail::kRingNextDir) == bool(link & detail::kRingSelfDir)) c = -c;   // orientations disagree
      if (c >= cos_min) continue;                                                          // one plane
      for (const auto& [u, w] : {std::array<Index, 2>{a, b}, std::array<Index, 2>{b, a}}) {
        if (type[u] != kFlat) continue;
        if (count[u] < 2) crease[u][count[u]] = w;
        if (count[u] < 3) ++count[u];
      }
    }
  }
  // A lone flat vertex between two curved ones on its crease: convex.
  for (Index v : lone)
    if (type[v] == kFlat && count[v] == 2 && type[crease[v][0]] != kFlat && type[crease[v][1]] != kFlat)
      kind[v] = kConvexVertex;
  // Walk each crease line once, both ways from a flat vertex on it.
  std::vector<std::uint8_t> walked(nv, 0);
  std::vector<Index> line;
  auto on_line = [&](Index v) { return type[v] == kFlat && count[v] == 2; };
  for (Index v = 0; v < Index(nv); ++v) {
    if (kind[v] != kFlatVertex || !on_line(v) || walked[v]) continue;
    line.assign(1, v);
    walked[v] = 1;
    bool saddle_end = false;
    for (int way = 0; way < 2; ++way) {
      Index previous = v, at = crease[v][way];
      while (on_line(at) && !walked[at]) {
        walked[at] = 1;
        line.push_back(at);
        const Index next = crease[at][0] == previous ? crease[at][1] : crease[at][0];
        previous = at, at = next;
      }
      if (!on_line(at) && type[at] == kSaddle) saddle_end = true;
    }
    if (saddle_end)
      for (Index w : line)
        if (kind[w] == kFlatVertex) kind[w] = kPlainVertex;
  }
}

}  // namespace gsp::intrinsic
