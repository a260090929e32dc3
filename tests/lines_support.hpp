#pragma once
// Meshes and closed forms for the gsp::lines tests: irregular triangulations of a unit square
// placed on a tilted plane in 3D, and the 3D distance from a point to a segment.
#include "helpers/mesh_builders.hpp"

#include <gsp/mesh.hpp>

#include <algorithm>
#include <random>
#include <vector>

namespace gsp::test {

// The plane the squares are put on: origin and two orthonormal axes, none axis-aligned, so
// every coordinate of every vertex is involved.
struct Plane {
  Vec3 origin{0.3, -1.2, 0.7};
  Vec3 u{0.6, 0.64, 0.48};     // unit
  Vec3 v{-0.8, 0.48, 0.36};    // unit, orthogonal to u
  Vec3 at(double x, double y) const { return origin + x * u + y * v; }
};

// An n x n grid on [0,1]^2 with interior vertices jittered by up to 0.2 cells (no triangle can
// flip: a corner moves less than half its distance to the opposite diagonal), boundary vertices
// moved along the boundary only (the square stays a square), and each cell's diagonal picked at
// random: irregular triangles, different for every seed. Vertex (i, j) is i + j*(n+1).
inline TriangleMesh jittered_square(int n, unsigned seed, const Plane& plane = {}) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> jitter(-0.2, 0.2);
  std::bernoulli_distribution coin(0.5);
  TriangleMesh m;
  const double h = 1.0 / n;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      double x = i * h, y = j * h;
      if (i > 0 && i < n) x += jitter(rng) * h;
      if (j > 0 && j < n) y += jitter(rng) * h;
      m.positions.push_back(plane.at(x, y));
    }
  add_grid_faces(m, n, [&](int, int) { return coin(rng); });
  return m;
}

inline double point_segment_distance(Vec3 p, Vec3 a, Vec3 b) {
  const Vec3 ab = b - a;
  const double l2 = dot(ab, ab);
  const double t = l2 > 0 ? std::clamp(dot(p - a, ab) / l2, 0.0, 1.0) : 0.0;
  return distance(p, a + t * ab);
}

}  // namespace gsp::test
