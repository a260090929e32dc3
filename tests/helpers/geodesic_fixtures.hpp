#pragma once
// Meshes with closed-form geodesic distances, for the geodesic tests.
#include "helpers/mesh_builders.hpp"

#include <gsp/mesh.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace gsp::test {

// A tiny deterministic generator (std:: distributions differ across standard libraries).
struct SplitMix {
  std::uint64_t s;
  std::uint64_t next() {
    std::uint64_t z = (s += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
  }
  double uniform() { return double(next() >> 11) * 0x1.0p-53; }
};

// An n x n grid over [0, n]^2 with interior vertices jittered by up to `jitter` (< 0.5) and
// each square split along a random diagonal: an irregular triangulation of a convex domain.
// Keep jitter <= 0.25: larger values can fold a triangle over (negative area).
inline TriangleMesh jittered_grid(int n, double jitter, std::uint64_t seed) {
  SplitMix rng{seed};
  TriangleMesh m = grid(n);
  const Index row = Index(n + 1);
  for (int j = 1; j < n; ++j)
    for (int i = 1; i < n; ++i) {
      Vec3& p = m.positions[j * row + i];
      p.x += jitter * (2 * rng.uniform() - 1);
      p.y += jitter * (2 * rng.uniform() - 1);
    }
  m.triangles.clear();
  add_grid_faces(m, n, [&](int, int) { return rng.uniform() < 0.5; });
  return m;
}

// A developable strip: an `nx` x `ny` grid of rectangles bent around a cylinder of radius r
// (less than half a turn). Its unrolling is the rectangle [0, nx * chord] x [0, ny * dy],
// so geodesic distances are plane distances between unrolled points.
struct BentStrip {
  TriangleMesh mesh;
  std::vector<std::array<double, 2>> unrolled;   // per vertex
};
inline BentStrip bent_strip(int nx, int ny, double radius, double turn, double dy) {
  BentStrip s;
  const double dphi = turn / nx;
  const double chord = 2 * radius * std::sin(dphi / 2);
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      s.mesh.positions.push_back({radius * std::cos(i * dphi), radius * std::sin(i * dphi), j * dy});
      s.unrolled.push_back({i * chord, j * dy});
    }
  const Index row = Index(nx + 1);
  for (Index j = 0; j < Index(ny); ++j)
    for (Index i = 0; i < Index(nx); ++i) {
      const Index a = j * row + i, b = a + 1, c = a + row + 1, d = a + row;
      if ((i + j) % 2) {
        s.mesh.triangles.push_back({a, b, c});
        s.mesh.triangles.push_back({a, c, d});
      } else {
        s.mesh.triangles.push_back({a, b, d});
        s.mesh.triangles.push_back({b, c, d});
      }
    }
  return s;
}

inline double relative_error(double approx, double exact) {
  return exact > 0 ? std::abs(approx - exact) / exact : std::abs(approx);
}

// Mean relative error against reference values over the vertices the reference reaches (> 0
// and finite): a vertex the approximation leaves unreached counts as 100%.
inline double mre(const std::vector<double>& approx, const std::vector<double>& reference) {
  double sum = 0;
  std::size_t n = 0;
  for (std::size_t v = 0; v < reference.size(); ++v) {
    if (!(reference[v] > 0) || !std::isfinite(reference[v])) continue;
    sum += std::isfinite(approx[v]) ? std::abs(approx[v] - reference[v]) / reference[v] : 1.0;
    ++n;
  }
  return n ? sum / double(n) : 0;
}

// The diagonal of the axis-aligned bounding box.
inline double bbox_diagonal(const TriangleMesh& m) { return bounding_box(m).diagonal(); }

}  // namespace gsp::test
