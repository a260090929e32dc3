#pragma once
// Small meshes built in code for the gsp::cvt tests.
#include <gsp/mesh.hpp>

namespace gsp::test {

// The square [0, size]^2 in the plane z = 0 as an n x n grid, each cell split along alternating
// diagonals; counter-clockwise seen from +z.
inline TriangleMesh square_grid(int n, double size = 1.0) {
  TriangleMesh m;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) m.positions.push_back({size * i / n, size * j / n, 0});
  auto id = [n](int i, int j) { return Index(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const Index a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      if ((i + j) % 2) {
        m.triangles.push_back({a, b, c});
        m.triangles.push_back({a, c, d});
      } else {
        m.triangles.push_back({a, b, d});
        m.triangles.push_back({b, c, d});
      }
    }
  return m;
}

}  // namespace gsp::test
