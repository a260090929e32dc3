// The per-face virtual sources (want_face_sources): the input faces' own run by default (what
// paths walk back on and CVT partitions), or fitted from the intrinsic Delaunay run to the
// vertex values (fitted_face_sources, what Python's distance_at reads; query_gather.hpp,
// fitted_face_sources), against CGAL's exact geodesics on a CAD plate whose flat faces are
// fans of slivers.
#include "helpers/geodesic_fixtures.hpp"
#include "helpers/mesh_builders.hpp"
#include "test_data.hpp"

#include <gsp/cli/load.hpp>
#include <gsp/errors.hpp>
#include <gsp/geodesics.hpp>
#include <gsp/surface_point.hpp>
#include <gsp/reference/exact_geodesics.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

namespace gsp::test {
namespace {

struct CornerErrors {
  double mean = 0;          // mean |relative error| over every (face, corner) reading
  double below_1pct = 0;    // share of readings more than 1% below exact
};

// Each face's source read at its three corners, against the exact distance there.
CornerErrors corner_errors(const TriangleMesh& m, const GeodesicResult& r, const std::vector<double>& ex) {
  CornerErrors e;
  std::size_t n = 0;
  for (std::size_t f = 0; f < m.num_faces(); ++f)
    for (int i = 0; i < 3; ++i) {
      const double x = ex[m.triangles[f][i]];
      if (!(x > 0)) continue;
      std::array<double, 3> bary{0, 0, 0};
      bary[std::size_t(i)] = 1;
      const double d = r.distance_at(m, Index(f), bary);
      const double rel = std::isfinite(d) ? (d - x) / x : 1.0;
      e.mean += std::abs(rel), e.below_1pct += rel < -0.01 ? 1 : 0, ++n;
    }
  e.mean /= double(n), e.below_1pct /= double(n);
  return e;
}

// A convex polygon written as a fan of slivers from one corner: every flipped face's source is
// the true one, so each input face's, unfolded back, must be too: exact up to rounding at any
// point of any face (the frames through the flips are isometries).
TEST(FaceSources, ExactOnAPlanarFanOfSlivers) {
  TriangleMesh m;
  const int n = 64;
  const double pi = std::acos(-1.0);
  for (int i = 0; i < n; ++i) m.positions.push_back({std::cos(2 * pi * i / n), 0.6 * std::sin(2 * pi * i / n), 0.0});
  for (int i = 1; i + 1 < n; ++i) m.triangles.push_back({0, Index(i), Index(i + 1)});
  const GeodesicSolver solver(m);
  ASSERT_GT(solver.intrinsic_flips(), 0u);
  GeodesicOptions o;
  o.want_face_sources = true;
  o.fitted_face_sources = true;
  for (Index s : {Index(0), Index(17), Index(40)}) {
    const GeodesicResult r = solver.compute({Source::at_vertex(s)}, o);
    double worst = 0;
    for (std::size_t f = 0; f < m.num_faces(); ++f)
      for (const std::array<double, 3>& b : {std::array<double, 3>{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0.2, 0.3, 0.5}}) {
        const Vec3 p = SurfacePoint::in_face(Index(f), b).position(m);
        const double exact = distance(p, m.positions[s]);
        worst = std::max(worst, std::abs(r.distance_at(m, Index(f), b) - exact));
      }
    EXPECT_LT(worst, 1e-5) << "source " << s;
    // Face values (at the centroids) come from the same sources.
    for (std::size_t f = 0; f < m.num_faces(); ++f) {
      const Vec3 c = SurfacePoint::in_face(Index(f), {1.0 / 3, 1.0 / 3, 1.0 / 3}).position(m);
      EXPECT_NEAR(r.face_distance[f], distance(c, m.positions[s]), 1e-5) << "face " << f;
    }
  }
}

TEST(FaceSources, FittedOnesFollowTheDelaunayRunOnCadSlivers) {
  const TriangleMesh m = plate_with_hole(10, 3, 1, 48);
  const GeodesicSolver solver(m);
  ASSERT_GT(solver.intrinsic_flips(), 0u);
  reference::ExactGeodesicSolver exact(m);
  GeodesicOptions own, fitted;
  own.want_face_sources = fitted.want_face_sources = true;
  fitted.fitted_face_sources = true;
  const Index top_rim = 48 + 4;
  for (Index s : {Index(0), top_rim, Index(top_rim + 20), Index(48)}) {   // rims, a corner
    const std::vector<double> ex = exact.distances_from_vertex(s);
    const GeodesicResult a = solver.compute({Source::at_vertex(s)}, own);
    const GeodesicResult b = solver.compute({Source::at_vertex(s)}, fitted);
    // The vertex values of a fitted run are the Delaunay run's, asked for face sources or not.
    EXPECT_EQ(b.vertex_distance, solver.compute({Source::at_vertex(s)}).vertex_distance) << "source " << s;
    ASSERT_EQ(b.face_sources.size(), m.num_faces());
    const CornerErrors e = corner_errors(m, b, ex), before = corner_errors(m, a, ex);
    // The input faces' own run: mean 4.3% (rims), 0.71% (corner); 41-49% of the readings more
    // than 1% below exact (14% from the corner). The vertex values themselves are up to 1.0%
    // MRE here, a third of them more than 1% below exact: the fit cannot beat what it fits.
    EXPECT_LT(e.mean, 0.025) << "source " << s;
    EXPECT_LT(e.mean, 0.9 * before.mean) << "source " << s;
    EXPECT_LT(e.below_1pct, 0.35) << "source " << s;
  }
}

// Inside the faces of the CAD plate, against CGAL at random points: distance_at takes the lower
// of the fitted source's reading and the paths through the face's corners (corner_paths), each
// the length of a path on the surface, and neither below the straight line (up to rounding).
TEST(FaceSources, ReadingsInsideFacesTakeTheShorterPath) {
  const TriangleMesh m = plate_with_hole(10, 3, 1, 48);
  const GeodesicSolver solver(m);
  reference::ExactGeodesicSolver exact(m);
  GeodesicOptions fitted;
  fitted.want_face_sources = fitted.fitted_face_sources = true;
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> unit(0, 1);
  for (Index s : {Index(0), Index(48 + 4), Index(48)}) {
    exact.set_sources({SurfacePoint::at_vertex(s)});
    const GeodesicResult r = solver.compute({Source::at_vertex(s)}, fitted);
    double at = 0, source_only = 0;
    std::size_t n = 0;
    for (int k = 0; k < 3000; ++k) {
      const Index f = Index(rng() % m.num_faces());
      double u = unit(rng), v = unit(rng);
      if (u + v > 1) u = 1 - u, v = 1 - v;
      const std::array<double, 3> b{1 - u - v, u, v};
      const double e = exact.distance_to_point(f, b);
      if (!(e > 0)) continue;
      const Vec3 q = SurfacePoint::in_face(f, b).position(m);
      const double d = r.distance_at(m, f, b);
      const VirtualSource& vs = r.face_sources[f];
      EXPECT_GE(d, distance(q, m.positions[s]) * (1 - 1e-5)) << "face " << f;   // float records
      EXPECT_LE(d, corner_paths(m, f, q, r.vertex_distance)) << "face " << f;
      at += std::abs(d - e) / e, source_only += std::abs(vs.sigma + distance(q, vs.position) - e) / e, ++n;
    }
    at /= double(n), source_only /= double(n);
    RecordProperty("mre_source_" + std::to_string(s), std::to_string(at));
    EXPECT_LT(at, source_only) << "source " << s;
  }
}

// Without fitted_face_sources the face sources are the input faces' own propagation, the same
// as a solver that never flips: each face's source carried on from a neighbour.
TEST(FaceSources, DefaultOnesAreTheInputFacesRun) {
  const TriangleMesh m = plate_with_hole(10, 3, 1, 48);
  const GeodesicSolver solver(m);
  SolverOptions no_flips;
  no_flips.intrinsic_delaunay = false;
  const GeodesicSolver on_input(m, no_flips);
  GeodesicOptions o;
  o.want_face_sources = true;
  const GeodesicResult a = solver.compute({Source::at_vertex(7)}, o);
  const GeodesicResult b = on_input.compute({Source::at_vertex(7)}, o);
  ASSERT_EQ(a.face_sources.size(), b.face_sources.size());
  for (std::size_t f = 0; f < a.face_sources.size(); ++f) {
    EXPECT_EQ(a.face_sources[f].sigma, b.face_sources[f].sigma);
    EXPECT_EQ(distance(a.face_sources[f].position, b.face_sources[f].position), 0.0);
  }
  // Targeted runs ignore the fit (they stop before the vertices are final).
  o.fitted_face_sources = true;
  o.targets = {40};
  const GeodesicResult c = solver.compute({Source::at_vertex(7)}, o);
  const GeodesicResult d = on_input.compute({Source::at_vertex(7)}, o);
  EXPECT_EQ(c.vertex_distance[40], d.vertex_distance[40]);
}

// Fitted sources read at every face's corners and at random points inside never more than 1%
// below the straight line from the source, over the shared meshes and the corpus (up to 30,000
// vertices, one source each): a candidate below it at a corner, an edge's midpoint or the
// points of the face and its edges nearest to the candidate's source gets a longer path
// behind its source until it reads the line there. Weighing the shortfall in the fit instead
// left CAD parts 16% below at the corners; checking the corners, midpoints and centroid only,
// a CAD gear 1.2% below inside a sliver (docs/gsp-core.md, "Fitted face sources").
TEST(FaceSources, FittedReadingsKeepTheStraightLineOverTheCorpus) {
  if (!have_shared_data()) GTEST_SKIP() << "shared meshes not found at " << data_dir();
  GeodesicOptions o;
  o.want_face_sources = true;
  o.fitted_face_sources = true;
  std::size_t fields = 0, readings = 0;
  for (const std::string& path : shared_and_corpus_files()) {
    cli::LoadedMesh in;
    try {
      in = cli::load_mesh(path, {});
    } catch (const Error&) {
      continue;   // a point cloud, or a file the readers reject
    }
    const TriangleMesh& m = in.mesh;
    if (m.num_faces() == 0 || m.num_vertices() > 30000) continue;
    const GeodesicSolver solver(m);
    const Index s = m.triangles[m.num_faces() / 2][0];
    const GeodesicResult r = solver.compute({Source::at_vertex(s)}, o);
    double worst = 0;
    std::mt19937_64 rng(m.num_faces());
    std::uniform_real_distribution<double> unit(0, 1);
    for (std::size_t f = 0; f < m.num_faces(); ++f)
      for (int i = 0; i < 8; ++i) {   // the corners, then five random points of the face
        std::array<double, 3> bary{0, 0, 0};
        if (i < 3) {
          bary[std::size_t(i)] = 1;
        } else {
          double u = unit(rng), v = unit(rng);
          if (u + v > 1) u = 1 - u, v = 1 - v;
          bary = {1 - u - v, u, v};
        }
        const double line = distance(SurfacePoint::in_face(Index(f), bary).position(m), m.positions[s]);
        const VirtualSource& vs = r.face_sources[f];
        if (!(line > 0) || !vs.reached()) continue;
        // The source itself, not distance_at: the paths through the corners keep that above it.
        const double d = vs.sigma + distance(SurfacePoint::in_face(Index(f), bary).position(m), vs.position);
        worst = std::max(worst, (line - d) / line), ++readings;
      }
    EXPECT_LE(worst, 1e-7) << path << " source " << s;   // exact up to double rounding
    ++fields;
  }
  EXPECT_GT(fields, 40u);
  EXPECT_GT(readings, 0u);
}

}  // namespace
}  // namespace gsp::test
