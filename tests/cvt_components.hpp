#pragma once
// Meshes of several components for the gsp::cvt component and surface tests.
#include "helpers/mesh_builders.hpp"

#include <cmath>
#include <utility>

namespace gsp::test {

// `b` scaled by s and moved by d, appended to `a` as a separate component.
inline void add(TriangleMesh& a, const TriangleMesh& b, double s, Vec3 d) {
  const Index base = Index(a.positions.size());
  for (const Vec3& p : b.positions) a.positions.push_back(s * p + d);
  for (const Triangle& t : b.triangles) a.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
}

// A Moebius strip of n quads: the last column joins the first one upside down.
inline TriangleMesh moebius(int n) {
  TriangleMesh m;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * M_PI * i / n;
    for (double w : {-0.3, 0.3}) {
      const double r = 1 + w * std::cos(a / 2);
      m.positions.push_back({r * std::cos(a), r * std::sin(a), w * std::sin(a / 2)});
    }
  }
  for (int i = 0; i < n; ++i) {
    const Index a = Index(2 * i), b = a + 1;
    Index c = Index(2 * ((i + 1) % n)), d = c + 1;
    if (i == n - 1) std::swap(c, d);   // the twist
    m.triangles.push_back({a, c, d});
    m.triangles.push_back({a, d, b});
  }
  return m;
}

// A torus of tube radius r around a circle of radius 1, n x m quads, outward.
inline TriangleMesh torus(double r, int n, int m) {
  TriangleMesh t;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < m; ++j) {
      const double a = 2 * M_PI * i / n, b = 2 * M_PI * j / m;
      t.positions.push_back({(1 + r * std::cos(b)) * std::cos(a), (1 + r * std::cos(b)) * std::sin(a), r * std::sin(b)});
    }
  auto v = [&](int i, int j) { return Index((i % n) * m + (j % m)); };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < m; ++j) {
      t.triangles.push_back({v(i, j), v(i + 1, j), v(i + 1, j + 1)});
      t.triangles.push_back({v(i, j), v(i + 1, j + 1), v(i, j + 1)});
    }
  return t;
}

}  // namespace gsp::test
