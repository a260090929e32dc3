// Big text files are parsed on several threads (io/src/text_pieces.hpp): the result must be
// the serial reader's to the bit, and a broken file must give the serial reader's error with
// its line, whatever the number of threads and wherever the pieces are cut.
#include <gsp/errors.hpp>
#include <gsp/io/mesh_io.hpp>

#include <gtest/gtest.h>

#include "apps_support.hpp"   // ScratchDir
#include "test_data.hpp"

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace {

namespace fs = std::filesystem;
using gsp::io::ReadOptions;
using gsp::io::ReadResult;
using gsp::test::ScratchDir;

// An n x n grid of vertices (2 (n-1)^2 triangles): about 3 MB of text for n = 250, above the
// size from which the readers go parallel.
constexpr int kN = 250;

double coord(int i, int j, int k) { return 0.001 * (i * 7 + j * 13 + k) + 1.0 / (3 + i + j); }

struct Variant {
  bool colors = false, crlf = false, relative = false, quads = false, comments = false;
  int bad_line = -1;   // a vertex or face line (index among them) replaced by garbage
};

std::string obj_text(const Variant& v) {
  std::ostringstream s;
  s.precision(17);
  const char* end = v.crlf ? "\r\n" : "\n";
  int line = 0;
  auto bad = [&]() { return line++ == v.bad_line; };
  s << "# grid" << end << "o grid" << end;
  for (int i = 0; i < kN; ++i)
    for (int j = 0; j < kN; ++j) {
      if (bad()) {
        s << "v 1.0 x2 3.0" << end;
        continue;
      }
      s << "v " << coord(i, j, 0) << ' ' << coord(i, j, 1) << ' ' << coord(i, j, 2);
      if (v.colors) s << ' ' << (i % 256) / 255.0 << ' ' << (j % 256) / 255.0 << " 0.5";
      s << end;
      if (v.comments && j == 0) s << "vt 0.5 0.5" << end << "# row " << i << end << end;
    }
  auto id = [](int i, int j) { return i * kN + j + 1; };
  for (int i = 0; i + 1 < kN; ++i)
    for (int j = 0; j + 1 < kN; ++j) {
      const int a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      auto ref = [&](int x) { return v.relative ? std::to_string(x - kN * kN - 1) : std::to_string(x) + "/1"; };
      if (bad()) {
        s << "f 1 2" << end;
        continue;
      }
      if (v.quads && (i + j) % 3 == 0) {
        s << "f " << ref(a) << ' ' << ref(b) << ' ' << ref(c) << ' ' << ref(d) << end;
      } else {
        s << "f " << ref(a) << ' ' << ref(b) << ' ' << ref(c) << end;
        s << "f " << ref(a) << ' ' << ref(c) << ' ' << ref(d) << end;
      }
    }
  return s.str();
}

std::string ply_text(const Variant& v) {
  std::ostringstream body;
  body.precision(9);
  const char* end = v.crlf ? "\r\n" : "\n";
  int line = 0, faces = 0;
  auto bad = [&]() { return line++ == v.bad_line; };
  for (int i = 0; i < kN; ++i)
    for (int j = 0; j < kN; ++j) {
      if (bad()) {
        body << "1 2 nan" << (v.colors ? " 1 2 3 0.25 7" : "") << end;
        continue;
      }
      body << coord(i, j, 0) << ' ' << coord(i, j, 1) << "  " << coord(i, j, 2);
      if (v.colors) body << ' ' << i % 256 << ' ' << j % 256 << " 9 " << 0.125 * j << ' ' << i - j;
      body << end;
    }
  for (int i = 0; i + 1 < kN; ++i)
    for (int j = 0; j + 1 < kN; ++j) {
      const int a = i * kN + j, b = a + kN, c = b + 1, d = a + 1;
      if (bad()) {
        body << "3 0 1 " << kN * kN << end;
        ++faces;
        continue;
      }
      if (v.quads && (i + j) % 3 == 0) {
        body << "4 " << a << ' ' << b << ' ' << c << ' ' << d << end;
        ++faces;
      } else {
        body << "3 " << a << ' ' << b << ' ' << c << end << "3 " << a << ' ' << c << ' ' << d << end;
        faces += 2;
      }
    }
  std::ostringstream s;
  s << "ply" << end << "format ascii 1.0" << end << "element vertex " << kN * kN << end << "property float x" << end
    << "property double y" << end << "property float z" << end;
  if (v.colors)
    s << "property uchar red" << end << "property uchar green" << end << "property uchar blue" << end
      << "property float quality" << end << "property int label" << end;
  s << "element face " << faces << end << "property list uchar int vertex_indices" << end << "end_header" << end
    << body.str();
  return s.str();
}

std::string write(const ScratchDir& dir, const std::string& name, const std::string& text) {
  const std::string path = (dir / name).string();
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

// Reads `path` on 1, 2 and 3 threads (parallel from `from_bytes` on): the same mesh and
// attributes, or the same error. Returns the serial reader's error message ("" when it read
// the file).
std::string expect_same(const std::string& path, std::size_t from_bytes = ReadOptions{}.parallel_from_bytes) {
  std::string errors[3];
  ReadResult results[3];
  for (unsigned t = 1; t <= 3; ++t) {
    ReadOptions options;
    options.threads = t;
    options.parallel_from_bytes = from_bytes;
    try {
      results[t - 1] = gsp::io::read_mesh(path, options);
    } catch (const gsp::Error& e) {
      errors[t - 1] = e.what();
    }
  }
  for (int t = 1; t < 3; ++t) {
    SCOPED_TRACE("threads " + std::to_string(t + 1));
    EXPECT_EQ(errors[t], errors[0]);
    if (!errors[0].empty()) continue;
    const ReadResult& a = results[0];
    const ReadResult& b = results[t];
    EXPECT_EQ(b.mesh.triangles, a.mesh.triangles);
    EXPECT_EQ(b.mesh.positions.size(), a.mesh.positions.size());
    if (b.mesh.positions.size() != a.mesh.positions.size()) continue;
    EXPECT_EQ(0, std::memcmp(b.mesh.positions.data(), a.mesh.positions.data(), a.mesh.positions.size() * sizeof(gsp::Vec3)));
    EXPECT_EQ(b.attributes.colors, a.attributes.colors);
    EXPECT_EQ(b.attributes.scalars, a.attributes.scalars);
    EXPECT_EQ(b.attributes.labels, a.attributes.labels);
    EXPECT_EQ(b.info.file_vertices, a.info.file_vertices);
    EXPECT_EQ(b.info.file_faces, a.info.file_faces);
    EXPECT_EQ(b.info.polygons_split, a.info.polygons_split);
    EXPECT_EQ(b.info.notes, a.info.notes);
  }
  return errors[0];
}

// Each variant written as one file of more than 1 MB: read alike by 1, 2 and 3 threads.
template <class Text>
void variants_read_alike(const ScratchDir& dir, const std::vector<Variant>& variants, const char* ext, Text text) {
  int k = 0;
  for (const Variant& v : variants) {
    SCOPED_TRACE("variant " + std::to_string(k));
    const std::string path = write(dir, "grid" + std::to_string(k++) + ext, text(v));
    ASSERT_GT(fs::file_size(path), std::uintmax_t(1) << 20);
    EXPECT_EQ(expect_same(path), "");
  }
}

TEST(ParallelRead, ObjVariantsReadAlike) {
  const ScratchDir dir("parallel-read");
  variants_read_alike(dir,
                      {{}, {true}, {false, true}, {false, false, true}, {false, false, false, true},
                       {false, false, false, false, true}, {true, true, true, true, true}},
                      ".obj", obj_text);
  // The values themselves: vertex 0, the last triangle, colours in 0..255.
  const ReadResult r = gsp::io::read_mesh(write(dir, "c.obj", obj_text({true})), ReadOptions{2});
  EXPECT_EQ(r.mesh.positions[0].x, coord(0, 0, 0));
  EXPECT_EQ(r.mesh.num_faces(), std::size_t(2 * (kN - 1) * (kN - 1)));
  EXPECT_EQ(r.mesh.triangles.back(), (gsp::Triangle{kN * kN - kN - 2, kN * kN - 1, kN * kN - kN - 1}));
  EXPECT_EQ(r.attributes.colors.at(kN).at(0), 1);
}

TEST(ParallelRead, ObjErrorsNameTheSerialLine) {
  const ScratchDir dir("parallel-read");
  for (int bad : {5, kN * kN / 2, kN * kN + 17, kN * kN + (kN - 1) * (kN - 1) - 1}) {
    SCOPED_TRACE("bad line " + std::to_string(bad));
    Variant v;
    v.bad_line = bad;
    const std::string message = expect_same(write(dir, "bad.obj", obj_text(v)));
    EXPECT_NE(message.find(bad < kN * kN ? "is not a number" : "2 corners"), std::string::npos) << message;
  }
  // A relative index reaching before the first vertex, in the last piece.
  std::string text = obj_text({});
  text += "f -1 -2 -" + std::to_string(kN * kN + 1) + "\n";
  const std::string message = expect_same(write(dir, "rel.obj", text));
  EXPECT_NE(message.find("points before the first vertex"), std::string::npos) << message;
}

TEST(ParallelRead, PlyAsciiVariantsReadAlike) {
  const ScratchDir dir("parallel-read");
  variants_read_alike(dir, {{}, {true}, {false, true}, {false, false, false, true}, {true, true, false, true}},
                      ".ply", ply_text);
  const ReadResult r = gsp::io::read_mesh(write(dir, "c.ply", ply_text({true})), ReadOptions{2});
  EXPECT_EQ(r.mesh.positions[1].x, double(float(coord(0, 1, 0))));
  EXPECT_EQ(r.mesh.positions[1].y, coord(0, 1, 1));
  ASSERT_EQ(r.attributes.labels.size(), 1u);
  EXPECT_EQ(r.attributes.labels[0].second[kN + 1], 0);
  EXPECT_EQ(r.attributes.colors[kN].at(0), 1);
}

TEST(ParallelRead, PlyAsciiErrorsNameTheSerialLine) {
  const ScratchDir dir("parallel-read");
  // The body starts on line 10; a face line stands for half a grid square.
  for (int bad : {0, kN * kN - 1, kN * kN + 3, kN * kN + (kN - 1) * (kN - 1) - 1}) {
    SCOPED_TRACE("bad line " + std::to_string(bad));
    Variant v;
    v.bad_line = bad;
    const std::string message = expect_same(write(dir, "bad.ply", ply_text(v)));
    const int line = bad < kN * kN ? 10 + bad : 10 + kN * kN + 2 * (bad - kN * kN);
    EXPECT_NE(message.find(bad < kN * kN ? "non-finite" : "out of range"), std::string::npos) << message;
    EXPECT_NE(message.find(":line " + std::to_string(line) + ":"), std::string::npos) << message;
  }
  // A body with one line less than the header promises; then one line split in two.
  std::string text = ply_text({});
  text.erase(text.rfind('\n', text.size() - 2) + 1);
  EXPECT_NE(expect_same(write(dir, "short.ply", text)).find("file ends"), std::string::npos);
  text = ply_text({});
  text[text.find('\n', text.find("end_header") + 11) - 3] = '\n';
  expect_same(write(dir, "split.ply", text));
}

// Every small fixture, broken file and fuzz finding through the parallel parsers too (three
// threads, whatever the size): the same result or the same error as the serial reader.
TEST(ParallelReadSmall, FixturesAndBrokenFilesReadAlike) {
  int files = 0;
  for (const char* folder : {"io", "io/broken", "io/fuzz-regressions"}) {
    for (const auto& entry : fs::directory_iterator(gsp::test::bundled(folder))) {
      const std::string ext = entry.path().extension().string();
      if (!entry.is_regular_file() || (ext != ".obj" && ext != ".ply")) continue;
      SCOPED_TRACE(entry.path().string());
      expect_same(entry.path().string(), 0);
      ++files;
    }
  }
  EXPECT_GT(files, 20);
}

}  // namespace
