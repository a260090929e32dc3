#pragma once
// A face in its canonical 2D frame, built from its three edge lengths only (internal layer:
// the core's propagation and the extensions share it; not a stable API). Corner 0 is at the
// origin, corner 1 on +x, corner 2 above (y >= 0). Any two faces sharing an edge agree on its
// length, so they unfold onto each other exactly as the surface is made, and a metric's
// intrinsic lengths give the same frames as 3D positions would.
#include <gsp/mesh.hpp>
#include <gsp/types.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace gsp::intrinsic {

// The face seen from its halfedge j: A = corner j at the origin, B = corner j+1 at (e1, 0),
// P = corner j+2 at (px, py), py >= 0. A zero-length AB puts P straight above A.
template <class Real>
struct EdgeView {
  Real e1, px, py;
};

template <class Real>
[[gnu::always_inline]] inline EdgeView<Real> edge_view(const Real len[3], Index j) {
  const Real e1 = len[j], e2 = len[j == 2 ? 0 : j + 1], e3 = len[j == 0 ? 2 : j - 1];
  if (!(e1 > 0)) return {Real(0), Real(0), e3};
  const Real px = (e1 * e1 + e3 * e3 - e2 * e2) / (2 * e1);
  return {e1, px, std::sqrt(std::max(Real(0), e3 * e3 - px * px))};   // clamped: slivers round below 0
}

// The canonical frame inside the edge frame of view v (halfedge j): origin (ox, oy) = corner 0,
// unit x axis (ux, uy) towards corner 1 (towards corner 2 when corners 0 and 1 coincide).
template <class Real>
struct CanonicalFrame {
  Real ox, oy, ux, uy;

  // Edge-frame point -> canonical coordinates, and back.
  void to_canonical(Real x, Real y, Real& cx, Real& cy) const {
    const Real dx = x - ox, dy = y - oy;
    cx = dx * ux + dy * uy;
    cy = ux * dy - uy * dx;
  }
  void to_edge(Real cx, Real cy, Real& x, Real& y) const {
    x = ox + cx * ux - cy * uy;
    y = oy + cx * uy + cy * ux;
  }
};

template <class Real>
[[gnu::always_inline]] inline CanonicalFrame<Real> canonical_frame(const Real len[3], Index j, const EdgeView<Real>& v) {
  // Corner 0 and the direction to corner 1, in the edge frame of halfedge j (A = corner j at
  // the origin, B = corner j+1 at (e1, 0), P = corner j+2 at (px, py)). Written per case, not
  // through arrays indexed by j: this runs twice per update step.
  const Real l = len[0];
  if (l > 0) {
    if (j == 0) return {Real(0), Real(0), Real(1), Real(0)};   // the canonical frame (e1 = l)
    if (j == 1) return {v.px, v.py, -v.px / l, -v.py / l};
    return {v.e1, Real(0), (v.px - v.e1) / l, v.py / l};
  }
  // Corners 0 and 1 coincide: towards corner 2 instead.
  Real x[3], y[3];
  const Index a = j, b = j == 2 ? 0 : j + 1, p = j == 0 ? 2 : j - 1;
  x[a] = 0, y[a] = 0;
  x[b] = v.e1, y[b] = 0;
  x[p] = v.px, y[p] = v.py;
  const Real dx = x[2] - x[0], dy = y[2] - y[0], l2 = len[2];
  if (!(l2 > 0)) return {x[0], y[0], Real(1), Real(0)};
  return {x[0], y[0], dx / l2, dy / l2};
}

// The canonical position of corner 2 (corner 0 is the origin, corner 1 is (len[0], 0)).
template <class Real>
inline void canonical_corner2(const Real len[3], Real& x, Real& y) {
  if (len[0] > 0) {
    const EdgeView<Real> v = edge_view(len, 0);
    x = v.px, y = v.py;
  } else {
    x = len[2], y = 0;
  }
}

// A 2D point or vector in a face frame (double).
struct Vec2 {
  double x = 0, y = 0;
  friend Vec2 operator+(Vec2 a, Vec2 b) { return {a.x + b.x, a.y + b.y}; }
  friend Vec2 operator-(Vec2 a, Vec2 b) { return {a.x - b.x, a.y - b.y}; }
  friend Vec2 operator*(double s, Vec2 a) { return {s * a.x, s * a.y}; }
};
inline double dot(Vec2 a, Vec2 b) { return a.x * b.x + a.y * b.y; }
inline double length(Vec2 a) { return std::sqrt(dot(a, a)); }

// A face's canonical corners and lengths in double, with the edge frames of its halfedges
// (for callers that keep frames per face rather than recomputing them per step).
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

inline FaceFrame face_frame(const std::array<double, 3>& len) {
  FaceFrame fr;
  fr.len = len;
  fr.corner[0] = {0, 0};
  fr.corner[1] = {len[0], 0};
  canonical_corner2(len.data(), fr.corner[2].x, fr.corner[2].y);
  return fr;
}

// Face f's frame from the 3D lengths of its edges.
inline FaceFrame face_frame(const TriangleMesh& mesh, Index f) {
  const Triangle& t = mesh.triangles[f];
  std::array<double, 3> len;
  for (int i = 0; i < 3; ++i) len[i] = distance(mesh.positions[t[i]], mesh.positions[t[(i + 1) % 3]]);
  return face_frame(len);
}

}  // namespace gsp::intrinsic
