#pragma once
// Whether two faces across an edge lie in one plane (internal layer shared by the core's
// carried windows and the flat-corner rule's creases; not a stable API). 3D positions only: a
// caller's metric has no planes.
#include <gsp/connectivity.hpp>
#include <gsp/mesh.hpp>

#include <array>
#include <cmath>
#include <vector>

namespace gsp::intrinsic {

// Faces whose normals agree within this angle (degrees) are one plane (docs/gsp-core.md,
// rules 4 and 10, have what it was measured against).
inline constexpr double kCoplanarDegrees = 0.05;

// Face f's normal, unnormalised (twice its area long).
inline Vec3 face_normal(const std::vector<Triangle>& triangles, const std::vector<Vec3>& positions, Index f) {
  const Triangle& t = triangles[f];
  return cross(positions[t[1]] - positions[t[0]], positions[t[2]] - positions[t[0]]);
}

// A face normal as the flat-corner rule's creases compare them: unit length, in float; zero
// for a zero vector.
inline std::array<float, 3> unit_normal(const Vec3& n) {
  const double length = std::sqrt(dot(n, n));
  const double k = length > 0 ? 1 / length : 0;
  return {float(n[0] * k), float(n[1] * k), float(n[2] * k)};
}

// Whether face_of(h) (normal n, face_normal()) and face_of(g), both on halfedge h's edge, lie
// in one plane (normals within kCoplanarDegrees, the faces' orientations reconciled along the
// edge). Most pairs fail at once: g's far corner lies off f's plane by more than the angle
// allows even measured from h's first end (the edge's line is no farther than that).
inline bool coplanar_across(const std::vector<Triangle>& triangles, const std::vector<Vec3>& positions, const Vec3& n,
                            Index h, Index g) {
  constexpr double kPi = 3.14159265358979323846;
  static const double sin2 = std::pow(std::sin(kCoplanarDegrees * kPi / 180), 2);
  const Index a = triangles[face_of(h)][corner_of(h)];
  const Triangle& tg = triangles[face_of(g)];
  const Vec3 q = positions[tg[corner_of(g) == 0 ? 2 : corner_of(g) - 1]] - positions[a];
  const double off = dot(n, q), n2 = dot(n, n);
  if (off * off > sin2 * n2 * dot(q, q)) return false;
  Vec3 m = face_normal(triangles, positions, face_of(g));
  if (tg[corner_of(g)] == a) m = -1.0 * m;   // both walk the edge the same way: orientations disagree
  if (!(dot(n, m) > 0)) return false;
  const Vec3 c = cross(n, m);
  return dot(c, c) <= sin2 * n2 * dot(m, m);
}

}  // namespace gsp::intrinsic
