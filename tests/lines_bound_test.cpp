// The two bounds of line sources: on meshes with a boundary, no distance to the boundary is
// below the 3D distance to the nearest boundary edge (the propagation alone went up to 5%
// below on the bunny and 50% on a balcony wall of the corpus), nor above the shortest path
// along the edges from the boundary's vertices (up to 3.6x on a CAD pig of the corpus before
// the core's vertex relaxation ran after the waves).
#include "test_data.hpp"

#include <gsp/dijkstra.hpp>
#include <gsp/io/mesh_io.hpp>
#include <gsp/lines/line_distances.hpp>
#include <gsp/weld.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <set>

namespace gsp::test {
namespace {

double point_segment(Vec3 x, Vec3 a, Vec3 b) {
  const Vec3 ab = b - a;
  const double l2 = dot(ab, ab);
  const double t = l2 > 0 ? std::clamp(dot(x - a, ab) / l2, 0.0, 1.0) : 0.0;
  return distance(x, a + t * ab);
}

TEST(LinesBound, BoundaryDistancesNeverBelowTheStraightLine) {
  if (!have_shared_data()) GTEST_SKIP() << "shared data folder missing";
  for (const char* name : {"stanford_bunny.obj", "newell_teapot.obj"}) {
    const TriangleMesh m = io::read_mesh(shared_mesh(name)).mesh;
    const lines::LineSource src = lines::boundary_source(m);
    const lines::LineResult r = lines::line_distances(m, src);
    lines::LineOptions raw;
    raw.straight_line_bound = false;
    const lines::LineResult r_raw = lines::line_distances(m, src, raw);
    std::size_t below_raw = 0;
    for (std::size_t v = 0; v < m.num_vertices(); ++v) {
      if (!std::isfinite(r.vertex_distance[v])) continue;
      double bound = std::numeric_limits<double>::infinity();
      for (const auto& seg : src.segments) bound = std::min(bound, point_segment(m.positions[v], seg[0], seg[1]));
      // Boundary edges are straight: their pieces are the segments themselves.
      EXPECT_GE(r.vertex_distance[v], bound * (1 - 1e-12)) << name << " vertex " << v;
      EXPECT_GE(r.vertex_distance[v], r_raw.vertex_distance[v]) << name;   // only ever raised
      below_raw += r_raw.vertex_distance[v] < bound * (1 - 1e-6);
    }
    EXPECT_EQ(r.stats.raised_to_line, below_raw) << name;
  }
}

TEST(LinesBound, BoundaryDistancesNeverAboveTheEdgePath) {
  const std::string pig = data_dir() + "/../corpus/cgal_pig.stl";
  if (!have_shared_data() || !std::filesystem::exists(pig)) GTEST_SKIP() << "shared data folder missing";
  for (const std::string& path : {pig, shared_mesh("stanford_bunny.obj")}) {
    const TriangleMesh m = weld_vertices(io::read_mesh(path).mesh).mesh;
    const lines::LineSource src = lines::boundary_source(m);
    const lines::LineResult r = lines::line_distances(m, src);
    std::set<Index> ends;
    for (const auto& p : src.pieces)
      for (int k = 0; k < 3; ++k)
        if (p.start[k] == 1 || p.end[k] == 1) ends.insert(m.triangles[p.face][k]);
    std::vector<Source> sources;
    for (Index v : ends) sources.push_back(Source::at_vertex(v));
    const std::vector<double> edges = dijkstra_distances(m, sources).vertex_distance;
    for (std::size_t v = 0; v < m.num_vertices(); ++v)
      EXPECT_LE(r.vertex_distance[v], edges[v] * (1 + 1e-9)) << path << " vertex " << v;
    if (path == pig) EXPECT_GE(r.stats.relaxation_rounds, 1u) << "the case this test is about";
  }
}

}  // namespace
}  // namespace gsp::test
