#pragma once
// Tiny meshes built in code, for tests that need a known answer: each function returns a
// gsp::TriangleMesh whose counts and topology are stated in its comment. Faces are oriented
// counter-clockwise seen from outside (or from +z for flat meshes) unless stated otherwise.
#include <gsp/mesh.hpp>
#include <gsp/subdivide.hpp>   // midpoint_subdivide: fine meshes of known geometry

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <utility>

namespace gsp::test {

// One triangle in the z = 0 plane: 3 vertices, 3 boundary edges, area 0.5.
inline TriangleMesh single_triangle() {
  TriangleMesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  m.triangles = {{0, 1, 2}};
  return m;
}

// Unit square split along the diagonal 0-2: 4 vertices, 2 faces, 5 edges, 1 boundary loop.
inline TriangleMesh quad() {
  TriangleMesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  return m;
}

// The faces of an n x n grid of cells over (n+1)^2 vertices numbered row by row (index =
// j * (n + 1) + i), appended cell by cell, rows first: with a = (i, j), b = (i+1, j),
// c = (i+1, j+1), d = (i, j+1), cell (i, j) is split along a-c when along_ac(i, j), else along
// b-d; counter-clockwise seen from +z. along_ac is called once per cell in that order (so a
// random choice consumes its generator the same way every time).
template <class AlongAc>
inline void add_grid_faces(TriangleMesh& m, int n, AlongAc&& along_ac) {
  const Index row = static_cast<Index>(n + 1);
  for (Index j = 0; j < Index(n); ++j)
    for (Index i = 0; i < Index(n); ++i) {
      const Index a = j * row + i, b = a + 1, c = a + row + 1, d = a + row;
      if (along_ac(int(i), int(j))) {
        m.triangles.push_back({a, b, c});
        m.triangles.push_back({a, c, d});
      } else {
        m.triangles.push_back({a, b, d});
        m.triangles.push_back({b, c, d});
      }
    }
}

// n x n unit squares over [0, n]^2 in z = 0, vertices row by row (index = j * (n + 1) + i),
// each square split along its diagonal: (n+1)^2 vertices, 2 n^2 faces, 3 n^2 + 2 n edges,
// 4 n boundary edges in one loop, Euler characteristic 1.
inline TriangleMesh grid(int n) {
  TriangleMesh m;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) m.positions.push_back({double(i), double(j), 0});
  add_grid_faces(m, n, [](int, int) { return true; });
  return m;
}

// Regular tetrahedron: 4 vertices, 4 faces, 6 edges, closed, Euler characteristic 2.
inline TriangleMesh tetrahedron() {
  TriangleMesh m;
  m.positions = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
  m.triangles = {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}};
  return m;
}

