#include "prefetch_corners.hpp"

#include <gsp/intrinsic/coplanar_faces.hpp>
#include <gsp/intrinsic/saddle_creases.hpp>

#include <array>
#include <cmath>

namespace gsp::intrinsic {

void apply_crease_rules(const TriangleMesh& mesh, const std::vector<double>& angle,
                        const std::vector<std::uint8_t>& interior, const std::vector<bool>& skipped_face,
                        const std::function<Index(Index)>& partner, const std::vector<Index>& lone,
                        std::vector<std::uint8_t>& kind) {
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
  // Unit normals of the faces with a flat corner, in face order: the edges then read one
  // normal across instead of three corners' positions (on a file whose vertices are not in the
  // faces' order each is a cache miss: the pass took as long as the angle sums without this).
  std::vector<std::array<float, 3>> normal(tris.size());
  for (Index f = 0; f < Index(tris.size()); ++f) {
    detail::prefetch_corners(tris, mesh.positions, f);
    if (!has_flat_corner(f)) continue;
    const Vec3 n = face_normal(tris, mesh.positions, f);
    const double length = std::sqrt(dot(n, n));
    const double k = length > 0 ? 1 / length : 0;
    normal[f] = {float(n[0] * k), float(n[1] * k), float(n[2] * k)};
  }
  // Each flat vertex's crease edges: up to two other ends, and how many (3 for more).
  static const float cos_min = float(std::cos(kCoplanarDegrees * kPi / 180));
  std::vector<std::array<Index, 2>> crease(nv);
  std::vector<std::uint8_t> count(nv, 0);
  for (Index f = 0; f < Index(tris.size()); ++f) {
    if (f + detail::kFacesAhead < tris.size()) {
      const Index g = partner(3 * (f + Index(detail::kFacesAhead)));
      __builtin_prefetch(&normal[face_of(g)]);
      __builtin_prefetch(&tris[face_of(g)]);
    }
    if (!has_flat_corner(f)) continue;
    const Triangle& t = tris[f];
    for (Index i = 0; i < 3; ++i) {
      const Index h = 3 * f + i, a = t[i], b = t[i == 2 ? 0 : i + 1];
      if (type[a] != kFlat && type[b] != kFlat) continue;
      const Index g = partner(h);
      if (g <= h) continue;   // each edge once, from its lower halfedge; a lone edge has no flat end
      const std::array<float, 3>&m = normal[f], &n = normal[face_of(g)];
      float c = m[0] * n[0] + m[1] * n[1] + m[2] * n[2];
      if (tris[face_of(g)][corner_of(g)] == a) c = -c;   // both walk the edge the same way: orientations disagree
      if (c >= cos_min) continue;                          // one plane
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
