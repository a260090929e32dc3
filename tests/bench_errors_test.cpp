// The errors gsp-bench reports, recomputed here without it: exact distances from
// gsp::reference, GSP and Dijkstra from the core, the relative error written out. The app's
// per-source MRE and max RE must match, and its summary figures must be the stated
// aggregates of its own per-source numbers.
#include "bench_support.hpp"

#include <gsp/dijkstra.hpp>
#include <gsp/geodesics.hpp>
#include <gsp/io/mesh_io.hpp>
#include <gsp/reference/exact_geodesics.hpp>

#include <algorithm>
#include <cmath>

namespace {

using gsp::test::bench_method;
using gsp::test::JsonValue;
using gsp::test::quote;
using gsp::test::ScratchDir;

struct Errors {
  double mre = 0, max_re = 0;
};

// Mean and max of |d - e| / e over vertices with 0 < e < inf; unreached (d = inf) counts as 1.
Errors errors(const std::vector<double>& d, const std::vector<double>& e) {
  Errors out;
  double sum = 0;
  std::size_t n = 0;
  for (std::size_t v = 0; v < e.size(); ++v) {
    if (!(e[v] > 0) || !std::isfinite(e[v])) continue;
    const double re = std::isfinite(d[v]) ? std::abs(d[v] - e[v]) / e[v] : 1.0;
    sum += re, ++n;
    out.max_re = std::max(out.max_re, re);
  }
  out.mre = n ? sum / double(n) : 0;
  return out;
}

class BenchErrors : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    ScratchDir dir("bench-errors");
    const auto r = gsp::test::run_bench(quote(gsp::test::sample_fertility()) +
                                            " --sources 2 --repetitions 1 --seed 3 --no-table --json - "
                                            "--methods gsp,gsp-random-layout,dijkstra,exact",
                                        dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    report_ = new JsonValue(gsp::test::parse_json(r.out));
  }
  static void TearDownTestSuite() {
    delete report_;
    report_ = nullptr;
  }
  static const JsonValue& mesh() { return (*report_)["meshes"].items.at(0); }
  static JsonValue* report_;
};
JsonValue* BenchErrors::report_ = nullptr;

TEST_F(BenchErrors, PerSourceErrorsMatchAnIndependentComputation) {
  ASSERT_NE(report_, nullptr);
  const gsp::TriangleMesh fertility = gsp::io::read_mesh(gsp::test::sample_fertility()).mesh;
  gsp::reference::ExactGeodesicSolver exact(fertility);
  const gsp::GeodesicSolver gsp_solver(fertility);
  const gsp::DijkstraSolver dijkstra(fertility);
  const auto& gsp_sources = bench_method(mesh(), "gsp")["per_source"].items;
  const auto& dijkstra_sources = bench_method(mesh(), "dijkstra")["per_source"].items;
  const auto& random_sources = bench_method(mesh(), "gsp-random-layout")["per_source"].items;
  ASSERT_EQ(gsp_sources.size(), 2u);
  for (std::size_t k = 0; k < gsp_sources.size(); ++k) {
    const auto source = gsp::Index(gsp_sources[k]["source"].num);
    const std::vector<double> e = exact.distances_from_vertex(source);
    const Errors g = errors(gsp_solver.compute({gsp::Source::at_vertex(source)}).vertex_distance, e);
    const Errors d = errors(dijkstra.compute({gsp::Source::at_vertex(source)}).vertex_distance, e);
    // Same deterministic computations, so agreement to rounding of the JSON numbers (17 digits).
    EXPECT_NEAR(gsp_sources[k]["mre"].num, g.mre, 1e-12 * g.mre) << "source " << source;
    EXPECT_NEAR(gsp_sources[k]["max_re"].num, g.max_re, 1e-12 * g.max_re) << "source " << source;
    EXPECT_NEAR(dijkstra_sources[k]["mre"].num, d.mre, 1e-12 * d.mre) << "source " << source;
    EXPECT_NEAR(dijkstra_sources[k]["max_re"].num, d.max_re, 1e-12 * d.max_re) << "source " << source;
    // A random memory layout changes the order of float operations, not the method: the
    // errors stay within a small fraction of GSP's own.
    EXPECT_NEAR(random_sources[k]["mre"].num, g.mre, 0.05 * g.mre) << "source " << source;
    // The paper's accuracy on a benign mesh (well under 1% MRE), and Dijkstra's zig-zag bias.
    EXPECT_LT(g.mre, 0.01);
    EXPECT_GT(d.mre, 3 * g.mre);
  }
}

TEST_F(BenchErrors, SummariesAreTheStatedAggregates) {
  ASSERT_NE(report_, nullptr);
  const double vertices = mesh()["vertices"].num;
  const double dijkstra_query = bench_method(mesh(), "dijkstra")["query_s"].num;
  for (const char* name : {"gsp", "gsp-random-layout", "dijkstra"}) {
    const JsonValue& m = bench_method(mesh(), name);
    double sum = 0, max_re = 0;
    std::vector<double> medians;
    for (const JsonValue& s : m["per_source"].items) {
      sum += s["mre"].num;
      max_re = std::max(max_re, s["max_re"].num);
      medians.push_back(s["median_s"].num);
    }
    EXPECT_NEAR(m["mre"].num, sum / 2, 1e-12 * sum) << name;
    EXPECT_DOUBLE_EQ(m["max_re"].num, max_re) << name;
    // query_s: the median of the two per-source medians (their mean).
    EXPECT_NEAR(m["query_s"].num, 0.5 * (medians[0] + medians[1]), 1e-12) << name;
    // Throughput: the median (here: mean) over sources of reached vertices / median time; on
    // a closed connected mesh every vertex is reached.
    double throughput = 0;
    for (const JsonValue& src : m["per_source"].items) {
      EXPECT_EQ(src["reached"].num, vertices) << name;
      throughput += 0.5 * src["reached"].num / src["median_s"].num;
    }
    EXPECT_NEAR(m["vertices_per_s"].num, throughput, 1e-9 * throughput) << name;
    EXPECT_NEAR(m["vs_dijkstra"].num, m["query_s"].num / dijkstra_query, 1e-9 * m["vs_dijkstra"].num) << name;
  }
  EXPECT_NEAR(bench_method(mesh(), "dijkstra")["vs_dijkstra"].num, 1.0, 1e-12);
  EXPECT_EQ(bench_method(mesh(), "exact")["mre"].type, JsonValue::null);   // the reference itself
}

}  // namespace
