// Robustness on every mesh of the shared set (benign scans, CAD soups, non-manifold and
// inconsistently oriented ones): no NaN anywhere, every vertex connected to a source gets a
// finite distance, every other vertex +inf.
#include "helpers/geodesic_fixtures.hpp"
#include "test_data.hpp"

#include <gsp/geodesics.hpp>
#include <gsp/io/mesh_io.hpp>
#include <gsp/mesh.hpp>
#include <gsp/weld.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

namespace gsp::test {
namespace {

// Vertex components through faces that can carry a distance (no repeated index).
std::vector<Index> vertex_components(const TriangleMesh& m) {
  std::vector<Index> parent(m.num_vertices());
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](Index x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for (const Triangle& t : m.triangles) {
    if (repeats_vertex(t)) continue;
    parent[find(t[1])] = find(t[0]);
    parent[find(t[2])] = find(t[0]);
  }
  std::vector<Index> comp(m.num_vertices());
  for (Index v = 0; v < m.num_vertices(); ++v) comp[v] = find(v);
  return comp;
}

std::vector<bool> in_some_face(const TriangleMesh& m) {
  std::vector<bool> used(m.num_vertices(), false);
  for (const Triangle& t : m.triangles)
    if (!repeats_vertex(t)) used[t[0]] = used[t[1]] = used[t[2]] = true;
  return used;
}

class SharedMesh : public ::testing::TestWithParam<const char*> {};

TEST_P(SharedMesh, ConnectedVerticesFiniteOthersInfiniteNoNaN) {
  if (!have_shared_data()) GTEST_SKIP() << "shared meshes not found";
  const std::string name = GetParam();
  TriangleMesh m = io::read_mesh(shared_mesh(name)).mesh;
  const io::Format f = io::format_from_path(name);
  if (f == io::Format::stl || f == io::Format::glb) m = weld_vertices(m).mesh;   // as the apps do
  const std::vector<Index> comp = vertex_components(m);
  const std::vector<bool> used = in_some_face(m);
  const GeodesicSolver solver(m);
  SplitMix rng{std::hash<std::string>{}(name)};
  for (int trial = 0; trial < 3; ++trial) {
    Index src;
    do src = Index(rng.next() % m.num_vertices()); while (!used[src]);
    for (Precision p : {Precision::single, Precision::double_precision}) {
      GeodesicOptions o;
      o.precision = p;
      const GeodesicResult r = solver.compute({Source::at_vertex(src)}, o);
      std::size_t finite = 0;
      for (Index v = 0; v < m.num_vertices(); ++v) {
        const double d = r.vertex_distance[v];
        ASSERT_FALSE(std::isnan(d)) << name << " vertex " << v;
        ASSERT_GE(d, 0.0);
        if (comp[v] == comp[src] && used[v]) {
          ASSERT_TRUE(std::isfinite(d)) << name << ": vertex " << v << " is connected to source " << src;
          ++finite;
        } else if (v != src) {
          ASSERT_TRUE(std::isinf(d)) << name << ": vertex " << v << " is not connected to source " << src;
        }
      }
      EXPECT_GT(finite, 0u);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(AllMeshes, SharedMesh,
                         ::testing::Values("adis16480_sensor.stl", "armadillo_remeshed.obj", "camelhead.off",
                                           "cesium_milk_truck.glb", "cycloidal_drive.ply", "falconstatue.obj",
                                           "fertility.off", "manifold_offset1.obj", "nefertiti_lowres.obj",
                                           "newell_teapot.obj", "openscad_nonmanifold_crash.obj",
                                           "stanford_bunny.obj", "thingi10k_88566_fence_panels.stl",
                                           "thingi10k_99865_tires.stl"),
                         [](const auto& info) {
                           std::string s = info.param;
                           for (char& c : s) if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return s;
                         });

}  // namespace
}  // namespace gsp::test
