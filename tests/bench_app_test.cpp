// Integration tests of gsp-bench, run as a user runs it: the built binary on the bundled
// fertility sample (2 sources, 1 repetition) and on tiny meshes written here. Nothing here
// asserts a timing: only the shape of the reports, the source picks, the exact cache, the
// sharding and the exit codes.
#include "bench_support.hpp"

#include <gsp/io/mesh_io.hpp>

#include <algorithm>
#include <cmath>
#include <set>

namespace {

using gsp::test::bench_method;
using gsp::test::bench_mesh;
using gsp::test::JsonValue;
using gsp::test::parse_csv;
using gsp::test::parse_json;
using gsp::test::quote;
using gsp::test::run_bench;
using gsp::test::sample_fertility;
using gsp::test::ScratchDir;
namespace fs = std::filesystem;

const char* kTetrahedron =
    "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
// Three triangles on the edge 0-1: GSP propagates across it, CGAL refuses the mesh.
const char* kNonManifold =
    "OFF\n5 3 0\n0 0 0\n1 0 0\n0.5 1 0\n0.5 -1 0\n0.5 0 1\n3 0 1 2\n3 1 0 3\n3 0 1 4\n";

const std::vector<std::string> kCsvColumns = {
    "mesh", "vertices", "faces", "method", "status", "sources", "repetitions", "precompute_s", "query_s",
    "vertices_per_s", "cycles_per_vertex", "update_steps_per_triangle", "mre", "max_re", "unreached",
    "state_bytes_per_vertex", "solver_bytes_per_vertex", "vs_dijkstra", "vs_heat", "vs_heat_idt", "vs_gsp",
    "exact_cached", "clock", "below_line", "below_line_count", "above_edge", "above_edge_count",
    "edge_unreached", "nan_count"};

std::vector<double> sources_of(const JsonValue& method) {
  std::vector<double> out;
  for (const JsonValue& s : method["per_source"].items) out.push_back(s["source"].num);
  return out;
}

TEST(BenchApp, ReportsOneRowPerMeshAndMethod) {
  ScratchDir dir("bench");
  const std::string methods = "gsp,gsp-random-layout,gsp-no-layout,dijkstra,heat,heat-idt,exact";
  const auto r = run_bench(quote(sample_fertility()) + " --sources 2 --repetitions 1 --methods " + methods +
                               " --json " + quote((dir / "b.json").string()) + " --csv " +
                               quote((dir / "b.csv").string()),
                           dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("fertility.off: 4494 vertices, 9000 faces, 2 sources"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("gsp / dijkstra"), std::string::npos) << r.out;

  const auto rows = parse_csv(gsp::test::slurp(dir / "b.csv"));
  ASSERT_EQ(rows.size(), 8u);   // header + 7 methods
  EXPECT_EQ(rows[0], kCsvColumns);
  std::vector<std::string> names;
  for (std::size_t i = 1; i < rows.size(); ++i) {
    ASSERT_EQ(rows[i].size(), kCsvColumns.size());
    EXPECT_EQ(rows[i][0], "fertility.off");
    EXPECT_EQ(rows[i][1], "4494");
    EXPECT_EQ(rows[i][2], "9000");
    EXPECT_EQ(rows[i][4], "ok");
    EXPECT_EQ(rows[i][5], "2");
    EXPECT_EQ(rows[i][22], "wall");
    names.push_back(rows[i][3]);
    if (rows[i][3] == "exact") continue;
    EXPECT_GT(std::stod(rows[i][8]), 0.0) << rows[i][3];   // a query time was measured
    EXPECT_GT(std::stod(rows[i][12]), 0.0) << rows[i][3];  // an MRE against exact
  }
  EXPECT_EQ(names, (std::vector<std::string>{"gsp", "gsp-random-layout", "gsp-no-layout", "dijkstra", "heat",
                                             "heat-idt", "exact"}));

  const JsonValue report = parse_json(gsp::test::slurp(dir / "b.json"));
  EXPECT_EQ(report["app"].str, "gsp-bench");
  EXPECT_EQ(report["settings"]["repetitions"].num, 1);
  ASSERT_EQ(report["meshes"].items.size(), 1u);
  const JsonValue& mesh = report["meshes"].items[0];
  EXPECT_EQ(mesh["vertices"].num, 4494);
  EXPECT_EQ(mesh["methods"].items.size(), 7u);
  // One warm-up (untimed) and one repetition per source.
  for (const JsonValue& s : bench_method(mesh, "gsp")["per_source"].items) EXPECT_EQ(s["seconds"].items.size(), 1u);
  // Update steps per triangle from the per-source counts: mean(update_steps / faces reached),
  // and fertility is connected: every face is reached.
  const JsonValue& gsp = bench_method(mesh, "gsp");
  double steps = 0;
  for (const JsonValue& s : gsp["per_source"].items) {
    EXPECT_EQ(s["faces_reached"].num, 9000);
    steps += s["update_steps"].num;
  }
  EXPECT_NEAR(gsp["update_steps_per_triangle"].num, steps / 2 / 9000, 1e-12);
  EXPECT_GE(gsp["update_steps_per_triangle"].num, 1.0);   // every face is reached at least once
  EXPECT_GT(gsp["state_bytes_per_vertex"].num, 0.0);
  EXPECT_EQ(bench_method(mesh, "dijkstra")["state_bytes_per_vertex"].type, JsonValue::null);
}

// The threaded methods: the same distances as one thread up to GSP's order effects (their MRE
// against exact no worse than gsp's by 0.01 percentage points), and the JSON's speed-up and
// per-round overhead.
TEST(BenchApp, ThreadedMethodsReportSpeedupAndOverhead) {
  ScratchDir dir("bench");
  const auto r = run_bench(quote(sample_fertility()) + " --sources 2 --repetitions 1 --methods gsp,gsp-2threads,exact" +
                               " --json " + quote((dir / "b.json").string()),
                           dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const JsonValue doc = parse_json(gsp::test::slurp(dir / "b.json"));
  const JsonValue& gsp = bench_method(bench_mesh(doc, "fertility.off"), "gsp");
  const JsonValue& two = bench_method(bench_mesh(doc, "fertility.off"), "gsp-2threads");
  EXPECT_EQ(two["threads"].num, 2);
  EXPECT_GT(two["speedup"].num, 0.0);
  EXPECT_NEAR(two["speedup"].num, 1 / two["vs_gsp"].num, 1e-9);
  EXPECT_EQ(two["overhead_per_round_us"].type, JsonValue::number);
  EXPECT_LE(two["mre"].num, gsp["mre"].num + 1e-4);   // no worse by 0.01 percentage points
}

TEST(BenchApp, SameSourcesForEveryMethodAndRun) {
  ScratchDir dir("bench");
  const std::string common = quote(sample_fertility()) + " --sources 3 --repetitions 1 --no-table --methods " +
                             "gsp,gsp-bfs,gsp-random-layout,dijkstra,heat --json -";
  const auto a = run_bench(common + " --seed 7", dir);
  const auto b = run_bench(common + " --seed 7", dir);
  const auto c = run_bench(common + " --seed 8 --clock cpu", dir);
  ASSERT_EQ(a.exit_code, 0) << a.err;
  ASSERT_EQ(c.exit_code, 0) << c.err;
  const JsonValue ja = parse_json(a.out), jb = parse_json(b.out), jc = parse_json(c.out);
  const JsonValue& mesh = ja["meshes"].items[0];
  std::vector<double> picks;
  for (const JsonValue& s : mesh["sources"].items) picks.push_back(s.num);
  ASSERT_EQ(picks.size(), 3u);
  EXPECT_EQ(std::set<double>(picks.begin(), picks.end()).size(), 3u);   // drawn without replacement
  for (const JsonValue& m : mesh["methods"].items) EXPECT_EQ(sources_of(m), picks) << m["method"].str;

  std::vector<double> again, other;
  for (const JsonValue& s : jb["meshes"].items[0]["sources"].items) again.push_back(s.num);
  for (const JsonValue& s : jc["meshes"].items[0]["sources"].items) other.push_back(s.num);
  EXPECT_EQ(again, picks);    // seeded: the same picks every run
  EXPECT_NE(other, picks);    // another seed, other picks (3 of 4494 vertices)

  // --clock picks which of the two measured clocks is "seconds" (and so the medians).
  EXPECT_EQ(jc["settings"]["clock"].str, "cpu");
  for (const JsonValue& src : bench_method(jc["meshes"].items[0], "gsp")["per_source"].items) {
    ASSERT_EQ(src["seconds"].items.size(), 1u);
    EXPECT_EQ(src["seconds"].items[0].num, src["cpu_seconds"].items[0].num);
  }
  for (const JsonValue& src : bench_method(mesh, "gsp")["per_source"].items)
    EXPECT_EQ(src["seconds"].items[0].num, src["wall_seconds"].items[0].num);

  // Every pick is a vertex of some face.
  const gsp::TriangleMesh fertility = gsp::io::read_mesh(sample_fertility()).mesh;
  std::vector<char> used(fertility.num_vertices(), 0);
  for (const auto& t : fertility.triangles) used[t[0]] = used[t[1]] = used[t[2]] = 1;
  for (double v : picks) {
    ASSERT_LT(v, double(fertility.num_vertices()));
    EXPECT_TRUE(used[std::size_t(v)]);
  }
}

TEST(BenchApp, SecondRunReadsTheExactCache) {
  ScratchDir dir("bench");
  const fs::path cache = dir / "cache";
  const std::string args = quote(sample_fertility()) + " --sources 2 --repetitions 1 --no-table --json - --cache " +
                           quote(cache.string());
  const auto first = run_bench(args + " --methods gsp,dijkstra,exact", dir);
  ASSERT_EQ(first.exit_code, 0) << first.err;
  // One file per (mesh content, source): <16 hex digits>_<vertex>.bin.
  std::vector<std::string> files;
  for (const auto& e : fs::directory_iterator(cache)) files.push_back(e.path().filename().string());
  ASSERT_EQ(files.size(), 2u);
  for (const std::string& f : files) EXPECT_EQ(f.find('_'), 16u) << f;

  const auto second = run_bench(args + " --methods gsp,dijkstra,exact", dir);
  ASSERT_EQ(second.exit_code, 0) << second.err;
  // Without exact among the methods, the cache still supplies the references.
  const auto third = run_bench(args + " --methods gsp,dijkstra", dir);
  ASSERT_EQ(third.exit_code, 0) << third.err;

  const JsonValue m1 = parse_json(first.out)["meshes"].items[0];
  const JsonValue m2 = parse_json(second.out)["meshes"].items[0];
  const JsonValue m3 = parse_json(third.out)["meshes"].items[0];
  EXPECT_EQ(m1["exact_cached"].num, 0);
  EXPECT_EQ(m2["exact_cached"].num, 2);
  EXPECT_EQ(m3["exact_cached"].num, 2);
  EXPECT_EQ(m3["exact_references"].num, 2);
  // First run: exact computed and timed once per source; second: read, not timed.
  for (const JsonValue& s : bench_method(m1, "exact")["per_source"].items) EXPECT_EQ(s["seconds"].items.size(), 1u);
  for (const JsonValue& s : bench_method(m2, "exact")["per_source"].items) {
    EXPECT_TRUE(s.has("from_cache"));
    EXPECT_TRUE(s["seconds"].items.empty());
  }
  EXPECT_EQ(bench_method(m2, "exact")["query_s"].type, JsonValue::null);
  for (const char* method : {"gsp", "dijkstra"}) {
    const double mre = bench_method(m1, method)["mre"].num;
    EXPECT_GT(mre, 0.0);
    EXPECT_DOUBLE_EQ(bench_method(m2, method)["mre"].num, mre) << method;
    EXPECT_DOUBLE_EQ(bench_method(m3, method)["mre"].num, mre) << method;
    EXPECT_DOUBLE_EQ(bench_method(m2, method)["max_re"].num, bench_method(m1, method)["max_re"].num) << method;
  }
}

TEST(BenchApp, ShardsCoverTheWorkExactlyOnce) {
  ScratchDir dir("bench");
  gsp::test::write_file(dir / "tetrahedron.off", kTetrahedron);
  const std::string args = quote(sample_fertility()) + " " + quote((dir / "tetrahedron.off").string()) +
                           " --sources 3 --repetitions 1 --methods gsp,dijkstra --no-table --json -";
  const auto all = run_bench(args, dir);
  const auto s0 = run_bench(args + " --shard 0/2", dir);
  const auto s1 = run_bench(args + " --shard 1/2", dir);
  const auto last = run_bench(args + " --shard 5/6", dir);
  for (const auto* r : {&all, &s0, &s1, &last}) ASSERT_EQ(r->exit_code, 0) << r->err;

  using Item = std::pair<std::string, double>;
  const auto items = [](const JsonValue& report) {
    std::map<double, Item> out;   // index -> (mesh, source)
    for (const JsonValue& w : report["work_items"].items) out[w["index"].num] = {w["mesh"].str, w["source"].num};
    return out;
  };
  const JsonValue jall = parse_json(all.out), j0 = parse_json(s0.out), j1 = parse_json(s1.out);
  const auto i_all = items(jall), i0 = items(j0), i1 = items(j1);
  EXPECT_EQ(jall["total_work_items"].num, 6);   // 3 sources on each mesh
  EXPECT_EQ(j0["total_work_items"].num, 6);
  ASSERT_EQ(i_all.size(), 6u);
  EXPECT_EQ(i0.size(), 3u);
  EXPECT_EQ(i1.size(), 3u);
  std::map<double, Item> merged = i0;
  for (const auto& [index, item] : i1) EXPECT_TRUE(merged.emplace(index, item).second) << "item " << index << " twice";
  EXPECT_EQ(merged, i_all);
  for (const auto& [index, item] : i0) EXPECT_EQ(int(index) % 2, 0);

  // Each shard benchmarks exactly its own sources, on every method.
  for (const JsonValue* report : {&j0, &j1}) {
    for (const JsonValue& mesh : (*report)["meshes"].items) {
      std::vector<double> expected;
      for (const JsonValue& w : (*report)["work_items"].items)
        if (w["mesh"].str == mesh["name"].str) expected.push_back(w["source"].num);
      for (const JsonValue& m : mesh["methods"].items) EXPECT_EQ(sources_of(m), expected);
    }
  }
  // A shard with no work on a mesh leaves the mesh out.
  const JsonValue jlast = parse_json(last.out);
  ASSERT_EQ(jlast["meshes"].items.size(), 1u);
  EXPECT_EQ(jlast["meshes"].items[0]["name"].str, "tetrahedron.off");
}

TEST(BenchApp, CgalRefusalSkipsExactAndHeatOnly) {
  ScratchDir dir("bench");
  gsp::test::write_file(dir / "fin.off", kNonManifold);
  const auto r = run_bench(quote((dir / "fin.off").string()) +
                               " --sources 2 --repetitions 1 --methods gsp,dijkstra,heat,exact --csv -",
                           dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto rows = parse_csv(r.out);
  ASSERT_EQ(rows.size(), 5u);
  for (std::size_t i = 1; i < rows.size(); ++i) {
    const bool cgal = rows[i][3] == "heat" || rows[i][3] == "exact";
    if (cgal) {
      EXPECT_EQ(rows[i][4].rfind("skipped: ", 0), 0u) << rows[i][4];
      EXPECT_NE(rows[i][4].find("non-manifold"), std::string::npos) << rows[i][4];
      EXPECT_EQ(rows[i][8], "");
    } else {
      EXPECT_EQ(rows[i][4], "ok");
      EXPECT_GT(std::stod(rows[i][8]), 0.0);
      EXPECT_EQ(rows[i][12], "");   // no exact reference: no error
    }
  }
  EXPECT_NE(r.err.find("exact skipped"), std::string::npos) << r.err;
}

TEST(BenchApp, SubdivideBuildsLargerCurvedMeshes) {
  // Loop subdivision of a closed mesh: a vertex per edge added (V + E = V + 3F/2), 4x the
  // faces.
  ScratchDir dir("bench");
  gsp::test::write_file(dir / "tet.off", kTetrahedron);
  const auto r = run_bench(quote((dir / "tet.off").string()) + " --subdivide 2 --sources 1 --repetitions 1 " +
                               "--methods gsp,dijkstra --csv " + quote((dir / "b.csv").string()),
                           dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // 4 -> 4 + 6 = 10 vertices, 16 faces -> 10 + 24 = 34 vertices, 64 faces.
  EXPECT_NE(r.out.find("tet.off@loop2: 34 vertices, 64 faces"), std::string::npos) << r.out;
  const auto rows = parse_csv(gsp::test::slurp(dir / "b.csv"));
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[1][0], "tet.off@loop2");
  // A vertex no face uses (scans keep some) is dropped, not a crash: 4 + 6 = 10 vertices.
  gsp::test::write_file(dir / "tet_extra.off",
                        "OFF\n5 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n5 5 5\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n");
  const auto extra = run_bench(quote((dir / "tet_extra.off").string()) + " --subdivide 1 --sources 1 " +
                                   "--repetitions 1 --methods gsp",
                               dir);
  ASSERT_EQ(extra.exit_code, 0) << extra.err;
  EXPECT_NE(extra.out.find("tet_extra.off@loop1: 10 vertices, 16 faces"), std::string::npos) << extra.out;
  // A non-manifold mesh cannot be subdivided: a clear error, exit 1.
  gsp::test::write_file(dir / "nm.off", kNonManifold);
  const auto bad = run_bench(quote((dir / "nm.off").string()) + " --subdivide 1", dir);
  EXPECT_EQ(bad.exit_code, 1) << bad.err;
  EXPECT_NE(bad.err.find("not manifold"), std::string::npos) << bad.err;
}

TEST(BenchApp, MidpointSubdivisionKeepsTheSurface) {
  // Midpoint splits: a vertex per edge, 4x the faces, nothing moved (a tetrahedron stays a
  // tetrahedron: every new vertex on an old face), and a non-manifold soup is fine.
  ScratchDir dir("bench");
  gsp::test::write_file(dir / "tet.off", kTetrahedron);
  const auto r = run_bench(quote((dir / "tet.off").string()) + " --subdivide 2 --subdivision midpoint --sources 1 " +
                               "--repetitions 1 --methods gsp,dijkstra",
                           dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("tet.off@mid2: 34 vertices, 64 faces"), std::string::npos) << r.out;
  gsp::test::write_file(dir / "nm.off", kNonManifold);
  const auto nm = run_bench(quote((dir / "nm.off").string()) + " --subdivide 1 --subdivision midpoint --sources 1 " +
                                "--repetitions 1 --methods gsp",
                            dir);
  EXPECT_EQ(nm.exit_code, 0) << nm.err;
  EXPECT_NE(nm.out.find("nm.off@mid1"), std::string::npos) << nm.out;
  const auto bad = run_bench(quote((dir / "tet.off").string()) + " --subdivision cubic", dir);
  EXPECT_EQ(bad.exit_code, 2) << bad.err;
}

TEST(BenchApp, BadInputExitsOne) {
  ScratchDir dir("bench");
  gsp::test::write_file(dir / "broken.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n");
  const fs::path json = dir / "out.json";
  for (const std::string& input : {(dir / "missing.off").string(), (dir / "broken.off").string()}) {
    const auto r = run_bench(quote(sample_fertility()) + " " + quote(input) + " --json " + quote(json.string()), dir);
    EXPECT_EQ(r.exit_code, 1) << input;
    const auto err = gsp::test::lines(r.err);
    ASSERT_EQ(err.size(), 1u) << r.err;
    EXPECT_EQ(err[0].rfind("gsp-bench: error: ", 0), 0u) << err[0];
    EXPECT_NE(err[0].find(fs::path(input).filename().string()), std::string::npos) << err[0];
    EXPECT_FALSE(fs::exists(json));   // nothing partial left behind
  }
}

TEST(BenchApp, UsageErrorsExitTwo) {
  ScratchDir dir("bench");
  const std::string mesh = quote(sample_fertility());
  for (const std::string& args : {std::string(""), mesh + " --methods gsp,fast", mesh + " --methods ,",
                                  mesh + " --shard 2/2", mesh + " --shard 1", mesh + " --shard a/b",
                                  mesh + " --sources 0", mesh + " --json - --csv -", mesh + " --frobnicate",
                                  mesh + " --subdivide 7"}) {
    const auto r = run_bench(args, dir);
    EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.err;
    EXPECT_TRUE(r.out.empty()) << args;
  }
}

}  // namespace
