// gsp::reference and the adapters on the shared real meshes (golden figures from
// SOURCES.md): the benign ones are accepted and bracketed by closed-form bounds, the malign
// ones refused with a message naming the problem.
#include <gsp/adapters/cgal.hpp>
#include <gsp/adapters/openmesh.hpp>
#include <gsp/errors.hpp>
#include <gsp/io/mesh_io.hpp>
#include <gsp/reference/exact_geodesics.hpp>
#include <gsp/reference/heat_method.hpp>
#include <gsp/weld.hpp>

#include "test_data.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <numeric>
#include <queue>
#include <string>

namespace {

using gsp::Index;
using gsp::TriangleMesh;
using gsp::reference::ExactGeodesicSolver;
using gsp::reference::ExactSource;
using gsp::reference::HeatMethodMode;
using gsp::reference::HeatMethodSolver;

constexpr double kInf = std::numeric_limits<double>::infinity();

#define REQUIRE_SHARED_DATA() \
  if (!gsp::test::have_shared_data()) GTEST_SKIP() << "shared meshes not found at " << gsp::test::data_dir()

TriangleMesh load(const std::string& name, bool weld) {
  TriangleMesh m = gsp::io::read_mesh(gsp::test::shared_mesh(name)).mesh;
  return weld ? gsp::weld_vertices(m).mesh : m;
}

// Shortest paths along edges: every edge path lies on the surface, so this bounds the exact
// geodesic distance from above.
std::vector<double> edge_dijkstra(const TriangleMesh& m, Index source) {
  std::vector<std::vector<std::pair<Index, double>>> adj(m.num_vertices());
  for (const auto& t : m.triangles)
    for (int i = 0; i < 3; ++i) {
      const Index a = t[i], b = t[(i + 1) % 3];
      const double w = gsp::distance(m.positions[a], m.positions[b]);
      adj[a].push_back({b, w});
      adj[b].push_back({a, w});
    }
  std::vector<double> d(m.num_vertices(), kInf);
  using Item = std::pair<double, Index>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> queue;
  d[source] = 0;
  queue.push({0, source});
  while (!queue.empty()) {
    auto [dist, v] = queue.top();
    queue.pop();
    if (dist > d[v]) continue;
    for (auto [w, len] : adj[v])
      if (dist + len < d[w]) queue.push({d[w] = dist + len, w});
  }
  return d;
}

TEST(ReferenceSharedMeshes, FertilityBracketedAndSymmetric) {
  REQUIRE_SHARED_DATA();
  const TriangleMesh m = load("fertility.off", false);
  ASSERT_EQ(m.num_vertices(), 4494u);
  ExactGeodesicSolver solver(m);
  EXPECT_EQ(solver.num_components(), 1u);
  EXPECT_EQ(solver.isolated_vertices(), 0u);
  EXPECT_EQ(solver.flipped_faces(), 0u);
  const Index sources[] = {0, 1500, 3333};
  std::vector<std::vector<double>> d;
  for (Index s : sources) {
    d.push_back(solver.distances_from_vertex(s));
    const auto upper = edge_dijkstra(m, s);
    std::size_t strictly_shorter = 0;
    for (std::size_t v = 0; v < m.num_vertices(); ++v) {
      const double lower = gsp::distance(m.positions[v], m.positions[s]);
      ASSERT_TRUE(std::isfinite(d.back()[v]));
      EXPECT_GE(d.back()[v], lower * (1 - 1e-12)) << s << " -> " << v;
      EXPECT_LE(d.back()[v], upper[v] * (1 + 1e-12)) << s << " -> " << v;
      strictly_shorter += d.back()[v] < upper[v] * (1 - 1e-3);
    }
    EXPECT_GT(strictly_shorter, m.num_vertices() / 2);  // paths cut across faces
  }
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = 0; j < 3; ++j)
      EXPECT_NEAR(d[i][sources[j]], d[j][sources[i]], 1e-9 * d[i][sources[j]]);
}

TEST(ReferenceSharedMeshes, HeatMethodOnFertility) {
  REQUIRE_SHARED_DATA();
  const TriangleMesh m = load("fertility.off", false);
  ExactGeodesicSolver exact(m);
  const auto reference = exact.distances_from_vertex(0);
  const double scale = *std::max_element(reference.begin(), reference.end());
  for (HeatMethodMode mode : {HeatMethodMode::direct, HeatMethodMode::intrinsic_delaunay}) {
    const auto heat = HeatMethodSolver(m, mode).solve({0});
    double mre = 0;
    std::size_t n = 0;
    for (std::size_t v = 0; v < m.num_vertices(); ++v)
      if (reference[v] > 0.05 * scale) {
        mre += std::abs(heat[v] - reference[v]) / reference[v];
        ++n;
      }
    mre /= double(n);
    EXPECT_LT(mre, 0.05);
    RecordProperty(mode == HeatMethodMode::direct ? "direct_mre" : "idt_mre", std::to_string(mre));
  }
}

