// Integration tests of gsp-bench's corpus mode and physical bounds, run as a user runs them:
// the built binary on a temporary folder (the bundled fertility sample, a broken file, a
// point cloud, a SOURCES.md) and on a flat grid, where the geodesic is the straight line.
#include "bench_support.hpp"

#include <cmath>
#include <string>

namespace {

using gsp::test::bench_method;
using gsp::test::JsonValue;
using gsp::test::parse_csv;
using gsp::test::parse_json;
using gsp::test::quote;
using gsp::test::run_bench;
using gsp::test::sample_fertility;
using gsp::test::ScratchDir;
using gsp::test::slurp;
using gsp::test::write_file;
namespace fs = std::filesystem;

// n x n vertices on the unit square in the plane z = 0, two triangles per cell.
std::string flat_grid_off(int n) {
  std::string off = "OFF\n" + std::to_string(n * n) + " " + std::to_string(2 * (n - 1) * (n - 1)) + " 0\n";
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) off += std::to_string(double(i) / (n - 1)) + " " + std::to_string(double(j) / (n - 1)) + " 0\n";
  for (int j = 0; j + 1 < n; ++j)
    for (int i = 0; i + 1 < n; ++i) {
      const int v = j * n + i;
      off += "3 " + std::to_string(v) + " " + std::to_string(v + 1) + " " + std::to_string(v + n + 1) + "\n";
      off += "3 " + std::to_string(v) + " " + std::to_string(v + n + 1) + " " + std::to_string(v + n) + "\n";
    }
  return off;
}

const JsonValue& row_of(const JsonValue& doc, const std::string& name) {
  for (const JsonValue& r : doc["meshes"].items)
    if (r["name"].str == name) return r;
  throw std::runtime_error("no row " + name);
}

const JsonValue& aggregate_of(const JsonValue& doc, const std::string& category) {
  for (const JsonValue& a : doc["aggregate"].items)
    if (a["category"].str == category) return a;
  throw std::runtime_error("no aggregate " + category);
}

