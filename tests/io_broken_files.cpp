// A corpus of broken files (tests/data/io/broken, plus fuzz regressions): each must throw
// gsp::IoError whose message names the file and, where the format has one, the place.
#include <gsp/io/mesh_io.hpp>

#include <gtest/gtest.h>

#include <filesystem>
#include <set>

#include "test_data.hpp"

namespace {

struct Broken {
  const char* file;
  const char* place;   // expected in the message after the file name ("" = no place)
  const char* what;    // expected substring of the description
};

const Broken kBroken[] = {
    {"empty.obj", "", "empty file"},
    {"empty.ply", "", "empty file"},
    {"empty.off", "", "empty file"},
    {"empty.stl", "", "empty file"},
    {"empty.gltf", "", "empty file"},
    {"empty.glb", "", "empty file"},
    {"empty.xyz", "", "empty file"},
    {"wrong_magic.ply", ":line 1:", "magic"},
    {"wrong_magic.off", ":line 1:", "magic"},
    {"wrong_magic.glb", ":byte 0:", "magic"},
    {"glb_version1.glb", ":byte 4:", "version 1"},
    {"truncated.glb", ":byte 938:", "truncated"},
    {"truncated_json_chunk.glb", ":byte 20:", "truncated"},
    {"truncated.stl", ":byte 154:", "truncated"},
    {"tiny.stl", ":byte 40:", "truncated"},
    {"absurd_count.stl", ":byte 184:", "4000000000 triangles"},
    {"truncated_binary.ply", ":byte ", "truncated"},
    {"absurd_count.ply", ":line 3:", "4000000000"},
    {"absurd_list.ply", ":byte 204:", "truncated: list of 4000000000"},
    {"index_out_of_range.ply", ":line 13:", "out of range"},
    {"negative_index.ply", ":line 13:", "index -1"},
    {"nan_vertex.ply", ":line 9:", "vertex 1 has a non-finite"},
    {"no_end_header.ply", ":line 4:", "end_header"},
    {"nan_vertex.obj", ":line 3:", "vertex 2 has a non-finite"},
    {"inf_vertex.xyz", ":line 2:", "vertex 1 has a non-finite"},
    {"index_out_of_range.obj", ":line 4:", "out of range"},
    {"negative_index.obj", ":line 4:", "points before the first vertex"},
    {"zero_index.obj", ":line 4:", "index 0"},
    {"two_corners.obj", ":line 4:", "2 corners"},
    {"garbage.obj", "", "no vertices"},
    {"index_out_of_range.off", ":line 6:", "out of range"},
    {"negative_index.off", ":line 6:", "index -1"},
    {"nan_vertex.off", ":line 4:", "vertex 1 has a non-finite"},
    {"absurd_count.off", ":line 2:", "cannot fit"},
    {"truncated.off", ":line 6:", "1 of 2 faces"},
    {"nan_vertex.stl", ":line 5:", "vertex 1 has a non-finite"},
    {"unclosed_facet.stl", ":line 4:", "inside a facet"},
    {"mesh.unknownext", "", "unknown mesh format"},
    {"not_json.gltf", "", "glTF"},
    {"accessor_overrun.gltf", ":accessor 0:", "exceeds bufferView"},
    {"accessor_offset.gltf", ":accessor 0:", "exceeds bufferView"},
    {"accessor_component.gltf", "", "componentType"},   // tinygltf rejects it first,
    {"index_out_of_range.gltf", ":accessor 1:", "out of range"},
    {"bufferview_overrun.gltf", ":accessor 0:", "exceeds buffer 0"},
};

std::string broken_path(const std::string& name) { return gsp::test::bundled("io/broken/" + name); }

class BrokenFile : public ::testing::TestWithParam<Broken> {};

TEST_P(BrokenFile, ThrowsIoErrorNamingFileAndPlace) {
  const Broken& b = GetParam();
  const std::string path = broken_path(b.file);
  ASSERT_TRUE(std::filesystem::exists(path)) << path;
  try {
    gsp::io::read_mesh(path);
    FAIL() << b.file << " was read without an error";
  } catch (const gsp::IoError& e) {
    const std::string msg = e.what();
    EXPECT_EQ(msg.rfind(path, 0), 0u) << msg;   // "<path>:<place>: <what>"
    EXPECT_NE(msg.find(path + b.place), std::string::npos) << msg;
    EXPECT_NE(msg.find(b.what), std::string::npos) << msg;
    EXPECT_EQ(e.path, path);
  }
}

INSTANTIATE_TEST_SUITE_P(Corpus, BrokenFile, ::testing::ValuesIn(kBroken), [](const auto& info) {
  std::string name = info.param.file;
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name;
});

// Every file in broken/ is in the table above, so a new broken file cannot go untested.
TEST(BrokenCorpus, EveryFileListed) {
  std::set<std::string> listed;
  for (const Broken& b : kBroken) listed.insert(b.file);
  for (const auto& entry : std::filesystem::directory_iterator(gsp::test::bundled("io/broken")))
    EXPECT_TRUE(listed.count(entry.path().filename().string())) << entry.path() << " is not in kBroken";
}

// Inputs that crashed or hung a reader under the fuzzers: each must now be read or rejected
// with gsp::Error, nothing else.
TEST(FuzzRegressions, ReadOrRejectCleanly) {
  const std::string dir = gsp::test::bundled("io/fuzz-regressions");
  if (!std::filesystem::exists(dir)) GTEST_SKIP() << "no fuzz regressions recorded";
  std::size_t files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    ++files;
    try {
      gsp::io::read_mesh(entry.path().string());
    } catch (const gsp::Error&) {
    }
  }
  EXPECT_GT(files, 0u);
}

}  // namespace