// SOURCES.md: 1,113 vertices referenced by no face, one component, five holes.
TEST(ReferenceSharedMeshes, BunnyIsolatedVerticesCompactedAndMappedBack) {
  REQUIRE_SHARED_DATA();
  const TriangleMesh m = load("stanford_bunny.obj", false);
  ASSERT_EQ(m.num_vertices(), 35947u);
  ExactGeodesicSolver exact(m);  // construction only: one exact solve takes ~13 s here
  EXPECT_EQ(exact.isolated_vertices(), 1113u);
  EXPECT_EQ(exact.num_components(), 1u);

  std::vector<char> referenced(m.num_vertices(), 0);
  for (const auto& t : m.triangles)
    for (Index v : t) referenced[v] = 1;
  const Index source = Index(std::find(referenced.begin(), referenced.end(), 1) - referenced.begin());
  HeatMethodSolver heat(m, HeatMethodMode::intrinsic_delaunay);
  const auto d = heat.solve({source});
  std::size_t infinite = 0;
  for (std::size_t v = 0; v < m.num_vertices(); ++v) {
    if (!referenced[v]) {
      EXPECT_EQ(d[v], kInf) << v;
      ++infinite;
    } else {
      EXPECT_TRUE(std::isfinite(d[v]) && d[v] >= -1e-9) << v;
    }
  }
  EXPECT_EQ(infinite, 1113u);
}

// SOURCES.md: the tyres weld to 35,987 vertices in 4 closed components.
TEST(ReferenceSharedMeshes, TiresComponentsWithoutSourceAreInfinite) {
  REQUIRE_SHARED_DATA();
  const TriangleMesh m = load("thingi10k_99865_tires.stl", true);
  ASSERT_EQ(m.num_vertices(), 35987u);
  ExactGeodesicSolver solver(m);
  EXPECT_EQ(solver.num_components(), 4u);
  const auto d = solver.distances_from_vertex(0);
  // The source's component by union-find over the faces, independent of the solver.
  std::vector<Index> parent(m.num_vertices());
  std::iota(parent.begin(), parent.end(), Index(0));
  std::function<Index(Index)> find = [&](Index x) { return parent[x] == x ? x : parent[x] = find(parent[x]); };
  for (const auto& t : m.triangles) {
    parent[find(t[1])] = find(t[0]);
    parent[find(t[2])] = find(t[0]);
  }
  for (std::size_t v = 0; v < m.num_vertices(); ++v) {
    if (find(Index(v)) == find(0)) {
      EXPECT_TRUE(std::isfinite(d[v])) << v;
      EXPECT_GE(d[v], gsp::distance(m.positions[v], m.positions[0]) * (1 - 1e-12)) << v;
    } else {
      EXPECT_EQ(d[v], kInf) << v;
    }
  }
}

void expect_refused(const std::string& name, bool weld, const std::string& reason) {
  const TriangleMesh m = load(name, weld);
  try {
    ExactGeodesicSolver solver(m);
    ADD_FAILURE() << name << " accepted";
  } catch (const gsp::TopologyError& e) {
    EXPECT_NE(std::string(e.what()).find(reason), std::string::npos) << name << ": " << e.what();
  }
  EXPECT_THROW(HeatMethodSolver{m}, gsp::TopologyError) << name;
}

TEST(ReferenceSharedMeshes, MalignMeshesRefused) {
  REQUIRE_SHARED_DATA();
  expect_refused("cycloidal_drive.ply", false, "non-manifold edge");  // 242 such edges
  expect_refused("manifold_offset1.obj", false, "zero area");          // 68 zero-area faces
  expect_refused("openscad_nonmanifold_crash.obj", true, "zero area"); // 1 zero-area face
  expect_refused("cesium_milk_truck.glb", true, "non-manifold vertex");
}

// 18 non-manifold edges after welding (SOURCES.md): both halfedge structures must leave out
// some faces, report every one of them and keep the rest.
TEST(ReferenceSharedMeshes, AdaptersReportNonManifoldFaces) {
  REQUIRE_SHARED_DATA();
  const TriangleMesh m = load("openscad_nonmanifold_crash.obj", true);
  ASSERT_EQ(m.num_faces(), 1442u);
  const auto cgal = gsp::adapters::to_cgal(m);
  const auto om = gsp::adapters::to_openmesh(m);
  // Each non-manifold edge has >= 3 faces, so at least one skipped face per 3 such edges.
  EXPECT_GE(cgal.skipped_faces.size(), 6u);
  EXPECT_EQ(cgal.skipped_faces.size() + cgal.face_map.size(), m.num_faces());
  EXPECT_EQ(cgal.mesh.number_of_faces(), cgal.face_map.size());
  EXPECT_TRUE(cgal.mesh.is_valid(false));
  EXPECT_EQ(om.skipped_faces.size() + om.face_map.size(), m.num_faces());
  EXPECT_EQ(om.mesh.n_faces(), om.face_map.size());
  EXPECT_GE(om.skipped_faces.size(), 6u);
  // The two add-face rules differ in detail, so the skipped sets need not be equal.
  RecordProperty("cgal_skipped_faces", std::to_string(cgal.skipped_faces.size()));
  RecordProperty("openmesh_skipped_faces", std::to_string(om.skipped_faces.size()));
}

}  // namespace
