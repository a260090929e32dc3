// gsp::cvt quality figures and closest points: closed forms on small meshes, the Embree index
// against the library's linear scan, Hausdorff distances of shifted planes.
#include "cvt_meshes.hpp"
#include "test_data.hpp"

#include <gsp/closest_point.hpp>
#include <gsp/cvt/closest_point_index.hpp>
#include <gsp/cvt/cvt.hpp>
#include <gsp/cvt/quality.hpp>
#include <gsp/cvt/remesh.hpp>
#include <gsp/errors.hpp>
#include <gsp/io/mesh_io.hpp>
#include <gsp/sampling/random.hpp>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <map>
#include <vector>

namespace {

using namespace gsp;

TEST(CvtQuality, EquilateralAndRightTriangles) {
  TriangleMesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0.5, std::sqrt(3.0) / 2, 0}};
  m.triangles = {{0, 1, 2}};
  cvt::MeshQuality q = cvt::measure_mesh_quality(m);
  EXPECT_NEAR(q.min_angle, 60.0, 1e-9);
  EXPECT_NEAR(q.max_angle, 60.0, 1e-9);
  EXPECT_NEAR(q.mean_aspect_ratio, 1.0, 1e-12);
  EXPECT_EQ(q.below_30, 0.0);
  EXPECT_EQ(q.vertices, 3u);
  ASSERT_EQ(q.valence_histogram.size(), 3u);
  EXPECT_EQ(q.valence_histogram[2], 3u);

  // Right isosceles: 45/45/90; AR = sqrt2 * (2 + sqrt2) / (4 sqrt3 * 1/2).
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  q = cvt::measure_mesh_quality(m);
  EXPECT_NEAR(q.min_angle, 45.0, 1e-9);
  EXPECT_NEAR(q.max_angle, 90.0, 1e-9);
  EXPECT_NEAR(q.mean_aspect_ratio, std::sqrt(2.0) * (2 + std::sqrt(2.0)) / (2 * std::sqrt(3.0)), 1e-12);

  // A 1 x 10 sliver: 2 of its 3 angles are below 30 degrees; plus one degenerate triangle.
  m.positions = {{0, 0, 0}, {10, 0, 0}, {5, 1, 0}, {20, 0, 0}};
  m.triangles = {{0, 1, 2}, {0, 1, 3}};
  q = cvt::measure_mesh_quality(m);
  EXPECT_EQ(q.degenerate, 1u);
  EXPECT_NEAR(q.below_30, 2.0 / 3.0, 1e-12);
  EXPECT_NEAR(q.min_angle, std::atan(0.2) * 180 / M_PI, 1e-9);
}

TEST(CvtQuality, GridValences) {
  // Interior vertex (i, j) of the alternating 4 x 4 grid: valence 8 when i + j is odd (all
  // four diagonals end there; 4 such vertices), else 4. Valences sum to twice the edge count
  // (20 + 20 axis edges, 16 diagonals).
  const TriangleMesh m = test::square_grid(4);
  const cvt::MeshQuality q = cvt::measure_mesh_quality(m);
  EXPECT_EQ(q.vertices, 25u);
  ASSERT_EQ(q.valence_histogram.size(), 9u);
  EXPECT_EQ(q.valence_histogram[8], 4u);
  std::size_t sum = 0, count = 0;
  for (std::size_t k = 0; k < q.valence_histogram.size(); ++k) sum += k * q.valence_histogram[k], count += q.valence_histogram[k];
  EXPECT_EQ(sum, 2u * 56u);
  EXPECT_EQ(count, 25u);
  EXPECT_NEAR(q.mean_edge_length, (40 * 0.25 + 16 * 0.25 * std::sqrt(2.0)) / 56, 1e-12);
}

