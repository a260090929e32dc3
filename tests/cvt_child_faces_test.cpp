// Which working face holds a point of an input face (extensions/cvt/src/child_faces.*): the
// grid over an input face's barycentric plane must pick the face a scan of all its children
// picks (the first at the least distance), on uniform splits, on bisected slivers, and for
// points on shared edges and corners.
#include "child_faces.hpp"
#include "working_geometry.hpp"

#include "helpers/mesh_builders.hpp"

#include <gsp/cvt/cvt.hpp>

#include <gtest/gtest.h>

#include <limits>
#include <random>

namespace {

using namespace gsp;
using cvt::detail::ChildFaces;
using cvt::detail::SurfaceSite;
using cvt::detail::WorkingGeometry;

SurfaceSite scan(const cvt::WorkingMesh& w, const WorkingGeometry& g, Index parent, Vec3 p) {
  SurfaceSite best;
  double best_d = std::numeric_limits<double>::infinity();
  for (Index f = 0; f < w.parent.size(); ++f) {
    if (w.parent[f] != parent) continue;
    const SurfaceSite q = g.closest_on_face(f, p);
    if (const double d = distance(q.position, p); d < best_d) best_d = d, best = q;
  }
  return best;
}

// Random points and the children's own corners (on shared edges and vertices), each located
// both ways; returns how many parents had a grid's worth of children.
void check_against_scan(const TriangleMesh& input, const cvt::WorkingMesh& w) {
  const WorkingGeometry g(w.mesh);
  const ChildFaces children(w, input.num_faces());
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> u(0, 1);
  auto check = [&](Index parent, std::array<double, 3> b) {
    const Triangle& t = input.triangles[parent];
    const Vec3 p = b[0] * input.positions[t[0]] + b[1] * input.positions[t[1]] + b[2] * input.positions[t[2]];
    const SurfaceSite expected = scan(w, g, parent, p);
    const SurfaceSite got = children.closest(g, parent, b, p);
    ASSERT_EQ(got.point.element, expected.point.element) << "parent " << parent;
    EXPECT_EQ(got.position, expected.position);
  };
  for (Index parent = 0; parent < input.num_faces(); ++parent) {
    for (int i = 0; i < 200; ++i) {
      double b1 = u(random), b2 = u(random);
      if (b1 + b2 > 1) b1 = 1 - b1, b2 = 1 - b2;
      check(parent, {1 - b1 - b2, b1, b2});
    }
    for (Index f = 0; f < w.parent.size(); f += 7)
      if (w.parent[f] == parent)
        for (int k = 0; k < 3; ++k) check(parent, w.corner_bary[f][k]);
  }
}

TEST(CvtChildFaces, UniformSplitsOfOneTriangle) {
  const TriangleMesh m = test::single_triangle();
  check_against_scan(m, cvt::subdivide(m, 5));   // 1,024 children: the grid
  check_against_scan(m, cvt::subdivide(m, 2));   // 16: the scan
}

TEST(CvtChildFaces, BisectedSliversAndSplits) {
  // A needle 200 long and 1 wide, and a square beside it: bisection makes irregular
  // children of different sizes in one input face before the uniform levels.
  TriangleMesh m;
  m.positions = {{0, 0, 0}, {200, 0, 0}, {0, 1, 0}, {0, -5, 0}, {5, -5, 0}};
  m.triangles = {{0, 1, 2}, {0, 3, 4}, {0, 4, 1}};
  cvt::WorkingMesh w = cvt::subdivide(m, 0);
  ASSERT_GT(cvt::refine_long_edges(w, 2.0, 100000), 0u);
  cvt::subdivide(w, 2);
  check_against_scan(m, w);
}

}  // namespace
