// The intrinsic-geometry layer the core and the extensions share (gsp/intrinsic/): bridge
// vertices, vertex kinds and face frames on meshes built in code, whose answers follow from
// their construction.
#include <gsp/connectivity.hpp>
#include <gsp/intrinsic/bridge_vertices.hpp>
#include <gsp/intrinsic/coincident_vertices.hpp>
#include <gsp/intrinsic/edge_lengths.hpp>
#include <gsp/intrinsic/face_frame.hpp>
#include <gsp/intrinsic/vertex_kinds.hpp>

#include <gtest/gtest.h>

#include "helpers/mesh_builders.hpp"

#include <algorithm>
#include <cmath>

namespace gsp {
namespace {

std::vector<bool> none_skipped(const TriangleMesh& m) { return std::vector<bool>(m.num_faces(), false); }

std::vector<Index> bridges(const TriangleMesh& m, std::vector<bool> skipped = {}) {
  if (skipped.empty()) skipped = none_skipped(m);
  return intrinsic::bridge_vertices(m, build_connectivity(m), skipped);
}

TEST(Bridges, BowtieCentreIsTheOnlyBridge) { EXPECT_EQ(bridges(test::bowtie()), std::vector<Index>{0}); }

TEST(Bridges, ClosedAndOpenManifoldsHaveNone) {
  EXPECT_TRUE(bridges(test::tetrahedron()).empty());
  EXPECT_TRUE(bridges(test::icosphere(2)).empty());
  EXPECT_TRUE(bridges(test::grid(6)).empty());
  // Inconsistent orientation joins fans all the same: the edge is shared either way.
  EXPECT_TRUE(bridges(test::flipped_face_tetrahedron()).empty());
  // A non-manifold edge joins its three pages: one fan at each spine vertex.
  EXPECT_TRUE(bridges(test::book()).empty());
}

TEST(Bridges, TwoTetrahedraTouchingAtACorner) {
  TriangleMesh m = test::tetrahedron();
  const Index n = Index(m.num_vertices());
  const TriangleMesh t = test::tetrahedron();
  for (const Vec3& p : t.positions) m.positions.push_back(Vec3{-p.x, -p.y, -p.z});
  for (const Triangle& f : t.triangles) {
    Triangle g = f;
    for (Index& v : g) v = v == 0 ? 0 : v + n;   // vertex 0 is shared: the two touch there
    m.triangles.push_back(g);
  }
  EXPECT_EQ(bridges(m), std::vector<Index>{0});
}

TEST(Bridges, SkippedFacesDoNotJoinFans) {
  // Round vertex 0: faces 0 and 1 share edge 0-2, face 2 shares no edge with them (two
  // fans); face 3 shares 0-5 with face 2 and 0-1 with face 0 (one fan), unless it is skipped.
  TriangleMesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {-1, 1, 0}, {-1, -1, 0}, {0, -1, 0}};
  m.triangles = {{0, 1, 2}, {0, 2, 3}, {0, 4, 5}};
  EXPECT_EQ(bridges(m), std::vector<Index>{0});   // fan {0, 1} and fan {2}
  m.triangles.push_back({0, 5, 1});                // joins them: one fan
  EXPECT_TRUE(bridges(m).empty());
  EXPECT_EQ(bridges(m, {false, false, false, true}), std::vector<Index>{0});
}

// The definition, read off the faces alone: at v, the faces (one per corner at v) joined when
// two of them hold a common edge {v, w} with w != v; v is a bridge where they fall apart.
std::vector<Index> bridges_by_definition(const TriangleMesh& m, const std::vector<bool>& skipped) {
  std::vector<Index> out;
  for (Index v = 0; v < Index(m.num_vertices()); ++v) {
    std::vector<Index> corner;   // 3f + i with triangles[f][i] == v, unskipped
    for (Index f = 0; f < Index(m.num_faces()); ++f)
      for (Index i = 0; i < 3; ++i)
        if (!skipped[f] && m.triangles[f][i] == v) corner.push_back(3 * f + i);
    // The edges {v, w} of corner c: to its next and previous corner's vertex.
    auto edges = [&](Index c) {
      const Triangle& t = m.triangles[c / 3];
      return std::array<Index, 2>{t[(c % 3 + 1) % 3], t[(c % 3 + 2) % 3]};
    };
    std::vector<int> group(corner.size());
    for (std::size_t i = 0; i < group.size(); ++i) group[i] = int(i);
    for (bool changed = true; changed;) {
      changed = false;
      for (std::size_t i = 0; i < corner.size(); ++i)
        for (std::size_t j = 0; j < corner.size(); ++j) {
          if (group[i] == group[j]) continue;
          bool share = false;
          for (Index a : edges(corner[i]))
            for (Index b : edges(corner[j])) share = share || (a == b && a != v);
          if (share) group[i] = group[j] = std::min(group[i], group[j]), changed = true;
        }
    }
    if (!corner.empty() && std::any_of(group.begin(), group.end(), [&](int g) { return g != group[0]; }))
      out.push_back(v);
  }
  return out;
}

TEST(Bridges, RandomSoupsMatchTheDefinition) {
  // Few vertices, many faces: repeated edges (non-manifold), both orientations, faces that
  // repeat a vertex, skipped faces; every kind of corner joint the pass meets.
  std::uint32_t state = 12345;
  auto next = [&](std::uint32_t n) {
    state = state * 1664525u + 1013904223u;
    return (state >> 8) % n;
  };
  std::size_t with_bridges = 0;
  for (int trial = 0; trial < 300; ++trial) {
    TriangleMesh m;
    const std::uint32_t nv = 4 + next(9), nf = 1 + next(14);
    for (std::uint32_t v = 0; v < nv; ++v) m.positions.push_back(Vec3{double(v), double(v * v % 7), double(v % 3)});
    for (std::uint32_t f = 0; f < nf; ++f) {
      Triangle t{Index(next(nv)), Index(next(nv)), Index(next(nv))};
      if (next(4) != 0)
        while (t[1] == t[0]) t[1] = Index(next(nv));   // most faces proper, some repeat a vertex
      if (next(4) != 0)
        while (t[2] == t[0] || t[2] == t[1]) t[2] = Index(next(nv));
      m.triangles.push_back(t);
    }
    std::vector<bool> skipped(nf, false);
    for (std::uint32_t f = 0; f < nf; ++f) skipped[f] = next(6) == 0;
    const std::vector<Index> want = bridges_by_definition(m, skipped);
    with_bridges += !want.empty();
    ASSERT_EQ(bridges(m, skipped), want) << "trial " << trial;
  }
  EXPECT_GT(with_bridges, 50u);   // the soups do exercise the answer
}

// Vertices 0, 3 and 6 share a position, joined by zero-length edges of two slivers (0-3 and
// 3-6); vertex 7 shares it too but no edge joins it to them; 1 and 4 are apart.
TEST(Coincident, ZeroLengthEdgesOfFacesThatTakePartJoinTheirEnds) {
  TriangleMesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 0}, {-1, 0, 0}, {0, -1, 0}, {0, 0, 0}, {0, 0, 0}, {2, 2, 0}};
  m.triangles = {{0, 1, 2}, {3, 4, 5}, {0, 3, 1}, {3, 6, 4}, {7, 8, 2}};
  const Connectivity conn = build_connectivity(m);
  std::vector<double> length = intrinsic::halfedge_lengths(m);
  intrinsic::snap_zero_lengths(length);
  auto groups = [&](const std::vector<bool>& skipped) {
    const intrinsic::CoincidentVertices c = intrinsic::coincident_vertices(m, conn, skipped, length);
    std::vector<std::vector<Index>> out;
    for (std::size_t g = 0; g + 1 < c.begin.size(); ++g) {
      out.emplace_back(c.vertices.begin() + c.begin[g], c.vertices.begin() + c.begin[g + 1]);
      std::sort(out.back().begin(), out.back().end());
    }
    return out;
  };
  EXPECT_EQ(groups(none_skipped(m)), (std::vector<std::vector<Index>>{{0, 3, 6}}));
  // Without the second sliver only 0-3 is left; without both, nothing.
  EXPECT_EQ(groups({false, false, false, true, false}), (std::vector<std::vector<Index>>{{0, 3}}));
  EXPECT_TRUE(groups({false, false, true, true, false}).empty());
  // A mesh with no zero-length edge has no groups (and builds no table for them).
  const TriangleMesh g = test::grid(4);
  std::vector<double> gl = intrinsic::halfedge_lengths(g);
  EXPECT_TRUE(intrinsic::coincident_vertices(g, build_connectivity(g), none_skipped(g), gl).vertices.empty());
}

