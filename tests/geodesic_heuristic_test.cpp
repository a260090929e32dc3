// The visibility heuristic as data: presets, text round trip, validation, and its effect
// (the conservative probe over-estimates, the centroid under-estimates on a curved mesh).
#include "helpers/geodesic_fixtures.hpp"

#include <gsp/errors.hpp>
#include <gsp/geodesics.hpp>
#include <gsp/heuristic.hpp>

#include <gtest/gtest.h>

namespace gsp::test {
namespace {

TEST(Heuristic, PresetsRoundTripThroughText) {
  for (const VisibilityHeuristic& h : {VisibilityHeuristic::published(), VisibilityHeuristic::trained(),
                                       VisibilityHeuristic::centroid(), VisibilityHeuristic::opposite_corner()}) {
    const VisibilityHeuristic back = VisibilityHeuristic::from_string(h.to_string());
    EXPECT_NEAR(back.c, h.c, 1e-7 * h.c);
    EXPECT_NEAR(back.hg, h.hg, 1e-7 * h.hg);
    for (int i = 0; i < 16; ++i) {
      EXPECT_NEAR(back.lambda[i], h.lambda[i], 1e-7);
      EXPECT_GE(h.lambda[i], 0.0);
      EXPECT_LE(h.lambda[i], 1.0);
    }
  }
  // The paper's table, entry 8 (the isotropic triangle's) is the centroid.
  EXPECT_EQ(VisibilityHeuristic::published().lambda[8], 1.0);
  EXPECT_EQ(VisibilityHeuristic::published().signature(1.0, 1.0, 1.0, 0.866), 8);
}

TEST(Heuristic, MalformedTextIsRejected) {
  EXPECT_THROW(VisibilityHeuristic::from_string("1 2 3"), InvalidInput);
  EXPECT_THROW(VisibilityHeuristic::from_string(VisibilityHeuristic::published().to_string().replace(0, 6, "nan   ")),
               InvalidInput);
  std::string text = "5 4 0.5 2.8";
  for (int i = 0; i < 16; ++i) text += i == 3 ? " 1.5" : " 0.5";   // a lambda outside [0, 1]
  EXPECT_THROW(VisibilityHeuristic::from_string(text), InvalidInput);
}

TEST(Heuristic, ProbePositionOrdersTheDistances) {
  // On a sphere the opposite-corner probe bends wherever any part of a face is hidden, so it
  // can only lengthen paths compared with the centroid probe; every preset stays close.
  const TriangleMesh m = icosphere(3);
  SolverOptions corner, centre, trained;
  corner.heuristic = VisibilityHeuristic::opposite_corner();
  centre.heuristic = VisibilityHeuristic::centroid();
  trained.heuristic = VisibilityHeuristic::trained();
  const auto a = GeodesicSolver(m, corner).compute({Source::at_vertex(0)}).vertex_distance;
  const auto b = GeodesicSolver(m, centre).compute({Source::at_vertex(0)}).vertex_distance;
  const auto c = GeodesicSolver(m, trained).compute({Source::at_vertex(0)}).vertex_distance;
  double sa = 0, sb = 0, sc = 0;
  for (std::size_t v = 0; v < m.num_vertices(); ++v) sa += a[v], sb += b[v], sc += c[v];
  EXPECT_GT(sa, sb);
  EXPECT_NEAR(sc / sb, 1.0, 0.02);
  EXPECT_NEAR(sa / sb, 1.0, 0.05);
}

}  // namespace
}  // namespace gsp::test
