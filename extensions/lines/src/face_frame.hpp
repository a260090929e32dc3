#pragma once
// A face in its canonical 2D frame (internal): corner 0 at the origin, corner 1 on +x, corner 2
// above, built from the three 3D edge lengths only, so any two faces sharing an edge agree on
// its length and unfold onto each other exactly as the surface is made.
#include <gsp/mesh.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace gsp::lines::detail {

struct Vec2 {
  double x = 0, y = 0;
  friend Vec2 operator+(Vec2 a, Vec2 b) { return {a.x + b.x, a.y + b.y}; }
  friend Vec2 operator-(Vec2 a, Vec2 b) { return {a.x - b.x, a.y - b.y}; }
  friend Vec2 operator*(double s, Vec2 a) { return {s * a.x, s * a.y}; }
};
inline double dot(Vec2 a, Vec2 b) { return a.x * b.x + a.y * b.y; }
inline double length(Vec2 a) { return std::sqrt(dot(a, a)); }

// The point of segment [a, b] nearest to p (a == b: a point source).
inline Vec2 nearest_on_segment(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 ab = b - a;
  const double l2 = dot(ab, ab);
  if (!(l2 > 0)) return a;
  const double t = std::clamp(dot(p - a, ab) / l2, 0.0, 1.0);
  return a + t * ab;
}
inline double segment_distance(Vec2 p, Vec2 a, Vec2 b) { return length(p - nearest_on_segment(p, a, b)); }

struct FaceFrame {
  std::array<Vec2, 3> corner;   // canonical positions of corners 0, 1, 2
  std::array<double, 3> len;    // len[i] = |corner i -> corner i+1|

  Vec2 at(const std::array<double, 3>& w) const {
    return w[0] * corner[0] + w[1] * corner[1] + w[2] * corner[2];
  }

  // The edge frame of halfedge j: corner j at the origin, corner j+1 on +x, the face on +y.
  // The canonical triangle runs counter-clockwise, so +y is the left normal of every edge.
  Vec2 axis(int j) const {
    const Vec2 d = corner[(j + 1) % 3] - corner[j];
    const double l = length(d);
    return l > 0 ? (1.0 / l) * d : Vec2{1, 0};
  }
  Vec2 to_edge(int j, Vec2 p) const {
    const Vec2 u = axis(j), d = p - corner[j];
    return {dot(d, u), u.x * d.y - u.y * d.x};
  }
  Vec2 from_edge(int j, Vec2 e) const {
    const Vec2 u = axis(j);
    return corner[j] + Vec2{e.x * u.x - e.y * u.y, e.x * u.y + e.y * u.x};
  }
};

inline FaceFrame face_frame(const TriangleMesh& mesh, Index f) {
  const Triangle& t = mesh.triangles[f];
  FaceFrame fr;
  for (int i = 0; i < 3; ++i) fr.len[i] = distance(mesh.positions[t[i]], mesh.positions[t[(i + 1) % 3]]);
  const double l0 = fr.len[0], l1 = fr.len[1], l2 = fr.len[2];
  fr.corner[0] = {0, 0};
  fr.corner[1] = {l0, 0};
  if (l0 > 0) {
    const double px = (l0 * l0 + l2 * l2 - l1 * l1) / (2 * l0);
    fr.corner[2] = {px, std::sqrt(std::max(0.0, l2 * l2 - px * px))};   // slivers round below 0
  } else {
    fr.corner[2] = {l2, 0};   // corners 0 and 1 coincide
  }
  return fr;
}

// True when face f names a vertex twice: such faces are left out (they have no plane).
inline bool repeats_vertex(const Triangle& t) { return t[0] == t[1] || t[1] == t[2] || t[0] == t[2]; }

}  // namespace gsp::lines::detail
