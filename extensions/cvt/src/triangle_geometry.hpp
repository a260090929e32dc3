#pragma once
// Small geometric helpers the remeshing passes share (internal to gsp::cvt).
#include <gsp/closest_point.hpp>
#include <gsp/mesh.hpp>
#include <gsp/types.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace gsp::cvt::detail {

// The angle at p of triangle (p, q, r), in radians (atan2: accurate for needles and caps).
inline double angle_at(Vec3 p, Vec3 q, Vec3 r) { return std::atan2(norm(cross(q - p, r - p)), dot(q - p, r - p)); }

// The smallest angle lies opposite the shortest edge, so one atan2 is enough (the post-pass
// asks this for every candidate point of every move: three were a tenth of its time). Where
// another edge is within 1e-6 of the shortest, its angle is measured too, so the result is
// the smallest of the three as computed one by one (but for caps whose two small angles are
// below about 1e-9 radians, where atan2's own rounding is larger than their difference).
inline double min_angle(Vec3 a, Vec3 b, Vec3 c) {
  const double la = dot(b - c, b - c), lb = dot(c - a, c - a), lc = dot(a - b, a - b);   // opposite a, b, c
  const double near_shortest = std::min({la, lb, lc}) * (1 + 2e-6);   // squared lengths
  double m = 10;
  if (la <= near_shortest) m = std::min(m, angle_at(a, b, c));
  if (lb <= near_shortest) m = std::min(m, angle_at(b, c, a));
  if (lc <= near_shortest) m = std::min(m, angle_at(c, a, b));
  return m;
}

// Unnormalised normal of triangle (a, b, c).
inline Vec3 normal(Vec3 a, Vec3 b, Vec3 c) { return cross(b - a, c - a); }

// Distance from z to triangle (a, b, c): what the surface checks compare, point by point.
inline double triangle_distance(Vec3 z, Vec3 a, Vec3 b, Vec3 c) {
  const std::array<double, 3> w = closest_point_on_triangle(z, a, b, c);
  return distance(z, w[0] * a + w[1] * b + w[2] * c);
}
inline double triangle_distance(Vec3 z, const TriangleMesh& m, const Triangle& t) {
  return triangle_distance(z, m.positions[t[0]], m.positions[t[1]], m.positions[t[2]]);
}

// The smallest angle of the mesh (10 when it has no triangle): the floor that moves and
// insertions may not push a new triangle under.
inline double mesh_min_angle(const TriangleMesh& m) {
  double worst = 10;
  for (const Triangle& t : m.triangles)
    worst = std::min(worst, min_angle(m.positions[t[0]], m.positions[t[1]], m.positions[t[2]]));
  return worst;
}

// The mean length of one edge per triangle: a length scale for grid cells and spacings, where
// all the edges would cost more and say no more.
inline double mean_edge_estimate(const TriangleMesh& m) {
  double sum = 0;
  for (const Triangle& t : m.triangles) sum += distance(m.positions[t[0]], m.positions[t[1]]);
  return sum / double(std::max<std::size_t>(1, m.num_faces()));
}

// Area-weighted, unnormalised vertex normals: which sheet a point lies on, across a slit or
// a thin wall.
inline std::vector<Vec3> vertex_normals(const TriangleMesh& m) {
  std::vector<Vec3> n(m.num_vertices());
  for (const Triangle& t : m.triangles) {
    const Vec3 f = normal(m.positions[t[0]], m.positions[t[1]], m.positions[t[2]]);
    for (Index w : t) n[w] = n[w] + f;
  }
  return n;
}

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
