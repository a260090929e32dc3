// gsp::SurfacePoint: positions of vertices and face points, the existence checks and their
// messages, the barycentric test, and Source as a surface point with an offset.
#include <gsp/closest_point.hpp>
#include <gsp/errors.hpp>
#include <gsp/geodesics.hpp>
#include <gsp/surface_point.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string>

namespace gsp {
namespace {

TriangleMesh two_triangles() {
  TriangleMesh m;
  m.positions = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {2, 2, 1}};
  m.triangles = {{0, 1, 2}, {1, 3, 2}};
  return m;
}

std::string message_of(const SurfacePoint& p, const TriangleMesh& m) {
  try {
    p.position(m);
  } catch (const InvalidInput& e) {
    return e.what();
  }
  return "";
}

TEST(CoreSurfacePoint, PositionsOfVerticesAndFacePoints) {
  const TriangleMesh m = two_triangles();
  EXPECT_EQ(SurfacePoint::at_vertex(3).position(m), (Vec3{2, 2, 1}));
  EXPECT_EQ(SurfacePoint::in_face(0, {0.5, 0.25, 0.25}).position(m), (Vec3{0.5, 0.5, 0}));
  // Corner order of the face, not of the vertices: weight 1 on corner 1 of face 1 is vertex 3.
  EXPECT_EQ(SurfacePoint::in_face(1, {0, 1, 0}).position(m), (Vec3{2, 2, 1}));
  EXPECT_TRUE(SurfacePoint::at_vertex(0).is_vertex());
  EXPECT_FALSE(SurfacePoint::in_face(0, {1, 0, 0}).is_vertex());
}

TEST(CoreSurfacePoint, MissingElementsAreNamed) {
  const TriangleMesh m = two_triangles();
  EXPECT_TRUE(SurfacePoint::at_vertex(3).exists_in(m));
  EXPECT_FALSE(SurfacePoint::at_vertex(4).exists_in(m));
  EXPECT_TRUE(SurfacePoint::in_face(1, {1, 0, 0}).exists_in(m));
  EXPECT_FALSE(SurfacePoint::in_face(2, {1, 0, 0}).exists_in(m));
  EXPECT_EQ(message_of(SurfacePoint::at_vertex(4), m), "vertex 4 does not exist (4 vertices)");
  EXPECT_EQ(message_of(SurfacePoint::in_face(2, {1, 0, 0}), m), "face 2 does not exist (2 faces)");
  EXPECT_EQ(message_of(SurfacePoint::in_face(kInvalidIndex, {1, 0, 0}), m),
            "face 4294967295 does not exist (2 faces)");
}

TEST(CoreSurfacePoint, BarycentricWeights) {
  EXPECT_TRUE(are_barycentric({1, 0, 0}));
  EXPECT_TRUE(are_barycentric({0.2, 0.3, 0.5 + 5e-7}));
  EXPECT_FALSE(are_barycentric({0.2, 0.3, 0.5 + 2e-6}));
  EXPECT_FALSE(are_barycentric({-1e-12, 0.5, 0.5}));
  EXPECT_FALSE(are_barycentric({std::nan(""), 0.5, 0.5}));
}

TEST(CoreSurfacePoint, SourceIsAPointWithAnOffset) {
  const Source v = Source::at_vertex(7, 1.5);
  EXPECT_EQ(v.kind, Source::Kind::vertex);
  EXPECT_EQ(v.element, 7u);
  EXPECT_EQ(v.offset, 1.5);
  const Source f = Source::in_face(2, {0.2, 0.3, 0.5});
  EXPECT_EQ(f.kind, SurfacePoint::Kind::face_point);
  EXPECT_EQ(f.barycentric, (std::array<double, 3>{0.2, 0.3, 0.5}));
  EXPECT_EQ(f.offset, 0.0);
  const Source s = Source::at(SurfacePoint::in_face(1, {0, 0, 1}), 2);
  EXPECT_EQ(s.element, 1u);
  EXPECT_EQ(s.offset, 2.0);
  const Source d;   // vertex 0, as Source always defaulted to
  EXPECT_TRUE(d.is_vertex());
  EXPECT_EQ(d.element, 0u);
}

TEST(CoreSurfacePoint, ClosestPointIsAFacePoint) {
  const TriangleMesh m = two_triangles();
  const ClosestPoint c = closest_surface_point(m, {0.25, 0.25, 1});
  EXPECT_FALSE(c.point.is_vertex());
  EXPECT_EQ(c.point.element, 0u);
  EXPECT_NEAR(c.distance, 1.0, 1e-12);
  // The same arithmetic as the query's own position: equal to the bit.
  EXPECT_EQ(c.point.position(m), c.position);
}

// Points a hair inside a triangle from one of its edges: the weights must stay barycentric (no
// weight rounding below 0), so such a closest point is a valid source. Before, 1 - v - w gave
// about -1e-16 for 2.7% of them and the solver refused the source.
TEST(CoreSurfacePoint, ClosestPointWeightsNearAnEdgeStayBarycentric) {
  std::uint64_t state = 12345;
  auto uniform = [&] {   // splitmix64 -> [-1, 1)
    std::uint64_t z = (state += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return double((z ^ (z >> 31)) >> 11) * 0x1.0p-52 - 1.0;
  };
  int refused = 0;
  for (int i = 0; i < 200000; ++i) {
    const Vec3 a{uniform(), uniform(), uniform()}, b{uniform(), uniform(), uniform()}, c{uniform(), uniform(), uniform()};
    const double t = 0.5 * (uniform() + 1), eps = std::ldexp(1.0, -40 - i % 20);
    Vec3 q = (1 - t) * b + t * c;
    q = q + eps * (a - q) + 1e-3 * uniform() * cross(b - a, c - a);
    refused += !are_barycentric(closest_point_on_triangle(q, a, b, c));
  }
  EXPECT_EQ(refused, 0);
}

// A CAD needle (aspect ratio about 1e7, as in a 3D-printing STL): points on the face a little
// off its plane project onto the face itself. The textbook region tests took the weights from
// differences of products of dot products and lost (aspect)^2 of the digits: weights off by
// 10% of the 40-unit edge, and a path lying on such a face read as off the surface.
TEST(CoreSurfacePoint, ClosestPointOnANeedleIsOnTheFace) {
  const Vec3 a{0, 0, 0}, b{40, 0, 0}, c{20, 4e-6, 0};
  const Vec3 n{0, 0, 1};
  double worst = 0;
  for (int i = 1; i < 100; ++i) {
    const double wb = 0.01 * i, wc = 0.3 * std::fmod(0.37 * i, 1.0) * (1 - wb) + 0.01;
    const Vec3 on = (1 - wb - wc) * a + wb * b + wc * c;
    const Vec3 q = on + (1e-3 * ((i % 3) - 1)) * n;
    const std::array<double, 3> w = closest_point_on_triangle(q, a, b, c);
    ASSERT_TRUE(are_barycentric(w)) << i;
    worst = std::max(worst, distance(w[0] * a + w[1] * b + w[2] * c, on));
  }
  EXPECT_LT(worst, 1e-9 * 40);
}

// A triangle with two corners at one position (exporters leave them at a sphere's poles):
// the closest point is on its one segment, never NaN, for points all around it. A NaN here
// once stopped gsp-cvt's closest-point searches early: 184 of a capsule's faces could not
// find their own centroids.
TEST(CoreSurfacePoint, ClosestPointOnATriangleWithTwoCornersAtOnePlace) {
  const Vec3 pole{0, 0, -1.5}, ring{-0.0231, 0.0584, -1.498};
  for (int k = 0; k < 3; ++k)
    for (const Vec3& q : {Vec3{-0.0109, 0.0331, -1.4984}, Vec3{0.3, -0.2, -1.7}, Vec3{0, 0, 2}, pole, ring,
                          0.5 * (pole + ring) + Vec3{0.01, 0, 0}}) {
      std::array<Vec3, 3> t = {pole, pole, ring};
      std::rotate(t.begin(), t.begin() + k, t.end());
      const std::array<double, 3> w = closest_point_on_triangle(q, t[0], t[1], t[2]);
      ASSERT_TRUE(are_barycentric(w)) << "corner order " << k;
      const Vec3 x = w[0] * t[0] + w[1] * t[1] + w[2] * t[2];
      // The closest point of the segment pole-ring, by its own formula.
      const Vec3 d = ring - pole;
      const double s = std::clamp(dot(q - pole, d) / dot(d, d), 0.0, 1.0);
      EXPECT_NEAR(distance(q, x), distance(q, pole + s * d), 1e-12) << "corner order " << k;
    }
}

}  // namespace
}  // namespace gsp