TEST(CvtRemeshFlips, RaiseAnglesKeepVerticesAndCount) {
  // restricted_delaunay with and without the edge flips on one (deliberately unconverged) CVT.
  const TriangleMesh m = test::square_grid(24);
  cvt::CvtOptions o;
  o.sites = 120;
  o.max_iterations = 3;   // not converged: some dual edges are not Delaunay
  const cvt::CvtResult cvt = cvt::compute_cvt(m, o);
  cvt::RemeshOptions no, flips_only;
  no.flip_edges = false;
  no.smooth = flips_only.smooth = false;   // the post-pass moves vertices (cvt_smoothing_test)
  const cvt::RemeshResult a = cvt::restricted_delaunay(cvt, no), b = cvt::restricted_delaunay(cvt, flips_only);
  EXPECT_EQ(a.stats.flips, 0u);
  EXPECT_EQ(a.mesh.num_faces(), b.mesh.num_faces());
  EXPECT_EQ(a.mesh.positions, b.mesh.positions);
  const cvt::MeshQuality qa = cvt::measure_mesh_quality(a.mesh), qb = cvt::measure_mesh_quality(b.mesh);
  EXPECT_GE(qb.min_angle, qa.min_angle);
  if (b.stats.flips > 0) EXPECT_GT(qb.mean_min_angle, qa.mean_min_angle);
  // Flat input: after the flips no interior edge of the (planar) dual is non-Delaunay.
  std::map<std::pair<Index, Index>, Index> opposite;
  for (const Triangle& t : b.mesh.triangles)
    for (int i = 0; i < 3; ++i) opposite[{t[i], t[(i + 1) % 3]}] = t[(i + 2) % 3];
  auto angle = [&](Index p, Index q, Index r) {
    const Vec3 u = b.mesh.positions[q] - b.mesh.positions[p], v = b.mesh.positions[r] - b.mesh.positions[p];
    return std::atan2(norm(cross(u, v)), dot(u, v));
  };
  std::size_t non_delaunay = 0;
  for (const auto& [edge, c] : opposite) {
    const auto other = opposite.find({edge.second, edge.first});
    if (other == opposite.end()) continue;
    non_delaunay += angle(c, edge.first, edge.second) + angle(other->second, edge.second, edge.first) > M_PI + 1e-9;
  }
  // A flip that would not raise the smaller minimum angle is not made, so a few may remain.
  EXPECT_LE(non_delaunay, 2u * 2u);
}

TriangleMesh fertility() { return io::read_mesh(std::string(GSP_TEST_DIR) + "/../data/samples/fertility.off").mesh; }

// A point in the box grown by 20% on every side: inside the mesh, outside it and far away.
Vec3 point_around(const BoundingBox& box, sampling::Random& random) {
  const Vec3 lo = box.min, hi = box.max;
  auto at = [&](double a, double b) { return a + (b - a) * (1.4 * random.uniform() - 0.2); };
  return {at(lo.x, hi.x), at(lo.y, hi.y), at(lo.z, hi.z)};   // a braced list: drawn in this order
}

TEST(CvtClosestPoint, MatchesLinearScan) {
  const TriangleMesh m = fertility();
  const cvt::ClosestPointIndex index(m);
  sampling::Random random(7);
  const BoundingBox box = bounding_box(m);
  for (int i = 0; i < 300; ++i) {
    const Vec3 p = point_around(box, random);
    const ClosestPoint a = index.closest(p), b = closest_surface_point(m, p);
    ASSERT_NE(a.point.element, kInvalidIndex);
    EXPECT_NEAR(a.distance, b.distance, 1e-9 * (1 + b.distance));
    EXPECT_NEAR(distance(a.position, p), a.distance, 1e-9 * (1 + a.distance));
  }
  // within(p, r) is closest(p).distance <= r: at, just below and just above each point's own
  // distance, at 0, and for points on the surface (vertices: distance 0).
  for (int i = 0; i < 300; ++i) {
    const Vec3 p = point_around(box, random);
    const double d = index.closest(p).distance;
    for (double r : {d, d * (1 - 1e-9), d * (1 + 1e-9), 0.5 * d, 2 * d, 0.0})
      EXPECT_EQ(index.within(p, r), d <= r) << "point " << i << " r " << r << " distance " << d;
  }
  for (Index v = 0; v < m.num_vertices(); v += 97) {
    EXPECT_TRUE(index.within(m.positions[v], 0.0));
    EXPECT_TRUE(index.within(m.positions[v], 1e-12));
  }
  EXPECT_FALSE(index.within(box.min, -1.0));
  TriangleMesh none;
  none.positions = {{0, 0, 0}, {1, 0, 0}};
  none.triangles = {{0, 0, 1}};
  EXPECT_THROW(cvt::ClosestPointIndex{none}, InvalidInput);
}

