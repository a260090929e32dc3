// Round trips through every writer: OBJ -> PLY -> GLB -> OFF -> OBJ keeps every vertex and
// face; PLY (binary and ascii) and glTF (.gltf and .glb) keep normals and attributes. PLY and
// glTF store float32, so positions are compared with the float-rounded input, bitwise.
#include <gsp/io/mesh_io.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>

#include <unistd.h>

#include "test_data.hpp"

namespace {

namespace fs = std::filesystem;
using gsp::TriangleMesh;
using gsp::Vec3;
using gsp::io::read_mesh;
using gsp::io::write_mesh;

class RoundTrip : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("gsp_io_round_trip_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  fs::path dir_;
};

// The value a float32 file stores. The volatile keeps the rounding: g++ 12 at -O2 dropped a
// plain double(float(x)) inside the gtest comparison below.
double round_to_float(double x) {
  volatile float f = static_cast<float>(x);
  return f;
}
Vec3 to_float(Vec3 p) { return {round_to_float(p.x), round_to_float(p.y), round_to_float(p.z)}; }

// A small mesh with awkward coordinates (not float-representable, negative, tiny, huge).
TriangleMesh sample_mesh() {
  TriangleMesh m;
  m.positions = {{0.1, -2.5, 1e-7}, {3.25, 0.3333333333333333, -1e6}, {-0.0, 7.0, 2.0}, {1.0 / 3, 2.0 / 3, 5e-30}, {12345.678, -0.001, 0.5}};
  m.triangles = {{0, 1, 2}, {0, 2, 3}, {1, 3, 4}, {4, 4, 0}};   // a repeated-index face is kept
  m.normals = {{0, 0, 1}, {0, 1, 0}, {1, 0, 0}, {0.6, 0.8, 0}, {0, -0.6, 0.8}};
  return m;
}

gsp::io::VertexAttributes sample_attributes() {
  gsp::io::VertexAttributes a;
  a.scalars = {{"distance", {0.f, 1.5f, std::numeric_limits<float>::infinity(), 1e-3f, 42.f}}};
  a.labels = {{"source", {0, 1, -1, 7, 123456}}};
  a.colors = {{{255, 0, 0, 255}}, {{0, 255, 0, 128}}, {{0, 0, 255, 0}}, {{1, 2, 3, 4}}, {{250, 251, 252, 253}}};
  return a;
}

TEST_F(RoundTrip, ObjPlyGlbOffObjKeepsEverything) {
  if (!gsp::test::have_shared_data()) GTEST_SKIP() << "shared data folder missing";
  const auto original = read_mesh(gsp::test::shared_mesh("openscad_nonmanifold_crash.obj")).mesh;
  ASSERT_EQ(original.num_faces(), 1442u);
  write_mesh(path("a.ply"), original);
  const auto ply = read_mesh(path("a.ply")).mesh;
  write_mesh(path("b.glb"), ply);
  const auto glb = read_mesh(path("b.glb")).mesh;
  write_mesh(path("c.off"), glb);
  const auto off = read_mesh(path("c.off")).mesh;
  write_mesh(path("d.obj"), off);
  const auto obj = read_mesh(path("d.obj")).mesh;
  for (const TriangleMesh* m : {&ply, &glb, &off, &obj}) {
    ASSERT_EQ(m->num_vertices(), original.num_vertices());
    ASSERT_EQ(m->triangles, original.triangles);
    for (std::size_t v = 0; v < original.num_vertices(); ++v)
      ASSERT_EQ(m->positions[v], to_float(original.positions[v])) << "vertex " << v;
  }
}

TEST_F(RoundTrip, TextFormatsKeepDoublesExactly) {
  const TriangleMesh m = sample_mesh();
  for (const char* name : {"exact.obj", "exact.off"}) {
    write_mesh(path(name), m);
    const auto r = read_mesh(path(name)).mesh;
    EXPECT_EQ(r.positions, m.positions) << name;
    EXPECT_EQ(r.triangles, m.triangles) << name;
  }
}

void expect_attributes(const gsp::io::ReadResult& r, const TriangleMesh& m, const gsp::io::VertexAttributes& a,
                       bool labels_as_scalars, const std::string& what) {
  SCOPED_TRACE(what);
  ASSERT_EQ(r.mesh.num_vertices(), m.num_vertices());
  EXPECT_EQ(r.mesh.triangles, m.triangles);
  for (std::size_t v = 0; v < m.num_vertices(); ++v) EXPECT_EQ(r.mesh.positions[v], to_float(m.positions[v]));
  ASSERT_EQ(r.mesh.normals.size(), m.num_vertices());
  for (std::size_t v = 0; v < m.num_vertices(); ++v) EXPECT_LT(gsp::distance(r.mesh.normals[v], m.normals[v]), 1e-6);
  EXPECT_EQ(r.attributes.colors, a.colors);
  if (labels_as_scalars) {
    // glTF: `_DISTANCE` and `_SOURCE`, both FLOAT SCALAR.
    ASSERT_EQ(r.attributes.scalars.size(), 2u);
    std::map<std::string, std::vector<float>> got(r.attributes.scalars.begin(), r.attributes.scalars.end());
    EXPECT_EQ(got["DISTANCE"], a.scalars[0].second);
    const std::vector<float> labels(a.labels[0].second.begin(), a.labels[0].second.end());
    EXPECT_EQ(got["SOURCE"], labels);
  } else {
    ASSERT_EQ(r.attributes.scalars.size(), 1u);
    EXPECT_EQ(r.attributes.scalars[0], a.scalars[0]);
    ASSERT_EQ(r.attributes.labels.size(), 1u);
    EXPECT_EQ(r.attributes.labels[0], a.labels[0]);
  }
}

TEST_F(RoundTrip, AttributesThroughPlyAndGltf) {
  const TriangleMesh m = sample_mesh();
  const auto a = sample_attributes();
  write_mesh(path("attr.ply"), m, a);
  expect_attributes(read_mesh(path("attr.ply")), m, a, false, "binary PLY");
  gsp::io::WriteOptions ascii;
  ascii.ascii = true;
  write_mesh(path("attr_ascii.ply"), m, a, ascii);
  const auto ra = read_mesh(path("attr_ascii.ply"));
  EXPECT_FALSE(ra.info.binary);
  expect_attributes(ra, m, a, false, "ascii PLY");
  write_mesh(path("attr.gltf"), m, a);
  expect_attributes(read_mesh(path("attr.gltf")), m, a, true, "glTF");
  write_mesh(path("attr.glb"), m, a);
  expect_attributes(read_mesh(path("attr.glb")), m, a, true, "GLB");
}

// A binary PLY body larger than the writer's 4 MB buffer (written out in several pieces, the
// last one partial) and one smaller than it: every vertex, value and face comes back.
TEST_F(RoundTrip, BinaryPlyAcrossTheWritersBuffer) {
  for (std::size_t n : {std::size_t(3), std::size_t(300001)}) {
    TriangleMesh m;
    gsp::io::VertexAttributes a;
    a.scalars = {{"distance", {}}};
    for (std::size_t i = 0; i < n; ++i) {
      m.positions.push_back({double(i), 0.5 * double(i % 7), -double(i % 13)});
      a.scalars[0].second.push_back(float(i) * 0.25f);
    }
    for (std::size_t i = 0; i + 2 < n; i += 2) m.triangles.push_back({gsp::Index(i), gsp::Index(i + 1), gsp::Index(i + 2)});
    write_mesh(path("big.ply"), m, a);
    const gsp::io::ReadResult r = read_mesh(path("big.ply"));
    ASSERT_EQ(r.mesh.num_vertices(), n);
    ASSERT_EQ(r.mesh.triangles, m.triangles);
    ASSERT_EQ(r.attributes.scalars.size(), 1u);
    for (std::size_t i = 0; i < n; ++i) {
      ASSERT_EQ(r.mesh.positions[i], to_float(m.positions[i])) << i;
      ASSERT_EQ(r.attributes.scalars[0].second[i], a.scalars[0].second[i]) << i;
    }
  }
}

TEST_F(RoundTrip, ColoursThroughObjAndCoff) {
  const TriangleMesh m = sample_mesh();
  auto a = sample_attributes();
  write_mesh(path("col.off"), m, a);
  EXPECT_EQ(read_mesh(path("col.off")).attributes.colors, a.colors);
  write_mesh(path("col.obj"), m, a);
  const auto obj = read_mesh(path("col.obj")).attributes.colors;
  ASSERT_EQ(obj.size(), a.colors.size());
  for (std::size_t v = 0; v < obj.size(); ++v)   // OBJ has no alpha
    EXPECT_EQ(obj[v], (std::array<std::uint8_t, 4>{a.colors[v][0], a.colors[v][1], a.colors[v][2], 255}));
}

TEST_F(RoundTrip, PointCloudStaysAPointCloud) {
  TriangleMesh m = sample_mesh();
  m.triangles.clear();
  for (const char* name : {"pc.ply", "pc.glb", "pc.gltf", "pc.obj", "pc.off"}) {
    write_mesh(path(name), m);
    const auto r = read_mesh(path(name)).mesh;
    EXPECT_TRUE(r.is_point_cloud()) << name;
    EXPECT_EQ(r.num_vertices(), m.num_vertices()) << name;
  }
}

TEST_F(RoundTrip, GltfPositionBoundsAreWritten) {
  // The spec requires min/max on POSITION; check the JSON carries the float-rounded bounds.
  write_mesh(path("bounds.gltf"), sample_mesh());
  std::ifstream in(path("bounds.gltf"));
  const std::string json((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(json.find("\"max\""), std::string::npos);
  EXPECT_NE(json.find("\"min\""), std::string::npos);
  EXPECT_NE(json.find("-1000000"), std::string::npos);   // min z
  EXPECT_NE(json.find("data:application/octet-stream;base64,"), std::string::npos);   // embedded buffer
}

TEST_F(RoundTrip, ValuesTxt) {
  const std::vector<double> values = {0.0, 1.5, -2.25, std::numeric_limits<double>::infinity(), double(0.1f), 1e30};
  gsp::io::write_values_txt(path("v.txt"), values);
  const auto back = gsp::io::read_values_txt(path("v.txt"));
  ASSERT_EQ(back.size(), values.size());
  for (std::size_t i = 0; i < values.size(); ++i) EXPECT_EQ(float(back[i]), float(values[i])) << i;   // %.9g: float-exact
  std::ifstream in(path("v.txt"));
  std::string line;
  for (int i = 0; i < 4; ++i) std::getline(in, line);
  EXPECT_EQ(line, "inf");
}

TEST_F(RoundTrip, StlAndXyzAreReadOnly) {
  for (const char* name : {"x.stl", "x.xyz", "x.unknown"}) {
    EXPECT_THROW(write_mesh(path(name), sample_mesh()), gsp::IoError) << name;
    EXPECT_FALSE(fs::exists(path(name)));
  }
}

}  // namespace
