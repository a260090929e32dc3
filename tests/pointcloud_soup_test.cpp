// Triangle soups (issue item 2, library side): a benign mesh split into separate triangles
// (every vertex duplicated per face), half the faces flipped, welded again with
// gsp::weld_vertices, gives the welded original's geodesics through the mesh core, for
// bit-identical copies and, with a weld tolerance, for positions jittered by 1e-7 of the
// bounding box.
#include "helpers/geodesic_fixtures.hpp"

#include <gsp/geodesics.hpp>
#include <gsp/io/mesh_io.hpp>
#include <gsp/weld.hpp>

#include <gtest/gtest.h>

#include <cmath>

namespace gsp::test {
namespace {

TriangleMesh fertility() { return io::read_mesh(std::string(GSP_TEST_DIR) + "/../data/samples/fertility.off").mesh; }

// Every face gets its own three vertices; odd faces are flipped (corners 1 and 2 swapped);
// positions move by up to `jitter` per coordinate. soup_of[c] = original vertex of soup vertex c.
TriangleMesh split_and_flip(const TriangleMesh& m, double jitter, bool flip, std::vector<Index>& soup_of) {
  SplitMix rng{99};
  TriangleMesh soup;
  soup_of.clear();
  for (std::size_t f = 0; f < m.num_faces(); ++f) {
    Triangle t = m.triangles[f];
    if (flip && f % 2) std::swap(t[1], t[2]);
    Triangle s;
    for (int c = 0; c < 3; ++c) {
      s[c] = Index(soup.positions.size());
      Vec3 p = m.positions[t[c]];
      p = p + jitter * Vec3{2 * rng.uniform() - 1, 2 * rng.uniform() - 1, 2 * rng.uniform() - 1};
      soup.positions.push_back(p);
      soup_of.push_back(t[c]);
    }
    soup.triangles.push_back(s);
  }
  return soup;
}

struct Difference {
  double max = 0;    // over vertices farther than 1% of the largest distance
  double mean = 0;   // over all vertices but the source
};

// Relative difference of the welded soup's distances (mapped back through the weld map to
// every soup vertex) from the original's at the soup vertex's original vertex.
Difference relative_difference(const TriangleMesh& original, const TriangleMesh& soup,
                               const std::vector<Index>& soup_of, double tolerance) {
  const WeldResult welded = weld_vertices(soup, tolerance);
  EXPECT_EQ(welded.mesh.num_vertices(), original.num_vertices());
  const Index source_original = 123;
  Index source_soup = kInvalidIndex;
  for (Index c = 0; c < soup_of.size(); ++c)
    if (soup_of[c] == source_original) source_soup = c;
  const auto ref = GeodesicSolver(original).compute({Source::at_vertex(source_original)}).vertex_distance;
  const auto got = GeodesicSolver(welded.mesh).compute({Source::at_vertex(welded.vertex_map[source_soup])}).vertex_distance;
  const auto per_soup_vertex = unweld_values(got, welded.vertex_map);
  double dmax = 0;
  for (double d : ref) dmax = std::max(dmax, d);
  Difference diff;
  for (std::size_t c = 0; c < soup_of.size(); ++c) {
    const double r = ref[soup_of[c]];
    EXPECT_TRUE(std::isfinite(per_soup_vertex[c])) << c;
    if (r > 0.01 * dmax) diff.max = std::max(diff.max, std::abs(per_soup_vertex[c] - r) / r);
    if (r > 0) diff.mean += std::abs(per_soup_vertex[c] - r) / r / double(soup_of.size());
  }
  return diff;
}

void report(const char* what, const Difference& d) {
  std::printf("soup (%s): relative difference max %.2e, mean %.2e\n", what, d.max, d.mean);
}

TEST(Soup, SplitAndWeldedMatchesTheOriginal) {
  const TriangleMesh m = fertility();
  std::vector<Index> soup_of;
  const TriangleMesh soup = split_and_flip(m, 0.0, false, soup_of);
  ASSERT_EQ(soup.num_vertices(), 3 * m.num_faces());
  const Difference d = relative_difference(m, soup, soup_of, 0.0);
  report("split, exact weld", d);
  EXPECT_LT(d.max, 1e-3);   // the 0.1% per vertex
}

TEST(Soup, TinyGapsWeldedWithATolerance) {
  const TriangleMesh m = fertility();
  const double diag = bbox_diagonal(m);
  std::vector<Index> soup_of;
  const TriangleMesh soup = split_and_flip(m, 1e-7 * diag, false, soup_of);
  EXPECT_EQ(weld_vertices(soup, 0.0).merged, 0u);   // nothing is bit-identical any more
  const Difference d = relative_difference(m, soup, soup_of, 1e-5 * diag);
  report("split, 1e-7 gaps, weld tolerance 1e-5", d);
  EXPECT_LT(d.max, 1e-3);
}

// Half the faces flipped: the core connects them (radial rings ignore orientation), and its
// intrinsic Delaunay step winds the faces consistently before flipping (intrinsic_delaunay.hpp),
// so the flips and the propagation see the original's triangles. Exactly half the faces are
// flipped here, a tie no majority can break, and GSP is not bit-for-bit mirror-symmetric
// (fertility mirrored: max 0.9%, mean 0.03%): the solver hands the mesh positions to the step,
// which winds closed patches outwards. Measured: max 3.1e-7, mean 1.1e-8; with 1e-7 gaps
// welded by tolerance max 1.8e-5 (before the winding step: mean 1.9e-3, max 3.6e-2).
// Asserted: the 0.1%, on every vertex.
TEST(Soup, FlippedFacesStayClose) {
  const TriangleMesh m = fertility();
  const double diag = bbox_diagonal(m);
  std::vector<Index> soup_of;
  for (double jitter : {0.0, 1e-7 * diag}) {
    const TriangleMesh soup = split_and_flip(m, jitter, true, soup_of);
    const Difference d = relative_difference(m, soup, soup_of, jitter > 0 ? 1e-5 * diag : 0.0);
    report(jitter > 0 ? "split, half flipped, 1e-7 gaps" : "split, half flipped", d);
    EXPECT_LT(d.mean, 1e-5);
    EXPECT_LT(d.max, 1e-3);
  }
}

}  // namespace
}  // namespace gsp::test
