#pragma once
// Small meshes built in code for the gsp::cvt tests.
#include "helpers/mesh_builders.hpp"

#include <gsp/mesh.hpp>

namespace gsp::test {

// The square [0, size]^2 in the plane z = 0 as an n x n grid, each cell split along alternating
// diagonals; counter-clockwise seen from +z.
inline TriangleMesh square_grid(int n, double size = 1.0) {
  TriangleMesh m;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) m.positions.push_back({size * i / n, size * j / n, 0});
  add_grid_faces(m, n, [](int i, int j) { return (i + j) % 2 != 0; });
  return m;
}

}  // namespace gsp::test
