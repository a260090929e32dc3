#pragma once
// Meshes built in code for the sampling tests: a flat disk of a given area and a long
// flattened tube (two parallel sheets closer than the sampling radius, joined at the sides).
#include <gsp/mesh.hpp>

#include <cmath>
#include <vector>

namespace gsp::test {

// A disk of radius R in the z = 0 plane: concentric rings (ring k has 6k vertices), each
// strip between two rings triangulated by walking both by angle.
inline TriangleMesh flat_disk(double R, int rings) {
  const double pi = std::acos(-1.0);
  TriangleMesh m;
  m.positions.push_back({0, 0, 0});
  std::vector<Index> start{0};
  for (int k = 1; k <= rings; ++k) {
    start.push_back(Index(m.positions.size()));
    for (int i = 0; i < 6 * k; ++i) {
      const double a = 2 * pi * i / (6 * k);
      m.positions.push_back({R * k / rings * std::cos(a), R * k / rings * std::sin(a), 0});
    }
  }
  for (int k = 1; k <= rings; ++k) {
    const int n_in = k == 1 ? 1 : 6 * (k - 1), n_out = 6 * k;
    int i = 0, o = 0;
    while (o < n_out || (n_in > 1 && i < n_in)) {
      const Index a = start[k - 1] + Index(i % n_in), b = start[k] + Index(o % n_out);
      // Advance the ring whose next vertex comes first by angle.
      const double next_in = n_in == 1 ? 2.0 : double(i + 1) / n_in, next_out = double(o + 1) / n_out;
      if (o < n_out && (i >= n_in || next_out <= next_in)) {
        m.triangles.push_back({a, b, start[k] + Index((o + 1) % n_out)});
        ++o;
      } else {
        m.triangles.push_back({a, b, start[k - 1] + Index((i + 1) % n_in)});
        ++i;
      }
    }
  }
  return m;
}

// An open tube along x of length `length` whose cross-section is a flat ellipse of width
// `width` (y) and height `height` (z): two nearly flat sheets `height` apart that join only
// at y = +-width/2.
inline TriangleMesh flattened_tube(double length, double width, double height, int nx, int nt) {
  const double pi = std::acos(-1.0);
  TriangleMesh m;
  for (int i = 0; i <= nx; ++i)
    for (int j = 0; j < nt; ++j) {
      const double a = 2 * pi * j / nt;
      m.positions.push_back({length * i / nx, 0.5 * width * std::cos(a), 0.5 * height * std::sin(a)});
    }
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < nt; ++j) {
      const Index a = Index(i * nt + j), b = Index(i * nt + (j + 1) % nt);
      const Index c = a + Index(nt), d = b + Index(nt);
      m.triangles.push_back({a, b, d});
      m.triangles.push_back({a, d, c});
    }
  return m;
}

}  // namespace gsp::test
