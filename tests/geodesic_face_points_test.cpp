// Sources inside faces run on the intrinsic Delaunay triangulation, found there by replaying the
// flips (libgsp/src/flip_replay.hpp). Before, they ran on the input's own faces, and on a CAD
// export's slivers (the ADIS16480 sensor STL: fans of needles) a face point placed exactly at a
// vertex gave distances 2.7% longer on average than the same vertex as a vertex source, up to
// 57% at single vertices; against CGAL's exact geodesics from points inside faces the error was
// several times GSP's error from vertices.
#include "helpers/geodesic_fixtures.hpp"
#include "test_data.hpp"

#include <gsp/geodesics.hpp>
#include <gsp/io/mesh_io.hpp>
#include <gsp/reference/exact_geodesics.hpp>
#include <gsp/weld.hpp>

#include <gtest/gtest.h>

#include <cmath>

namespace gsp::test {
namespace {

TriangleMesh sensor() { return weld_vertices(io::read_mesh(shared_mesh("adis16480_sensor.stl")).mesh).mesh; }

TEST(GeodesicFacePoints, APointAtACornerIsThatVertex) {
  if (!have_shared_data()) GTEST_SKIP() << "no shared meshes";
  const TriangleMesh m = sensor();
  const GeodesicSolver solver(m);
  ASSERT_GT(solver.intrinsic_flips(), 0u);
  SplitMix rng{7};
  for (int k = 0; k < 4; ++k) {
    const Index f = Index(rng.next() % m.num_faces());
    const int corner = int(rng.next() % 3);
    std::array<double, 3> b{0, 0, 0};
    b[corner] = 1;
    const std::vector<double> from_vertex = solver.compute({Source::at_vertex(m.triangles[f][corner])}).vertex_distance;
    const std::vector<double> from_point = solver.compute({Source::in_face(f, b)}).vertex_distance;
    // Input faces: 2.7% mean, 57% at worst on this mesh. The point seeds one face where the
    // vertex seeds its whole fan, so the fields differ a little near the source.
    EXPECT_LT(mre(from_point, from_vertex), 0.002) << "face " << f;
    double edges = 0;
    for (const Triangle& t : m.triangles)
      for (int i = 0; i < 3; ++i) edges += distance(m.positions[t[i]], m.positions[t[(i + 1) % 3]]);
    const double mean_edge = edges / double(3 * m.num_faces());
    for (std::size_t v = 0; v < m.num_vertices(); ++v)
      EXPECT_LT(from_point[v], from_vertex[v] * 1.02 + 0.5 * mean_edge) << "face " << f << " vertex " << v;
  }
}

TEST(GeodesicFacePoints, PointsInsideFacesAgainstExact) {
  if (!have_shared_data()) GTEST_SKIP() << "no shared meshes";
  for (const char* name : {"adis16480_sensor.stl", "thingi10k_88566_fence_panels.stl", "stanford_bunny.obj"}) {
    TriangleMesh m = weld_vertices(io::read_mesh(shared_mesh(name)).mesh).mesh;
    reference::ExactGeodesicSolver exact(m);
    const GeodesicSolver solver(m);
    SolverOptions input_faces;
    input_faces.intrinsic_delaunay = false;
    const GeodesicSolver on_input(m, input_faces);
    SplitMix rng{11};
    double gsp = 0, input = 0;
    const int points = 3;
    for (int k = 0; k < points; ++k) {
      const Index f = Index(rng.next() % m.num_faces());
      const std::array<double, 3> b{0.2, 0.3, 0.5};
      const std::vector<double> ex = exact.distances({SurfacePoint::in_face(f, b)});
      gsp += mre(solver.compute({Source::in_face(f, b)}).vertex_distance, ex) / points;
      input += mre(on_input.compute({Source::in_face(f, b)}).vertex_distance, ex) / points;
    }
    // Measured: the sensor 0.43% (input faces 3.19%), the fence panels 0.60% (0.52%; GSP's
    // hardest corpus mesh from vertices too), the bunny 0.160% (0.163%). The fence's were
    // 0.65% (0.78%) before the values at saddle vertices (docs/gsp-core.md), which mend the
    // input faces' fans of slivers round its holes more than the flipped faces.
    EXPECT_LT(gsp, 0.008) << name;
    EXPECT_LE(gsp, input * 1.2) << name;
    if (std::string(name) == "adis16480_sensor.stl") EXPECT_LT(gsp, input / 4) << name;
    std::printf("%s: face points MRE %.4f%% (input faces %.4f%%)\n", name, 100 * gsp, 100 * input);
  }
}

}  // namespace
}  // namespace gsp::test
