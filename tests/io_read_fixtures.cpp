// One small fixture per format feature (tests/data/io, written by hand or by
// tests/data/io/make_fixtures.py); expected values worked out from the files themselves.
#include <gsp/io/mesh_io.hpp>

#include <gtest/gtest.h>

#include "test_data.hpp"

namespace {

using gsp::Triangle;
using gsp::Vec3;
using gsp::io::read_mesh;

std::string fixture(const std::string& name) { return gsp::test::bundled("io/" + name); }

std::vector<Triangle> tris(std::initializer_list<Triangle> t) { return t; }

TEST(ReadObj, QuadsNegativeIndicesSlashFormsCrlfColours) {
  const auto r = read_mesh(fixture("features.obj"));
  ASSERT_EQ(r.mesh.num_vertices(), 5u);
  EXPECT_EQ(r.info.file_faces, 4u);   // 4 `f` lines; the quad gives 2 triangles
  EXPECT_EQ(r.info.polygons_split, 1u);
  EXPECT_EQ(r.mesh.triangles, tris({{0, 1, 2}, {0, 2, 3}, {0, 1, 4}, {1, 2, 4}, {2, 3, 4}}));
  EXPECT_EQ(r.mesh.positions[4], (Vec3{0.5, 0.5, 1}));
  ASSERT_EQ(r.attributes.colors.size(), 5u);
  EXPECT_EQ(r.attributes.colors[0], (std::array<std::uint8_t, 4>{255, 0, 0, 255}));
  EXPECT_EQ(r.attributes.colors[2], (std::array<std::uint8_t, 4>{0, 0, 255, 255}));
  EXPECT_EQ(r.attributes.colors[4], (std::array<std::uint8_t, 4>{128, 128, 128, 255}));
  EXPECT_FALSE(r.info.notes.empty());   // vt, vn, vp, g, o, s, usemtl, mtllib, l were noted
}

TEST(ReadObj, PentagonsAndUglyFacesKept) {
  const auto r = read_mesh(fixture("pentagon.obj"));
  EXPECT_EQ(r.mesh.num_vertices(), 5u);
  EXPECT_EQ(r.info.file_faces, 3u);
  EXPECT_EQ(r.info.polygons_split, 2u);
  // Fan triangulation, the repeated-index face and the duplicate pentagon all kept as they are.
  EXPECT_EQ(r.mesh.triangles, tris({{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 0, 1}, {0, 1, 2}, {0, 2, 3}, {0, 3, 4}}));
  EXPECT_TRUE(r.attributes.colors.empty());
}

TEST(ReadPly, BigEndianWithExtraPropertiesListsAndElements) {
  const auto r = read_mesh(fixture("big_endian_extras.ply"));
  EXPECT_TRUE(r.info.binary);
  ASSERT_EQ(r.mesh.num_vertices(), 5u);
  EXPECT_EQ(r.info.file_faces, 3u);
  EXPECT_EQ(r.mesh.triangles, tris({{0, 1, 2}, {0, 2, 3}, {0, 1, 4}, {1, 2, 4}}));
  EXPECT_EQ(r.mesh.positions[4], (Vec3{0.5, 0.5, 1}));   // doubles, exact
  ASSERT_TRUE(r.info.has_normals);
  EXPECT_EQ(r.mesh.normals[3], (Vec3{0, 0, 1}));
  ASSERT_EQ(r.attributes.scalars.size(), 1u);
  EXPECT_EQ(r.attributes.scalars[0].first, "quality");
  EXPECT_EQ(r.attributes.scalars[0].second, (std::vector<float>{0, 0.25f, 0.5f, 0.75f, 1.0f}));
}

TEST(ReadPly, CharCountUcharIndicesColoursLabels) {
  const auto r = read_mesh(fixture("uchar_indices.ply"));
  EXPECT_EQ(r.mesh.triangles, tris({{0, 1, 2}, {1, 3, 2}}));
  ASSERT_EQ(r.attributes.colors.size(), 4u);
  EXPECT_EQ(r.attributes.colors[3], (std::array<std::uint8_t, 4>{30, 60, 90, 255}));
  ASSERT_EQ(r.attributes.labels.size(), 1u);
  EXPECT_EQ(r.attributes.labels[0].second, (std::vector<std::int32_t>{100, 101, 102, 103}));
}

TEST(ReadPly, AsciiPolygonsExtraListAndElement) {
  const auto r = read_mesh(fixture("ascii_polygons.ply"));
  EXPECT_FALSE(r.info.binary);
  EXPECT_EQ(r.mesh.num_vertices(), 4u);
  EXPECT_EQ(r.info.file_faces, 2u);
  EXPECT_EQ(r.info.polygons_split, 1u);
  EXPECT_EQ(r.mesh.triangles, tris({{0, 1, 2}, {0, 2, 3}, {0, 0, 1}}));
  ASSERT_EQ(r.attributes.scalars.size(), 1u);
  EXPECT_EQ(r.attributes.scalars[0].second, (std::vector<float>{0.5f, 1.5f, 2.5f, 3.5f}));
}

TEST(ReadOff, CommentsBlankLinesPolygons) {
  const auto r = read_mesh(fixture("comments_polygons.off"));
  EXPECT_EQ(r.mesh.num_vertices(), 6u);
  EXPECT_EQ(r.info.file_faces, 3u);
  EXPECT_EQ(r.info.polygons_split, 2u);
  EXPECT_EQ(r.mesh.triangles, tris({{0, 1, 2}, {0, 2, 3}, {1, 4, 5}, {0, 1, 5}, {0, 5, 2}, {0, 2, 3}}));
  EXPECT_EQ(r.mesh.positions[5], (Vec3{2, 1, 0}));
}

TEST(ReadOff, CoffColours) {
  const auto r = read_mesh(fixture("colored.off"));
  ASSERT_EQ(r.attributes.colors.size(), 3u);
  EXPECT_EQ(r.attributes.colors[0], (std::array<std::uint8_t, 4>{255, 0, 0, 255}));
  EXPECT_EQ(r.attributes.colors[1], (std::array<std::uint8_t, 4>{0, 255, 0, 128}));
  EXPECT_EQ(r.attributes.colors[2], (std::array<std::uint8_t, 4>{0, 0, 255, 0}));
}

TEST(ReadStl, AsciiCrlfSeveralSolids) {
  const auto r = read_mesh(fixture("crlf_ascii.stl"));
  EXPECT_FALSE(r.info.binary);
  EXPECT_EQ(r.info.file_faces, 3u);
  EXPECT_EQ(r.mesh.num_vertices(), 9u);
  EXPECT_EQ(r.mesh.triangles, tris({{0, 1, 2}, {3, 4, 5}, {6, 7, 8}}));
  EXPECT_EQ(r.mesh.positions[8], (Vec3{1, 0, 1}));
}

TEST(ReadStl, BinaryWhoseHeaderSaysSolid) {
  const auto r = read_mesh(fixture("solid_header_binary.stl"));
  EXPECT_TRUE(r.info.binary);
  EXPECT_EQ(r.mesh.num_faces(), 2u);
  EXPECT_EQ(r.mesh.num_vertices(), 6u);
  EXPECT_EQ(r.mesh.positions[4], (Vec3{1, 1, 0}));
}

TEST(ReadXyz, CountLineCommentsBlankLines) {
  const auto r = read_mesh(fixture("count_header.xyz"));
  EXPECT_TRUE(r.mesh.is_point_cloud());
  EXPECT_EQ(r.mesh.num_vertices(), 3u);
  EXPECT_FALSE(r.info.has_normals);
  EXPECT_EQ(r.mesh.positions[2], (Vec3{0, 1, 0}));
}

// Root T(10,0,0) -> child S(2) with an indexed quad; sibling R(90 deg about z) with a
// non-indexed triangle, a strip of 4, a fan of 5 and a skipped LINES primitive; node 3 is
// outside the scene.
void expect_scene(const gsp::io::ReadResult& r) {
  ASSERT_EQ(r.mesh.num_vertices(), 16u);
  EXPECT_EQ(r.mesh.triangles, tris({{0, 1, 2}, {0, 2, 3}, {4, 5, 6}, {7, 8, 9}, {9, 8, 10},
                                    {11, 12, 13}, {11, 13, 14}, {11, 14, 15}}));
  const Vec3 expected[] = {{10, 0, 0}, {12, 0, 0}, {12, 2, 0}, {10, 2, 0}, {10, 0, 0}, {10, 1, 0}, {9, 0, 0},
                           {10, 0, 1}, {10, 1, 1}, {9, 0, 1}, {9, 1, 1}, {10, 0, 2}, {10, 1, 2}, {9, 1, 2},
                           {9, 0, 2}, {9, -1, 2}};
  for (std::size_t i = 0; i < 16; ++i) EXPECT_LT(gsp::distance(r.mesh.positions[i], expected[i]), 1e-6) << "vertex " << i;
  bool noted_lines = false;
  for (const auto& n : r.info.notes) noted_lines |= n.find("mode 1") != std::string::npos;
  EXPECT_TRUE(noted_lines);
}

TEST(ReadGltf, NodeTransformsStripFanNonIndexed) {
  const auto r = read_mesh(fixture("scene_transforms.gltf"));
  EXPECT_EQ(r.info.format, gsp::io::Format::gltf);
  expect_scene(r);
}

TEST(ReadGltf, SameSceneAsGlb) {
  const auto r = read_mesh(fixture("scene_transforms.glb"));
  EXPECT_EQ(r.info.format, gsp::io::Format::glb);
  EXPECT_TRUE(r.info.binary);
  expect_scene(r);
}

TEST(ReadGltf, PointsOnlyIsPointCloud) {
  const auto r = read_mesh(fixture("points_only.gltf"));
  EXPECT_TRUE(r.mesh.is_point_cloud());
  EXPECT_EQ(r.mesh.num_vertices(), 4u);
}

TEST(FormatFromPath, CaseInsensitiveExtensions) {
  using gsp::io::Format;
  EXPECT_EQ(gsp::io::format_from_path("a/b.PLY"), Format::ply);
  EXPECT_EQ(gsp::io::format_from_path("x.Glb"), Format::glb);
  EXPECT_EQ(gsp::io::format_from_path("x.txt"), Format::txt);
  EXPECT_EQ(gsp::io::format_from_path("dir.obj/file"), Format::unknown);
  EXPECT_EQ(gsp::io::format_from_path("noext"), Format::unknown);
}

}  // namespace