TEST(VertexKinds, GridInteriorFlatAndCornersFlatBoundary) {
  const TriangleMesh m = test::grid(4);
  const Connectivity conn = build_connectivity(m);
  std::vector<std::uint8_t> boundary(3 * m.num_faces());
  for (Index h = 0; h < Index(boundary.size()); ++h) boundary[h] = conn.ring_size(h) == 1;
  const auto kind = intrinsic::vertex_kinds(m, boundary, none_skipped(m), {});
  // Every vertex of a plane is flat: interior 2 pi, boundary at most pi.
  for (std::uint8_t k : kind) EXPECT_EQ(k, intrinsic::kFlatVertex);
  // Named non-manifold vertices are plain whatever their angles.
  const auto marked = intrinsic::vertex_kinds(m, boundary, none_skipped(m), {0});
  EXPECT_EQ(marked[0], intrinsic::kPlainVertex);
}

TEST(VertexKinds, IcosphereIsConvexEverywhere) {
  const TriangleMesh m = test::icosphere(1);
  const std::vector<std::uint8_t> boundary(3 * m.num_faces(), 0);
  for (std::uint8_t k : intrinsic::vertex_kinds(m, boundary, none_skipped(m), {})) EXPECT_EQ(k, intrinsic::kConvexVertex);
}