// A point as near to several faces (a vertex of the grid, the middle of an edge) gets the
// lowest-numbered of them, whatever order the BVH is walked in.
TEST(CvtClosestPoint, TiesGoToTheLowestFace) {
  const TriangleMesh m = test::square_grid(8);
  const cvt::ClosestPointIndex index(m);
  for (Index v = 0; v < m.num_vertices(); ++v) {
    const Vec3 p = m.positions[v] + Vec3{0, 0, 0.25};
    Index lowest = kInvalidIndex;
    for (Index f = 0; f < m.num_faces() && lowest == kInvalidIndex; ++f)
      for (Index k : m.triangles[f])
        if (k == v) lowest = f;
    const ClosestPoint c = index.closest(p);
    EXPECT_EQ(c.point.element, lowest) << "vertex " << v;
    EXPECT_DOUBLE_EQ(c.distance, 0.25);
  }
}

// A hint (a face to start the search from) changes how fast, never what: closest(p, hint) is
// closest(p) to the last bit, whatever face the hint names, near or far; within(p, r, hint)
// is within(p, r), and a hint it returns is a face within r.
TEST(CvtClosestPoint, HintsChangeNothing) {
  const TriangleMesh m = fertility();
  const cvt::ClosestPointIndex index(m);
  sampling::Random random(11);
  const BoundingBox box = bounding_box(m);
  for (int i = 0; i < 300; ++i) {
    const Vec3 p = point_around(box, random);
    const ClosestPoint plain = index.closest(p);
    const Index far = Index(random.uniform() * double(m.num_faces())) % Index(m.num_faces());
    // The answer itself and the face after it in the file (mostly a neighbour): the hints a
    // search of nearby points passes.
    const Index f = plain.point.element;
    const Index next = f + 1 < m.num_faces() ? f + 1 : f - 1;
    for (Index hint : {far, f, next}) {
      const ClosestPoint h = index.closest(p, hint);
      EXPECT_EQ(h.point.element, f) << "point " << i << " hint " << hint;
      EXPECT_EQ(h.distance, plain.distance) << "point " << i << " hint " << hint;
    }
    for (double r : {plain.distance, 0.5 * plain.distance, 2 * plain.distance}) {
      Index hint = far;
      const bool found = index.within(p, r, hint);
      EXPECT_EQ(found, index.within(p, r)) << "point " << i << " r " << r;
      if (found) {
        const Triangle& t = m.triangles[hint];
        const std::array<double, 3> w = closest_point_on_triangle(p, m.positions[t[0]], m.positions[t[1]], m.positions[t[2]]);
        EXPECT_LE(distance(p, w[0] * m.positions[t[0]] + w[1] * m.positions[t[1]] + w[2] * m.positions[t[2]]), r);
      }
    }
  }
}

// Ties with a hint: a point at distance 0 from several faces (a grid vertex, on the surface:
// the float boxes' rounding matters most there) gets the lowest of them whichever of them the
// search starts from.
TEST(CvtClosestPoint, TiesGoToTheLowestFaceFromAnyHint) {
  const TriangleMesh m = test::square_grid(8);
  const cvt::ClosestPointIndex index(m);
  for (Index v = 0; v < m.num_vertices(); ++v) {
    std::vector<Index> around;
    for (Index f = 0; f < m.num_faces(); ++f)
      for (Index k : m.triangles[f])
        if (k == v) around.push_back(f);
    for (double lift : {0.0, 0.25})
      for (Index hint : around) {
        const ClosestPoint c = index.closest(m.positions[v] + Vec3{0, 0, lift}, hint);
        EXPECT_EQ(c.point.element, around.front()) << "vertex " << v << " hint " << hint;
        EXPECT_DOUBLE_EQ(c.distance, lift);
      }
  }
}