// Unit icosphere: the icosahedron with each face split into 4, k times, new vertices pushed
// onto the sphere. 10 * 4^k + 2 vertices, 20 * 4^k faces, 30 * 4^k edges, Euler 2.
inline TriangleMesh icosphere(int k) {
  TriangleMesh m;
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  const Vec3 base[12] = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                         {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  for (const Vec3& p : base) m.positions.push_back((1.0 / norm(p)) * p);
  m.triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                 {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                 {3, 8, 9},  {4, 9, 5},  {2, 4, 11},  {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  for (int level = 0; level < k; ++level) {
    std::map<std::pair<Index, Index>, Index> midpoint;
    auto mid = [&](Index a, Index b) {
      const auto key = std::make_pair(std::min(a, b), std::max(a, b));
      auto it = midpoint.find(key);
      if (it != midpoint.end()) return it->second;
      const Vec3 p = 0.5 * (m.positions[a] + m.positions[b]);
      m.positions.push_back((1.0 / norm(p)) * p);
      const Index v = static_cast<Index>(m.positions.size() - 1);
      midpoint.emplace(key, v);
      return v;
    };
    std::vector<Triangle> finer;
    for (const Triangle& f : m.triangles) {
      const Index ab = mid(f[0], f[1]), bc = mid(f[1], f[2]), ca = mid(f[2], f[0]);
      finer.push_back({f[0], ab, ca});
      finer.push_back({f[1], bc, ab});
      finer.push_back({f[2], ca, bc});
      finer.push_back({ab, bc, ca});
    }
    m.triangles = std::move(finer);
  }
  return m;
}

// Open cylinder (a tube) of radius 1 around z: `segments` >= 3 around, `rings` >= 1 quads
// high. segments * (rings + 1) vertices, 2 * segments * rings faces, two boundary loops,
// Euler characteristic 0. Vertex index = ring * segments + segment.
inline TriangleMesh cylinder(int segments, int rings) {
  TriangleMesh m;
  const double pi = std::acos(-1.0);
  const Index s = static_cast<Index>(segments);
  for (int r = 0; r <= rings; ++r)
    for (int i = 0; i < segments; ++i)
      m.positions.push_back({std::cos(2 * pi * i / segments), std::sin(2 * pi * i / segments), double(r)});
  for (Index r = 0; r < Index(rings); ++r)
    for (Index i = 0; i < s; ++i) {
      const Index a = r * s + i, b = r * s + (i + 1) % s, c = b + s, d = a + s;
      m.triangles.push_back({a, b, c});
      m.triangles.push_back({a, c, d});
    }
  return m;
}

// A square plate [-a, a]^2 x [0, t] with a round through-hole of radius r (n rim segments),
// its flat faces written as CAD exporters write them: a fan of slivers from each square corner
// over its quarter of the rim, one triangle per side between two fans; the hole's wall and the
// outer walls as quads split in two. Closed, genus 1; the rim's vertices are saddles. Vertex
// index: bottom rim 0..n-1, bottom corners n..n+3, top rim n+4..2n+3, top corners 2n+4..2n+7.
inline TriangleMesh plate_with_hole(double a, double r, double t, int n) {
  TriangleMesh m;
  const double pi = std::acos(-1.0);
  const Index s = static_cast<Index>(n);
  auto angle = [&](Index i) { return 2 * pi * double(i) / double(n) + 0.1; };
  // The corner whose quarter of the rim vertex i faces (corners at 45, 135, 225, 315 degrees).
  auto quarter = [&](Index i) { return Index(std::floor(std::fmod(angle(i), 2 * pi) / (pi / 2))) % 4; };
  const double sx[4] = {1, -1, -1, 1}, sy[4] = {1, 1, -1, -1};
  for (int z = 0; z < 2; ++z) {
    for (Index i = 0; i < s; ++i) m.positions.push_back({r * std::cos(angle(i)), r * std::sin(angle(i)), z * t});
    for (int k = 0; k < 4; ++k) m.positions.push_back({a * sx[k], a * sy[k], z * t});
  }
  auto rim = [&](int z, Index i) { return Index(z) * (s + 4) + i % s; };
  auto corner = [&](int z, Index k) { return Index(z) * (s + 4) + s + k; };
  for (int z = 0; z < 2; ++z)
    for (Index i = 0; i < s; ++i) {
      const Index k = quarter(i), k2 = quarter((i + 1) % s);
      const Index c = corner(z, k), p = rim(z, i), q = rim(z, i + 1);
      m.triangles.push_back(z == 1 ? Triangle{c, p, q} : Triangle{c, q, p});
      if (k2 != k) {
        const Index c2 = corner(z, k2);
        m.triangles.push_back(z == 1 ? Triangle{c, q, c2} : Triangle{c, c2, q});
      }
    }
  for (Index i = 0; i < s; ++i) {
    m.triangles.push_back({rim(0, i), rim(0, i + 1), rim(1, i + 1)});
    m.triangles.push_back({rim(0, i), rim(1, i + 1), rim(1, i)});
  }
  for (Index k = 0; k < 4; ++k) {
    const Index k2 = (k + 1) % 4;
    m.triangles.push_back({corner(0, k), corner(1, k2), corner(0, k2)});
    m.triangles.push_back({corner(0, k), corner(1, k), corner(1, k2)});
  }
  return m;
}

// A plate of thickness t round a hole of radius r, both circles n-gons (outer radius R), its
// flat faces in k rings of well-shaped triangles (each ring's vertices turned half a segment
// against the last): a CAD part meshed by a careful mesher. Closed, genus 1; the hole's rim
// vertices are saddles, the rings' vertices inside the faces flat.
inline TriangleMesh ringed_plate_with_hole(double R, double r, double t, int n, int k) {
  TriangleMesh m;
  const double pi = std::acos(-1.0);
  std::vector<std::vector<Index>> ring(2 * std::size_t(k + 1));
  for (int z = 0; z < 2; ++z)
    for (int j = 0; j <= k; ++j) {
      const double rad = r + (R - r) * j / k, off = k > 1 ? 0.5 * j * 2 * pi / n : 0;
      for (int i = 0; i < n; ++i) {
        ring[std::size_t(z * (k + 1) + j)].push_back(Index(m.positions.size()));
        m.positions.push_back({rad * std::cos(2 * pi * i / n + off), rad * std::sin(2 * pi * i / n + off), z * t});
      }
    }
  auto at = [&](int z, int j, int i) { return ring[std::size_t(z * (k + 1) + j)][std::size_t(i % n)]; };
  auto add = [&](Triangle tr, bool flip) { m.triangles.push_back(flip ? Triangle{tr[2], tr[1], tr[0]} : tr); };
  for (int z = 0; z < 2; ++z)
    for (int j = 0; j < k; ++j)
      for (int i = 0; i < n; ++i) {
        const Index a0 = at(z, j, i), a1 = at(z, j, i + 1), b0 = at(z, j + 1, i), b1 = at(z, j + 1, i + 1);
        if (k > 1) {
          add({a0, b0, a1}, z == 0), add({a1, b0, b1}, z == 0);
        } else {
          add({a0, b1, a1}, z == 0), add({a0, b0, b1}, z == 0);
        }
      }
  for (int j : {0, k})
    for (int i = 0; i < n; ++i) {
      const Index a0 = at(0, j, i), a1 = at(0, j, i + 1), b0 = at(1, j, i), b1 = at(1, j, i + 1);
      add({a0, a1, b1}, j != k), add({a0, b1, b0}, j != k);
    }
  return m;
}

// A strip of `quads` unit squares along x (a grid one square high): 2 (quads + 1) vertices,
// 2 quads faces, one boundary loop.
inline TriangleMesh strip(int quads) {
  TriangleMesh m;
  for (int i = 0; i <= quads; ++i) {
    m.positions.push_back({double(i), 0, 0});
    m.positions.push_back({double(i), 1, 0});
  }
  for (Index i = 0; i < Index(quads); ++i) {
    const Index a = 2 * i, b = a + 2, c = a + 3, d = a + 1;
    m.triangles.push_back({a, b, c});
    m.triangles.push_back({a, c, d});
  }
  return m;
}

// Non-manifold "book": three triangles (pages) on the spine edge 0-1. 5 vertices, 7 edges,
// 1 non-manifold edge (ring of 3), 6 boundary edges, so vertices 0 and 1 are non-manifold.
inline TriangleMesh book() {
  TriangleMesh m;
  m.positions = {{0, 0, 0}, {0, 0, 1}, {1, 0, 0}, {-1, 0, 0}, {0, 1, 0}};
  m.triangles = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};
  return m;
}

// Bow-tie: two triangles sharing only vertex 0. 5 vertices, 6 boundary edges, manifold
// edges everywhere but vertex 0 is non-manifold (two fans). One component (shared vertex),
// one boundary loop (the boundary-edge graph is connected through vertex 0).
inline TriangleMesh bowtie() {
  TriangleMesh m;
  m.positions = {{0, 0, 0}, {1, -0.5, 0}, {1, 0.5, 0}, {-1, 0.5, 0}, {-1, -0.5, 0}};
  m.triangles = {{0, 1, 2}, {0, 3, 4}};
  return m;
}

// The tetrahedron with face 3 reversed: the three edges of that face are inconsistently
// oriented (both halfedges run the same way); still closed and manifold.
inline TriangleMesh flipped_face_tetrahedron() {
  TriangleMesh m = tetrahedron();
  std::swap(m.triangles[3][1], m.triangles[3][2]);
  return m;
}

// The quad plus trouble: face 2 = (1, 0, 2) repeats face 0 reversed (a duplicate), face 3 =
// (3, 3, 2) names vertex 3 twice, face 4 = (0, 1, 4) has zero area (4 = (2, 0, 0) is on the
// line through 0 and 1), and vertex 5 is referenced by no face. Counts: 6 vertices, 5 faces,
// 7 edges; 3 boundary (0-3, 1-4, 0-4; one loop), 3 non-manifold (0-1, 0-2, 2-3), so vertices
// 0..3 are non-manifold; 1 duplicate, 1 repeated-index and 1 zero-area face; 1 component;
// Euler characteristic 5 - 7 + 5 = 3.
inline TriangleMesh duplicate_and_degenerate() {
  TriangleMesh m = quad();
  m.positions.push_back({2, 0, 0});
  m.positions.push_back({5, 5, 5});
  m.triangles.push_back({1, 0, 2});
  m.triangles.push_back({3, 3, 2});
  m.triangles.push_back({0, 1, 4});
  return m;
}

// STL-like soup of `mesh`: every face gets its own three vertices (copies of the shared
// ones, in face order), as STL files and many glTF exports store them.
inline TriangleMesh explode(const TriangleMesh& mesh) {
  TriangleMesh m;
  for (const Triangle& t : mesh.triangles) {
    const Index base = static_cast<Index>(m.positions.size());
    for (Index v : t) m.positions.push_back(mesh.positions[v]);
    m.triangles.push_back({base, base + 1, base + 2});
  }
  return m;
}

}  // namespace gsp::test
