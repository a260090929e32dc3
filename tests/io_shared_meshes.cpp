// Every shared mesh is read with the vertex and face counts of data/meshes/SOURCES.md
// (the raw figures: STL and glTF vertices unshared, as stored).
#include <gsp/io/mesh_io.hpp>

#include <gtest/gtest.h>

#include "test_data.hpp"

namespace {

struct Golden {
  const char* file;
  gsp::io::Format format;
  std::size_t vertices, faces;
  bool binary, normals;
};

const Golden kGolden[] = {
    {"adis16480_sensor.stl", gsp::io::Format::stl, 22308, 7436, false, false},
    {"armadillo_remeshed.obj", gsp::io::Format::obj, 14587, 29170, false, false},
    {"b9_training_points.ply", gsp::io::Format::ply, 22300, 0, true, false},
    {"camelhead.off", gsp::io::Format::off, 11381, 22704, false, false},
    {"cesium_milk_truck.glb", gsp::io::Format::glb, 3564, 3624, true, true},
    {"cycloidal_drive.ply", gsp::io::Format::ply, 21384, 43368, true, false},
    {"falconstatue.obj", gsp::io::Format::obj, 25839, 51674, false, false},
    {"fertility.off", gsp::io::Format::off, 4494, 9000, false, false},
    {"kitten_points.xyz", gsp::io::Format::xyz, 5210, 0, false, true},
    {"manifold_offset1.obj", gsp::io::Format::obj, 2287, 4418, false, false},
    {"nefertiti_lowres.obj", gsp::io::Format::obj, 35002, 70000, false, false},
    {"newell_teapot.obj", gsp::io::Format::obj, 3644, 6320, false, false},
    {"openscad_nonmanifold_crash.obj", gsp::io::Format::obj, 717, 1442, false, false},
    {"stanford_bunny.obj", gsp::io::Format::obj, 35947, 69451, false, false},
    {"thingi10k_88566_fence_panels.stl", gsp::io::Format::stl, 16032, 5344, true, false},
    {"thingi10k_99865_tires.stl", gsp::io::Format::stl, 215922, 71974, true, false},
};

class SharedMesh : public ::testing::TestWithParam<Golden> {};

TEST_P(SharedMesh, CountsMatchSources) {
  if (!gsp::test::have_shared_data()) GTEST_SKIP() << "shared data folder missing: " << gsp::test::data_dir();
  const Golden& g = GetParam();
  const gsp::io::ReadResult r = gsp::io::read_mesh(gsp::test::shared_mesh(g.file));
  EXPECT_EQ(r.info.format, g.format);
  EXPECT_EQ(r.info.binary, g.binary);
  EXPECT_EQ(r.mesh.num_vertices(), g.vertices);
  EXPECT_EQ(r.mesh.num_faces(), g.faces);
  EXPECT_EQ(r.info.file_vertices, g.vertices);
  EXPECT_EQ(r.info.polygons_split, 0u);   // SOURCES.md: none of the files has polygons
  EXPECT_EQ(r.info.has_normals, g.normals);
  EXPECT_EQ(r.mesh.normals.size(), g.normals ? g.vertices : 0u);
  for (const gsp::Triangle& t : r.mesh.triangles)
    for (gsp::Index v : t) ASSERT_LT(v, r.mesh.num_vertices());
  for (const gsp::Vec3& p : r.mesh.positions) ASSERT_TRUE(gsp::is_finite(p));
}

INSTANTIATE_TEST_SUITE_P(AllFiles, SharedMesh, ::testing::ValuesIn(kGolden), [](const auto& info) {
  std::string name = info.param.file;
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name;
});

// The labelled point cloud keeps its colours and integer labels as attributes.
TEST(SharedMeshAttributes, PointCloudLabelsAndColours) {
  if (!gsp::test::have_shared_data()) GTEST_SKIP() << "shared data folder missing";
  const auto r = gsp::io::read_mesh(gsp::test::shared_mesh("b9_training_points.ply"));
  ASSERT_EQ(r.attributes.colors.size(), 22300u);
  ASSERT_EQ(r.attributes.labels.size(), 1u);
  EXPECT_EQ(r.attributes.labels[0].first, "label");
  EXPECT_EQ(r.attributes.labels[0].second.size(), 22300u);
  // SOURCES.md: georeferenced doubles, x ~ 5.97e5, y ~ 2.44e5.
  EXPECT_NEAR(r.mesh.positions[0].x, 5.97e5, 0.05e5);
  EXPECT_NEAR(r.mesh.positions[0].y, 2.44e5, 0.05e5);
}

// Triangle count of an STL soup equals its vertex count / 3, corners in file order.
TEST(SharedMeshAttributes, StlCornersUnshared) {
  if (!gsp::test::have_shared_data()) GTEST_SKIP() << "shared data folder missing";
  const auto r = gsp::io::read_mesh(gsp::test::shared_mesh("adis16480_sensor.stl"));
  for (std::size_t f = 0; f < r.mesh.num_faces(); ++f)
    for (int k = 0; k < 3; ++k) ASSERT_EQ(r.mesh.triangles[f][k], 3 * f + k);
}

}  // namespace