std::vector<std::uint8_t> kinds_of_closed(const TriangleMesh& m) {
  return intrinsic::vertex_kinds(m, std::vector<std::uint8_t>(3 * m.num_faces(), 0), none_skipped(m), {});
}

TEST(VertexKinds, FlatOnlyInsideFlatRegions) {
  // Twice split at edge midpoints: the icosphere's own vertices stay convex, every new vertex
  // is flat (it lies on an old edge or inside an old face), but only those with no old
  // vertex among their neighbours count as flat; the others are plain.
  const TriangleMesh ico = test::icosphere(1);
  const TriangleMesh m = midpoint_subdivide(midpoint_subdivide(ico));
  const Index old_count = Index(ico.num_vertices());
  std::vector<bool> next_to_old(m.num_vertices(), false);
  for (const Triangle& t : m.triangles)
    for (int i = 0; i < 3; ++i)
      if (t[(i + 1) % 3] < old_count || t[(i + 2) % 3] < old_count) next_to_old[t[i]] = true;
  const auto kind = kinds_of_closed(m);
  std::size_t flat = 0, plain = 0;
  for (Index v = 0; v < Index(m.num_vertices()); ++v) {
    if (v < old_count) {
      EXPECT_EQ(kind[v], intrinsic::kConvexVertex) << v;
    } else {
      EXPECT_EQ(kind[v], next_to_old[v] ? intrinsic::kPlainVertex : intrinsic::kFlatVertex) << v;
      ++(next_to_old[v] ? plain : flat);
    }
  }
  EXPECT_GT(flat, 0u);
  EXPECT_GT(plain, 0u);
}

TEST(VertexKinds, BarelySaddleVerticesGoWithTheConvexOnes) {
  // A closed fan: vertex 0 at the centre of six ring vertices at heights +h, -h, ..., closed
  // by a cone to an apex (the ring vertices are convex, so no saddle is next to vertex 0). Its angle sum exceeds 2 pi by
  // 0.066% at h = 0.02 (barely: convex), 0.26% at h = 0.04 (plain), 1.6% at h = 0.1 (saddle).
  auto fan = [](double h) {
    TriangleMesh m;
    m.positions.push_back({0, 0, 0});
    for (int i = 0; i < 6; ++i) {
      const double a = 3.14159265358979323846 / 3 * i;
      m.positions.push_back({std::cos(a), std::sin(a), i % 2 ? -h : h});
    }
    m.positions.push_back({0, 0, 3});
    for (Index i = 0; i < 6; ++i) {
      const Index a = 1 + i, b = 1 + (i + 1) % 6;
      m.triangles.push_back({0, a, b});
      m.triangles.push_back({a, 7, b});   // the upper apex over the ring
    }
    return m;
  };
  EXPECT_EQ(kinds_of_closed(fan(0.02))[0], intrinsic::kConvexVertex);
  EXPECT_EQ(kinds_of_closed(fan(0.04))[0], intrinsic::kPlainVertex);
  EXPECT_EQ(kinds_of_closed(fan(0.1))[0], intrinsic::kSaddleVertex);
}

TEST(FaceFrame, LengthsAreKeptAndEdgeFramesInvert) {
  const intrinsic::FaceFrame f = intrinsic::face_frame({3.0, 4.0, 5.0});   // right angle at corner 1
  EXPECT_DOUBLE_EQ(f.corner[2].x, 3.0);
  EXPECT_DOUBLE_EQ(f.corner[2].y, 4.0);
  for (int j = 0; j < 3; ++j) {
    EXPECT_NEAR(intrinsic::length(f.corner[(j + 1) % 3] - f.corner[j]), f.len[j], 1e-12);
    const intrinsic::Vec2 p{0.7, 1.3};
    const intrinsic::Vec2 back = f.from_edge(j, f.to_edge(j, p));
    EXPECT_NEAR(back.x, p.x, 1e-12);
    EXPECT_NEAR(back.y, p.y, 1e-12);
    EXPECT_GT(f.to_edge(j, f.corner[(j + 2) % 3]).y, 0);   // the face lies on +y of every edge
  }
  // Coincident corners 0 and 1: corner 2 on the x axis at its distance.
  const intrinsic::FaceFrame d = intrinsic::face_frame({0.0, 2.0, 2.0});
  EXPECT_DOUBLE_EQ(d.corner[2].x, 2.0);
  EXPECT_DOUBLE_EQ(d.corner[2].y, 0.0);
}

}  // namespace
}  // namespace gsp
