// The intrinsic Delaunay step on soups (libgsp/src/intrinsic_delaunay.*): faces are wound
// consistently before flipping, so a split soup with flipped faces gets back the original
// mesh's faces corner for corner; and flips work on edges whose two faces are wound
// inconsistently (a Moebius strip has such a seam whatever the winding).
#include "helpers/geodesic_fixtures.hpp"

#include "intrinsic_delaunay.hpp"   // internal (libgsp/src)

#include <gsp/connectivity.hpp>
#include <gsp/io/mesh_io.hpp>
#include <gsp/weld.hpp>

#include <gtest/gtest.h>

#include <cmath>

namespace gsp::test {
namespace {

constexpr double kPi = 3.14159265358979323846;

TriangleMesh fertility() { return io::read_mesh(std::string(GSP_TEST_DIR) + "/../data/samples/fertility.off").mesh; }

detail::IntrinsicTriangulation from_mesh(const TriangleMesh& m) {
  detail::IntrinsicTriangulation t;
  t.triangles = m.triangles;
  t.ring = build_connectivity(m).radial_next;
  t.skipped.assign(m.num_faces(), false);
  for (std::size_t f = 0; f < m.num_faces(); ++f)
    for (int i = 0; i < 3; ++i)
      t.length.push_back(distance(m.positions[m.triangles[f][i]], m.positions[m.triangles[f][(i + 1) % 3]]));
  return t;
}

// The mesh split into one triangle per face, faces with flip(f) wound the other way
// ((a, b, c) -> (a, c, b)), welded again; original_of maps welded vertices back.
template <class Flip>
TriangleMesh flipped_soup(const TriangleMesh& m, Flip flip, std::vector<Index>& original_of) {
  TriangleMesh soup;
  std::vector<Index> soup_of;
  for (std::size_t f = 0; f < m.num_faces(); ++f) {
    Triangle t = m.triangles[f];
    if (flip(f)) std::swap(t[1], t[2]);
    Triangle s;
    for (int c = 0; c < 3; ++c) {
      s[c] = Index(soup.positions.size());
      soup.positions.push_back(m.positions[t[c]]);
      soup_of.push_back(t[c]);
    }
    soup.triangles.push_back(s);
  }
  const WeldResult w = weld_vertices(soup, 0.0);
  original_of.assign(w.mesh.num_vertices(), kInvalidIndex);
  for (std::size_t c = 0; c < soup_of.size(); ++c) original_of[w.vertex_map[c]] = soup_of[c];
  return w.mesh;
}

// Faces of t (vertices mapped through original_of) equal to m's, corner for corner.
std::size_t faces_as_original(const detail::IntrinsicTriangulation& t, const TriangleMesh& m,
                              const std::vector<Index>& original_of) {
  std::size_t same = 0;
  for (std::size_t f = 0; f < m.num_faces(); ++f) {
    const Triangle& a = t.triangles[f];
    same += Triangle{original_of[a[0]], original_of[a[1]], original_of[a[2]]} == m.triangles[f];
  }
  return same;
}

TEST(SoupOrientation, HalfFlippedClosedMeshIsWoundOutwardsAgain) {
  const TriangleMesh m = fertility();   // closed, wound outwards
  std::vector<Index> original_of;
  // Exactly half flipped (a tie for the majority) and every face flipped: the signed volume decides.
  for (bool all : {false, true}) {
    const TriangleMesh soup = flipped_soup(m, [&](std::size_t f) { return all || f % 2 == 1; }, original_of);
    detail::IntrinsicTriangulation t = from_mesh(soup);
    t.positions = &soup.positions;
    const std::size_t reversed = detail::orient_consistently(t);
    EXPECT_EQ(reversed, all ? m.num_faces() : m.num_faces() / 2);
    EXPECT_EQ(faces_as_original(t, m, original_of), m.num_faces());
    // Lengths and rings moved with the corners: each halfedge's length is its edge's, twins agree.
    for (Index h = 0; h < Index(t.length.size()); ++h) {
      const Triangle& c = t.triangles[face_of(h)];
      EXPECT_DOUBLE_EQ(t.length[h], distance(soup.positions[c[corner_of(h)]], soup.positions[c[corner_of(next_halfedge(h))]]));
      EXPECT_EQ(t.ring[t.ring[h]], h);
      EXPECT_EQ(t.triangles[face_of(t.ring[h])][corner_of(t.ring[h])], c[corner_of(next_halfedge(h))]);   // runs backwards
    }
  }
}

// Consistently wound patches (the common input) take a shortcut with the same answer: each
// patch on its own, a closed one wound outwards. Two copies of fertility apart, the second
// wound inwards, and a face left out: only the second copy turns.
TEST(SoupOrientation, ConsistentPatchesAreWoundEachOnItsOwn) {
  const TriangleMesh m = fertility();
  TriangleMesh two = m;
  for (const Vec3& p : m.positions) two.positions.push_back(p + Vec3{500, 0, 0});
  const Index n = Index(m.num_vertices());
  for (Triangle t : m.triangles) two.triangles.push_back({t[0] + n, t[2] + n, t[1] + n});
  detail::IntrinsicTriangulation t = from_mesh(two);
  t.positions = &two.positions;
  t.skipped[0] = true;   // the first copy opens up: wound outwards still
  const std::vector<Triangle> before = t.triangles;
  EXPECT_EQ(detail::orient_consistently(t), m.num_faces());
  for (std::size_t f = 0; f < two.num_faces(); ++f) {
    const Triangle& a = t.triangles[f];
    const Triangle& b = before[f];
    if (f < m.num_faces()) EXPECT_EQ(a, b);
    else EXPECT_EQ(a, (Triangle{b[0], b[2], b[1]}));
  }
  for (Index h = 0; h < Index(t.length.size()); ++h) EXPECT_EQ(t.ring[t.ring[h]], h);
}

TEST(SoupOrientation, WithoutPositionsTheMajorityWindingWins) {
  const TriangleMesh m = fertility();
  std::vector<Index> original_of;
  SplitMix rng{5};
  const TriangleMesh soup = flipped_soup(m, [&](std::size_t) { return rng.uniform() < 0.3; }, original_of);
  detail::IntrinsicTriangulation t = from_mesh(soup);
  const std::size_t reversed = detail::orient_consistently(t);
  EXPECT_GT(reversed, m.num_faces() / 5);
  EXPECT_LT(reversed, m.num_faces() / 2);
  EXPECT_EQ(faces_as_original(t, m, original_of), m.num_faces());
}

// A Moebius strip: n quads around a circle, the outer row shifted by 0.8 of a quad so that
// the diagonal each quad is split along is the long one (far from Delaunay), the band making
// half a turn. However its faces are wound, some edge has two
// faces wound the same way; the flips must still keep the surface and end Delaunay.
TriangleMesh moebius(int n) {
  TriangleMesh m;
  for (int i = 0; i < n; ++i) {
    for (double v : {-0.3, 0.3}) {
      const double u = 2 * kPi * (i + (v > 0 ? 0.8 : 0.0)) / n;
      const double r = 1 + v * std::cos(u / 2);
      m.positions.push_back({r * std::cos(u), r * std::sin(u), v * std::sin(u / 2)});
    }
  }
  for (int i = 0; i < n; ++i) {
    const Index a = 2 * i, b = 2 * i + 1;
    // The last quad joins the strip's start with its sides swapped (the half turn).
    const Index c = i + 1 < n ? 2 * (i + 1) : 1, d = i + 1 < n ? 2 * (i + 1) + 1 : 0;
    m.triangles.push_back({a, c, d});
    m.triangles.push_back({a, d, b});
  }
  return m;
}

double corner_angle(double a, double b, double opposite) {
  return std::acos(std::clamp((a * a + b * b - opposite * opposite) / (2 * a * b), -1.0, 1.0));
}

TEST(SoupOrientation, FlipsAcrossInconsistentlyWoundEdges) {
  const TriangleMesh m = moebius(40);
  detail::IntrinsicTriangulation t = from_mesh(m);
  t.positions = &m.positions;
  auto angle_sums = [&](const detail::IntrinsicTriangulation& x) {
    std::vector<double> s(m.num_vertices(), 0);
    for (std::size_t f = 0; f < x.triangles.size(); ++f) {
      const double l[3] = {x.length[3 * f], x.length[3 * f + 1], x.length[3 * f + 2]};
      for (int i = 0; i < 3; ++i) s[x.triangles[f][i]] += corner_angle(l[i], l[(i + 2) % 3], l[(i + 1) % 3]);
    }
    return s;
  };
  const std::vector<double> before = angle_sums(t);
  const std::size_t flips = detail::make_intrinsic_delaunay(t, 10000);
  EXPECT_GT(flips, 0u);
  const std::vector<double> after = angle_sums(t);
  for (std::size_t v = 0; v < m.num_vertices(); ++v) EXPECT_NEAR(after[v], before[v], 1e-9) << v;
  std::size_t same_way = 0;
  for (Index h = 0; h < Index(t.length.size()); ++h) {
    const Index g = t.ring[h];
    if (g == h) continue;
    ASSERT_EQ(t.ring[g], h);
    EXPECT_NEAR(t.length[g], t.length[h], 1e-12);
    same_way += t.triangles[face_of(h)][corner_of(h)] == t.triangles[face_of(g)][corner_of(g)];
    const double a1 = corner_angle(t.length[next_halfedge(h)], t.length[prev_halfedge(h)], t.length[h]);
    const double a2 = corner_angle(t.length[next_halfedge(g)], t.length[prev_halfedge(g)], t.length[g]);
    EXPECT_LE(a1 + a2, kPi + 1e-9) << h;
  }
  EXPECT_GT(same_way, 0u);   // the seam is still there: the strip cannot be wound consistently
}

}  // namespace
}  // namespace gsp::test
