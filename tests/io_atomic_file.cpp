// AtomicFile: a failed write leaves no temporary file and never touches an existing target.
#include <gsp/io/atomic_file.hpp>
#include <gsp/io/mesh_io.hpp>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <unistd.h>

namespace {

namespace fs = std::filesystem;

class Atomic : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("gsp_io_atomic_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  std::size_t entries() const { return static_cast<std::size_t>(std::distance(fs::directory_iterator(dir_), fs::directory_iterator())); }
  static std::string slurp(const std::string& p) {
    std::ifstream in(p, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  }
  static void put(const std::string& p, const std::string& text) { std::ofstream(p, std::ios::binary) << text; }
  fs::path dir_;
};

gsp::TriangleMesh triangle() {
  gsp::TriangleMesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  m.triangles = {{0, 1, 2}};
  return m;
}

TEST_F(Atomic, CommitReplacesTarget) {
  put(path("out.txt"), "old");
  {
    gsp::io::AtomicFile f(path("out.txt"));
    EXPECT_EQ(fs::path(f.temp_path()).parent_path(), dir_);   // same folder: rename is atomic
    f.write("new", 3);
    EXPECT_EQ(slurp(path("out.txt")), "old");   // not visible before commit
    f.commit();
  }
  EXPECT_EQ(slurp(path("out.txt")), "new");
  EXPECT_EQ(entries(), 1u);
}

TEST_F(Atomic, ExceptionBeforeCommitLeavesTargetAndNoTemp) {
  put(path("out.ply"), "precious");
  std::string temp;
  try {
    gsp::io::AtomicFile f(path("out.ply"));
    temp = f.temp_path();
    f.write("half a file", 11);
    throw std::runtime_error("writer failed half way");
  } catch (const std::runtime_error&) {
  }
  EXPECT_FALSE(fs::exists(temp));
  EXPECT_EQ(slurp(path("out.ply")), "precious");
  EXPECT_EQ(entries(), 1u);
}

TEST_F(Atomic, WriteMeshWithBadAttributesTouchesNothing) {
  put(path("mesh.ply"), "precious");
  gsp::io::VertexAttributes a;
  a.scalars = {{"distance", {1.0f}}};   // 1 value for 3 vertices
  EXPECT_THROW(gsp::io::write_mesh(path("mesh.ply"), triangle(), a), gsp::InvalidInput);
  EXPECT_EQ(slurp(path("mesh.ply")), "precious");
  EXPECT_EQ(entries(), 1u);
}

TEST_F(Atomic, RenameFailureRemovesTempAndKeepsTarget) {
  // A directory in the target's place makes the final rename fail after all bytes are written.
  fs::create_directories(path("mesh.obj"));
  put(path("mesh.obj") + "/inside", "x");
  try {
    gsp::io::write_mesh(path("mesh.obj"), triangle());
    FAIL() << "writing over a directory succeeded";
  } catch (const gsp::IoError& e) {
    EXPECT_NE(std::string(e.what()).find(path("mesh.obj")), std::string::npos) << e.what();
  }
  EXPECT_TRUE(fs::is_directory(path("mesh.obj")));
  EXPECT_EQ(slurp(path("mesh.obj") + "/inside"), "x");
  EXPECT_EQ(entries(), 1u);
}

TEST_F(Atomic, MissingFolderIsIoErrorNamingPath) {
  const std::string target = path("no/such/folder/mesh.ply");
  try {
    gsp::io::write_mesh(target, triangle());
    FAIL();
  } catch (const gsp::IoError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(target, 0), 0u) << e.what();
  }
  EXPECT_EQ(entries(), 0u);
}

TEST_F(Atomic, EveryWriterLeavesOnlyItsTarget) {
  for (const char* name : {"a.ply", "b.obj", "c.off", "d.gltf", "e.glb"}) gsp::io::write_mesh(path(name), triangle());
  gsp::io::write_values_txt(path("f.txt"), {1.0, 2.0, 3.0});
  EXPECT_EQ(entries(), 6u);
}

}  // namespace