TEST(BenchCorpus, BrokenFileIsAFailedRowAndTheRunGoesOn) {
  ScratchDir dir("corpus");
  const fs::path corpus = dir / "meshes";
  fs::create_directories(corpus);
  fs::copy_file(sample_fertility(), corpus / "good.off");
  write_file(corpus / "broken.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n");   // index 7 of 3 vertices
  write_file(corpus / "cloud.ply",
             "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
             "end_header\n0 0 0\n1 0 0\n0 1 0\n");
  write_file(corpus / "notes.txt", "not a mesh\n");
  write_file(corpus / "SOURCES.md", "| File | Character |\n|---|---|\n| `good.off` | benign (scan) |\n");

  const auto r = run_bench("--corpus " + quote(corpus.string()) + " --sources 2 --json " +
                               quote((dir / "c.json").string()) + " --csv " + quote((dir / "c.csv").string()),
                           dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("FAILED"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("per category"), std::string::npos) << r.out;

  const JsonValue doc = parse_json(slurp(dir / "c.json"));
  EXPECT_EQ(doc["mode"].str, "corpus");
  ASSERT_EQ(doc["meshes"].items.size(), 2u);   // the point cloud and the .txt are no rows
  EXPECT_EQ(doc["meshes"].items[0]["name"].str, "broken.off");   // sorted by name
  ASSERT_EQ(doc["point_clouds_skipped"].items.size(), 1u);

  const JsonValue& broken = row_of(doc, "broken.off");
  EXPECT_EQ(broken["status"].str, "failed");
  EXPECT_EQ(broken["category"].str, "unknown");
  EXPECT_FALSE(broken["reason"].str.empty());

  const JsonValue& good = row_of(doc, "good.off");
  EXPECT_EQ(good["status"].str, "ok");
  EXPECT_EQ(good["category"].str, "benign");
  EXPECT_EQ(good["vertices"].num, 4494);
  EXPECT_EQ(good["sources"].num, 2);
  EXPECT_EQ(good["exact_references"].num, 2);
  ASSERT_EQ(good["methods"].items.size(), 4u);   // the corpus default: gsp, dijkstra, heat, exact
  const JsonValue& gsp = bench_method(good, "gsp");
  EXPECT_GT(gsp["mre"].num, 0.0);
  EXPECT_LT(gsp["mre"].num, 0.01);   // fertility: about 0.2%
  EXPECT_LT(gsp["mre"].num, bench_method(good, "dijkstra")["mre"].num);
  // The signed mean: within the MRE; Dijkstra's edge paths are never short, so its sign is +.
  EXPECT_LE(std::abs(gsp["signed_re"].num), gsp["mre"].num);
  EXPECT_GT(bench_method(good, "dijkstra")["signed_re"].num, 0.0);
  EXPECT_DOUBLE_EQ(bench_method(good, "dijkstra")["signed_re"].num, bench_method(good, "dijkstra")["mre"].num);
  EXPECT_EQ(good["gsp_beats_dijkstra"].type, JsonValue::boolean);
  EXPECT_TRUE(good["gsp_beats_dijkstra"].b);
  EXPECT_GT(good["gsp_steps_per_face"].num, 1.0);
  EXPECT_EQ(gsp["bounds"]["nan"].num, 0);

  const JsonValue& all = aggregate_of(doc, "all");
  EXPECT_EQ(all["meshes_run"].num, 1);
  EXPECT_EQ(all["failed"].num, 1);
  EXPECT_EQ(all["with_exact"].num, 1);
  EXPECT_EQ(all["gsp_worse_than_dijkstra"].num, 0);
  EXPECT_EQ(all["gsp_worse_than_heat"].num, 0);
  // Per source: each source of the good mesh compared with Dijkstra, GSP better on each.
  EXPECT_EQ(all["sources_compared_with_dijkstra"].num, good["sources"].num);
  EXPECT_EQ(all["sources_gsp_worse_than_dijkstra"].num, 0);
  EXPECT_EQ(all["figures"]["gsp_mre"]["n"].num, 1);
  EXPECT_DOUBLE_EQ(all["figures"]["gsp_mre"]["median"].num, gsp["mre"].num);
  EXPECT_DOUBLE_EQ(all["figures"]["gsp_mre"]["worst"].num, gsp["mre"].num);
  const JsonValue& benign = aggregate_of(doc, "benign");
  EXPECT_EQ(benign["meshes_run"].num, 1);
  EXPECT_EQ(benign["failed"].num, 0);
  EXPECT_EQ(aggregate_of(doc, "malign")["meshes_run"].num, 0);
  EXPECT_EQ(aggregate_of(doc, "malign")["figures"]["gsp_mre"]["n"].num, 0);

  const auto rows = parse_csv(slurp(dir / "c.csv"));
  ASSERT_EQ(rows.size(), 3u);   // header + 2 meshes
  EXPECT_EQ(rows[0][0], "mesh");
  EXPECT_EQ(rows[0][1], "category");
  EXPECT_EQ(rows[1][2], "failed");
  EXPECT_EQ(rows[2][1], "benign");
  EXPECT_EQ(rows[2][2], "ok");
  EXPECT_EQ(rows[1].size(), rows[0].size());
  EXPECT_EQ(rows[2].size(), rows[0].size());
}

TEST(BenchCorpus, UserFlagsOverrideTheCorpusDefaults) {
  ScratchDir dir("corpus");
  write_file(dir / "grid.off", flat_grid_off(6));
  const auto r = run_bench("--corpus " + quote((dir / "grid.off").string()) +
                               " --methods gsp,dijkstra --sources 4 --repetitions 2 --no-table --json -",
                           dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const JsonValue doc = parse_json(r.out);
  EXPECT_EQ(doc["settings"]["sources"].num, 4);
  EXPECT_EQ(doc["settings"]["repetitions"].num, 2);
  const JsonValue& row = row_of(doc, "grid.off");
  EXPECT_EQ(row["category"].str, "unknown");   // no SOURCES.md beside it
  EXPECT_EQ(row["methods"].items.size(), 2u);
  EXPECT_EQ(row["exact_references"].num, 0);
  EXPECT_EQ(bench_method(row, "gsp")["mre"].type, JsonValue::null);   // no exact: no error
  EXPECT_EQ(run_bench("--corpus " + quote((dir / "grid.off").string()) + " --shard 0/2", dir).exit_code, 2);
  EXPECT_EQ(run_bench(quote((dir / "grid.off").string()) + " --categories x.md", dir).exit_code, 2);
}

// A single triangle: every vertex is an edge away from the source, so Dijkstra is exact and
// GSP's single-precision rounding (MRE ~1e-8) is a tie, not a loss.
TEST(BenchCorpus, RoundingAgainstAnExactBaselineIsATie) {
  ScratchDir dir("corpus");
  write_file(dir / "triangle.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  const auto r = run_bench("--corpus " + quote((dir / "triangle.off").string()) + " --no-table --json -", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const JsonValue doc = parse_json(r.out);
  const JsonValue& row = row_of(doc, "triangle.off");
  EXPECT_EQ(bench_method(row, "dijkstra")["mre"].num, 0.0);
  EXPECT_LT(bench_method(row, "gsp")["mre"].num, 1e-6);
  EXPECT_EQ(aggregate_of(doc, "all")["gsp_worse_than_dijkstra"].num, 0);
}

// On a plane the geodesic is the straight line: GSP and Dijkstra never fall below it, and
// Dijkstra is the edge path itself.
TEST(BenchBoundsApp, FlatGridRespectsBothBounds) {
  ScratchDir dir("bounds");
  write_file(dir / "grid.off", flat_grid_off(21));
  const auto r = run_bench(quote((dir / "grid.off").string()) +
                               " --methods gsp,dijkstra --sources 3 --repetitions 1 --no-table --json -",
                           dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const JsonValue doc = parse_json(r.out);
  const JsonValue& mesh = doc["meshes"].items[0];
  const JsonValue& gsp = bench_method(mesh, "gsp")["bounds"];
  const JsonValue& dijkstra = bench_method(mesh, "dijkstra")["bounds"];
  EXPECT_LT(gsp["below_line"].num, 1e-4);
  EXPECT_LT(gsp["above_edge"].num, 1e-5);
  EXPECT_EQ(gsp["below_line_count"].num + gsp["above_edge_count"].num + gsp["nan"].num, 0);
  EXPECT_FALSE(gsp["violated"].b);
  EXPECT_LT(dijkstra["below_line"].num, 1e-12);
  EXPECT_EQ(dijkstra["above_edge"].num, 0.0);
  EXPECT_EQ(dijkstra["above_edge_count"].num, 0);
  // Per source as well: Dijkstra is its own edge path, and reaches every vertex.
  for (const JsonValue& s : bench_method(mesh, "dijkstra")["per_source"].items) {
    EXPECT_EQ(s["bounds"]["above_edge"].num, 0.0);
    EXPECT_EQ(s["bounds"]["edge_unreached"].num, 0);
  }
}

}  // namespace