// An index over a mesh whose edges were flipped after it was built (positions kept), asked
// besides the flipped faces (ClosestPointIndex::on_face, ties to the lower face), answers as
// an index built anew does, to the last bit: the cap flips of the post-pass rely on it.
TEST(CvtClosestPoint, FlippedFacesAskedBesideAStaleIndex) {
  for (const TriangleMesh& original : {fertility(), test::square_grid(8)}) {
    TriangleMesh m = original;
    const cvt::ClosestPointIndex stale(m);
    std::map<std::pair<Index, Index>, Index> directed;   // (a, b) -> face
    for (Index f = 0; f < m.num_faces(); ++f)
      for (int k = 0; k < 3; ++k) directed[{m.triangles[f][k], m.triangles[f][(k + 1) % 3]}] = f;
    std::vector<Index> flipped;
    sampling::Random random(5);
    for (int tries = 0; tries < 400 && flipped.size() < 40; ++tries) {
      const Index f = Index(random.uniform() * double(m.num_faces())) % Index(m.num_faces());
      const Triangle t = m.triangles[f];
      const Index a = t[0], b = t[1], c = t[2];
      const auto twin = directed.find({b, a});
      if (twin == directed.end()) continue;
      const Index g = twin->second;
      Index d = kInvalidIndex;
      for (Index k : m.triangles[g])
        if (k != a && k != b) d = k;
      if (d == kInvalidIndex || directed.count({c, d}) || directed.count({d, c})) continue;
      for (const Triangle& old : {m.triangles[f], m.triangles[g]})
        for (int k = 0; k < 3; ++k) directed.erase({old[k], old[(k + 1) % 3]});
      m.triangles[f] = {a, d, c};
      m.triangles[g] = {d, b, c};
      for (Index h : {f, g})
        for (int k = 0; k < 3; ++k) directed[{m.triangles[h][k], m.triangles[h][(k + 1) % 3]}] = h;
      flipped.push_back(f), flipped.push_back(g);
    }
    ASSERT_GE(flipped.size(), 20u);
    const cvt::ClosestPointIndex fresh(m);
    std::vector<Vec3> points;
    const BoundingBox box = bounding_box(m);
    for (int i = 0; i < 300; ++i) points.push_back(point_around(box, random));
    for (Index f : flipped)   // on and just off the flipped faces, and at their corners (ties)
      for (Index v : m.triangles[f]) points.push_back(m.positions[v]), points.push_back(m.positions[v] + Vec3{0, 0, 0.01});
    for (const Vec3& p : points) {
      ClosestPoint best = stale.closest(p);
      for (Index h : flipped) {
        const ClosestPoint r = stale.on_face(h, p);
        if (r.distance < best.distance || (r.distance == best.distance && h < best.point.element)) best = r;
      }
      const ClosestPoint want = fresh.closest(p);
      EXPECT_EQ(best.point.element, want.point.element);
      EXPECT_EQ(best.distance, want.distance);
    }
  }
}

TEST(CvtHausdorff, ShiftedSquares) {
  const TriangleMesh a = test::square_grid(6);
  TriangleMesh b = test::square_grid(3);
  for (Vec3& p : b.positions) p.z = 0.05;
  cvt::HausdorffOptions o;
  o.samples = 2000;
  cvt::HausdorffDistance h = cvt::hausdorff_distance(a, b, o);
  EXPECT_NEAR(h.a_to_b, 0.05, 1e-12);
  EXPECT_NEAR(h.b_to_a, 0.05, 1e-12);
  EXPECT_NEAR(h.mean, 0.05, 1e-12);
  EXPECT_NEAR(h.relative, 0.05 / std::sqrt(2.0), 1e-12);
  // Shifted sideways by 0.1 in x: points of the overhanging strip are 0.1 from the other square.
  for (Vec3& p : b.positions) p = {p.x + 0.1, p.y, 0.0};
  h = cvt::hausdorff_distance(a, b, o);
  EXPECT_NEAR(h.a_to_b, 0.1, 1e-12);   // vertices x = 0 are sampled exactly
  EXPECT_NEAR(h.b_to_a, 0.1, 1e-12);
  EXPECT_LT(h.mean, 0.1 * 0.1);        // only a 10% strip is off
}

}  // namespace
