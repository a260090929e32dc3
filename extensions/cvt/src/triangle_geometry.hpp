#pragma once
// Small geometric helpers the remeshing passes share (internal to gsp::cvt).
#include <gsp/mesh.hpp>
#include <gsp/types.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace gsp::cvt::detail {

// The angle at p of triangle (p, q, r), in radians (atan2: accurate for needles and caps).
inline double angle_at(Vec3 p, Vec3 q, Vec3 r) { return std::atan2(norm(cross(q - p, r - p)), dot(q - p, r - p)); }

inline double min_angle(Vec3 a, Vec3 b, Vec3 c) {
  return std::min({angle_at(a, b, c), angle_at(b, c, a), angle_at(c, a, b)});
}

// Unnormalised normal of triangle (a, b, c).
inline Vec3 normal(Vec3 a, Vec3 b, Vec3 c) { return cross(b - a, c - a); }

// A directed edge as one hashable number.
inline std::uint64_t edge_key(Index a, Index b) { return (std::uint64_t(a) << 32) | b; }

// Distance from p to the segment [a, b].
inline double segment_distance(Vec3 p, Vec3 a, Vec3 b) {
  const Vec3 d = b - a;
  const double dd = dot(d, d);
  const double t = dd > 0 ? std::clamp(dot(p - a, d) / dd, 0.0, 1.0) : 0.0;
  return distance(p, a + t * d);
}

// The boundary edges: (a, b) is one when no face has (b, a) (`directed`: edge_key -> face).
// next[a] = b and prev[b] = a for each; out_count[a] = how many leave a (more than one where
// the boundary passes a vertex twice).
struct BoundaryLinks {
  std::vector<Index> next, prev;
  std::vector<int> out_count;
};
inline BoundaryLinks boundary_links(const TriangleMesh& m, const std::unordered_map<std::uint64_t, Index>& directed) {
  BoundaryLinks b{std::vector<Index>(m.num_vertices(), kInvalidIndex), std::vector<Index>(m.num_vertices(), kInvalidIndex),
                  std::vector<int>(m.num_vertices(), 0)};
  for (const Triangle& t : m.triangles)
    for (Index i = 0; i < 3; ++i) {
      const Index u = t[i], v = t[(i + 1) % 3];
      if (directed.count(edge_key(v, u))) continue;
      b.next[u] = v, b.prev[v] = u;
      ++b.out_count[u];
    }
  return b;
}

}  // namespace gsp::cvt::detail
