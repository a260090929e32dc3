// gsp-path end to end: every output format read back (OBJ l elements, PLY edges, glTF
// LINE_STRIP, JSON points) against the library's path; exit 3 for end points that cannot be
// reached; exit 1 / 2 for bad input and usage, nothing left behind.
#include "apps_support.hpp"

#include <gsp/geodesics.hpp>
#include <gsp/io/mesh_io.hpp>
#include <gsp/pathfinding/shortest_path.hpp>

#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include <cstdio>

namespace {

using namespace gsp;
using namespace gsp::test;

const std::string kMesh = std::string(GSP_TEST_DIR) + "/../data/samples/fertility.off";
const std::string kApp = bin("gsp-path");

double library_length(Index from, Index to) {
  const TriangleMesh mesh = io::read_mesh(kMesh).mesh;
  const GeodesicSolver solver(mesh);
  const pathfinding::PathTracer tracer(mesh);
  pathfinding::PathQueryOptions o;
  o.method = pathfinding::PathMethod::windows;   // gsp-path's default
  const auto r = pathfinding::shortest_paths(solver, tracer, pathfinding::Endpoint::at_vertex(from),
                                             {pathfinding::Endpoint::at_vertex(to)}, o);
  return r.paths.at(0).length;
}

double polyline_length(const std::vector<Vec3>& pts) {
  double l = 0;
  for (std::size_t i = 1; i < pts.size(); ++i) l += distance(pts[i - 1], pts[i]);
  return l;
}

TEST(PathApp, ObjLinesAndStatsMatchTheLibrary) {
  ScratchDir dir("path");
  const auto out = dir / "p.obj";
  const RunResult r = run(kApp + " " + quote(kMesh) + " --from 0 --to 2000 --to 500 --stats - -o " + quote(out.string()), dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const JsonValue stats = parse_json(r.out);
  const JsonValue& paths = stats["result"]["paths"];
  ASSERT_EQ(paths.items.size(), 2u);
  EXPECT_NEAR(paths.items[0]["length"].num, library_length(0, 2000), 1e-9);
  EXPECT_GT(stats["operations"]["faces_expanded"].num, 0);
  EXPECT_LT(stats["operations"]["faces_expanded_fraction"].num, 1.0);
  // OBJ: v lines then one l element per path; each element's polyline has the path's length.
  std::vector<Vec3> v;
  std::vector<std::vector<Index>> elements;
  for (const std::string& line : lines(slurp(out))) {
    if (line.rfind("v ", 0) == 0) {
      Vec3 p;
      ASSERT_EQ(std::sscanf(line.c_str(), "v %lf %lf %lf", &p.x, &p.y, &p.z), 3);
      v.push_back(p);
    } else if (line.rfind("l ", 0) == 0) {
      std::stringstream ss(line.substr(2));
      std::vector<Index> e;
      for (long long i; ss >> i;) e.push_back(Index(i - 1));
      elements.push_back(e);
    }
  }
  ASSERT_EQ(elements.size(), 2u);
  for (std::size_t k = 0; k < 2; ++k) {
    std::vector<Vec3> pts;
    for (Index i : elements[k]) pts.push_back(v.at(i));
    EXPECT_NEAR(polyline_length(pts), paths.items[k]["length"].num, 1e-9 * paths.items[k]["length"].num);
    EXPECT_EQ(double(pts.size()), paths.items[k]["points"].num);
  }
}

// --one-end skips the propagations from the end points: the path is the one traced in
// --from's field, never shorter than the default's (which keeps the shorter of two).
TEST(PathApp, OneEndTracesOneField) {
  ScratchDir dir("path");
  const auto out = dir / "p.obj";
  const std::string base = kApp + " " + quote(kMesh) + " --from 0 --to 2000 --to 500 --stats - -o " + quote(out.string());
  const RunResult both = run(base, dir);
  const RunResult one = run(base + " --one-end", dir);
  ASSERT_EQ(both.exit_code, 0) << both.err;
  ASSERT_EQ(one.exit_code, 0) << one.err;
  const JsonValue sb = parse_json(both.out), so = parse_json(one.out);
  EXPECT_GT(sb["operations"]["reverse_faces_expanded"].num, 0);
  EXPECT_EQ(so["operations"]["reverse_faces_expanded"].num, 0);
  EXPECT_EQ(so["result"]["reversed"].num, 0);
  for (std::size_t k = 0; k < 2; ++k)
    EXPECT_LE(sb["result"]["paths"].items[k]["length"].num, so["result"]["paths"].items[k]["length"].num * (1 + 1e-12));
}

TEST(PathApp, PlyEdgesGltfLineStripAndJson) {
  ScratchDir dir("path");
  const double expected = library_length(0, 2000);
  for (const std::string name : {"p.ply", "p.glb", "p.gltf", "p.json"}) {
    SCOPED_TRACE(name);
    const auto out = dir / name;
    const RunResult r = run(kApp + " " + quote(kMesh) + " --from 0 --to 2000 -o " + quote(out.string()), dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    std::vector<Vec3> pts;
    if (name == "p.ply") {
      const std::string text = slurp(out);
      ASSERT_NE(text.find("element edge"), std::string::npos);
      // The reader takes the vertices (the edge element is not a face list): the points in order.
      pts = io::read_mesh(out.string()).mesh.positions;
    } else if (name == "p.json") {
      const JsonValue doc = parse_json(slurp(out));
      const JsonValue& p = doc["paths"].items.at(0);
      EXPECT_TRUE(p["found"].b);
      for (const JsonValue& q : p["points"].items) {
        const auto& pos = q["position"].items;
        pts.push_back({pos.at(0).num, pos.at(1).num, pos.at(2).num});
        EXPECT_NEAR(q["barycentric"].items[0].num + q["barycentric"].items[1].num + q["barycentric"].items[2].num, 1, 1e-9);
      }
      EXPECT_NEAR(p["length"].num, expected, 1e-9 * expected);
    } else {
      tinygltf::Model model;
      tinygltf::TinyGLTF loader;
      std::string err, warn;
      const bool ok = name == "p.glb" ? loader.LoadBinaryFromFile(&model, &err, &warn, out.string())
                                      : loader.LoadASCIIFromFile(&model, &err, &warn, out.string());
      ASSERT_TRUE(ok) << err;
      ASSERT_EQ(model.meshes.size(), 1u);
      const tinygltf::Primitive& prim = model.meshes[0].primitives.at(0);
      EXPECT_EQ(prim.mode, TINYGLTF_MODE_LINE_STRIP);
      const tinygltf::Accessor& a = model.accessors[prim.attributes.at("POSITION")];
      const tinygltf::BufferView& bv = model.bufferViews[a.bufferView];
      const float* f = reinterpret_cast<const float*>(model.buffers[bv.buffer].data.data() + bv.byteOffset + a.byteOffset);
      for (std::size_t i = 0; i < a.count; ++i) pts.push_back({f[3 * i], f[3 * i + 1], f[3 * i + 2]});
    }
    // glTF stores floats: the length within float rounding.
    EXPECT_NEAR(polyline_length(pts), expected, 1e-5 * expected);
  }
}

TEST(PathApp, UnreachableEndPointExitsThree) {
  ScratchDir dir("path");
  // Two separate tetrahedra.
  std::string obj;
  for (int c = 0; c < 2; ++c) {
    const double o = 10.0 * c;
    obj += "v " + std::to_string(o) + " 0 0\nv " + std::to_string(o + 1) + " 0 0\nv " + std::to_string(o) +
           " 1 0\nv " + std::to_string(o) + " 0 1\n";
  }
  for (int c = 0; c < 2; ++c) {
    const int b = 4 * c + 1;
    obj += "f " + std::to_string(b) + " " + std::to_string(b + 2) + " " + std::to_string(b + 1) + "\n";
    obj += "f " + std::to_string(b) + " " + std::to_string(b + 1) + " " + std::to_string(b + 3) + "\n";
    obj += "f " + std::to_string(b) + " " + std::to_string(b + 3) + " " + std::to_string(b + 2) + "\n";
    obj += "f " + std::to_string(b + 1) + " " + std::to_string(b + 2) + " " + std::to_string(b + 3) + "\n";
  }
  write_file(dir / "two.obj", obj);
  const auto out = dir / "p.obj";
  RunResult r = run(kApp + " " + quote((dir / "two.obj").string()) + " --from 0 --to 6 -o " + quote(out.string()), dir);
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_NE(r.err.find("no path"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out)) << "nothing to write when no end point is reached";
  // One reachable, one not: the reachable path is written, exit code still 3.
  r = run(kApp + " " + quote((dir / "two.obj").string()) + " --from 0 --to 2 --to 6 -o " + quote(out.string()), dir);
  EXPECT_EQ(r.exit_code, 3) << r.err;
  ASSERT_TRUE(fs::exists(out));
  EXPECT_NE(slurp(out).find("\nl "), std::string::npos);
}

TEST(PathApp, ErrorsAndUsage) {
  ScratchDir dir("path");
  const auto out = dir / "p.obj";
  const std::string base = kApp + " " + quote(kMesh) + " -o " + quote(out.string());
  RunResult r = run(base + " --from 0 --to 999999", dir);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(lines(r.err).size(), 1u) << r.err;
  r = run(base + " --from 0 --to 1,2", dir);   // neither a vertex, a point nor F:u,v
  EXPECT_EQ(r.exit_code, 2) << r.err;
  r = run(base + " --from 0 --to 5 --method nope", dir);
  EXPECT_EQ(r.exit_code, 2);
  r = run(kApp + " " + quote(kMesh) + " --from 0 --to 5 -o " + quote((dir / "p.stl").string()), dir);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  r = run(kApp + " " + quote((dir / "missing.obj").string()) + " --from 0 --to 5 -o " + quote(out.string()), dir);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
