// gsp-cvt-compare: gsp-cvt's remesh and CGAL's isotropic remeshing of the same mesh at the
// same vertex count, side by side (minimum angle, angles below 30 degrees, aspect ratio,
// Hausdorff distance, topology, time). GPL because of CGAL; gsp::cvt itself does not use it.
#include <gsp/adapters/cgal.hpp>
#include <gsp/cli/app.hpp>
#include <gsp/cli/load.hpp>
#include <gsp/connectivity.hpp>
#include <gsp/cvt/cvt.hpp>
#include <gsp/cvt/quality.hpp>
#include <gsp/cvt/remesh.hpp>
#include <gsp/io/mesh_io.hpp>
#include <gsp/topology.hpp>

#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CLI/CLI.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>

namespace {

using namespace gsp;
using Clock = std::chrono::steady_clock;

struct Options {
  std::string input, save_prefix;
  std::size_t vertices = 0;
  int cvt_iterations = 50, cgal_iterations = 5, count_runs = 3;
  std::size_t hausdorff_samples = 200000;
  cli::LoadOptions load;
};

struct Row {
  std::string method;
  TriangleMesh mesh;
  double seconds = 0;
  std::string note;
};

double surface_area(const TriangleMesh& m) {
  double a = 0;
  for (const Triangle& t : m.triangles)
    a += 0.5 * norm(cross(m.positions[t[1]] - m.positions[t[0]], m.positions[t[2]] - m.positions[t[0]]));
  return a;
}

// CGAL's isotropic remeshing with a target edge length; the vertex count it reaches depends
// on the surface, so the length is corrected by sqrt(count / wanted) between runs and the
// last run is the one timed and reported.
Row cgal_remesh(const TriangleMesh& mesh, std::size_t wanted, const Options& o) {
  namespace PMP = CGAL::Polygon_mesh_processing;
  double length = std::sqrt(2.0 * surface_area(mesh) / (std::sqrt(3.0) * double(wanted)));
  Row row;
  row.method = "CGAL isotropic_remeshing";
  for (int run = 0; run < o.count_runs; ++run) {
    adapters::ToCgalResult c = adapters::to_cgal(mesh);
    const auto t0 = Clock::now();
    PMP::isotropic_remeshing(faces(c.mesh), length, c.mesh, CGAL::parameters::number_of_iterations(o.cgal_iterations));
    c.mesh.collect_garbage();
    row.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
    row.mesh = adapters::from_cgal(c.mesh);
    row.note = "target edge " + std::to_string(length) + ", " + std::to_string(o.cgal_iterations) + " iterations";
    length *= std::sqrt(double(row.mesh.num_vertices()) / double(wanted));
  }
  return row;
}

Row gsp_remesh(const TriangleMesh& mesh, std::size_t wanted, const Options& o) {
  Row row;
  row.method = "gsp-cvt (Lloyd + restricted Delaunay)";
  cvt::CvtOptions co;
  co.sites = wanted;
  co.max_iterations = o.cvt_iterations;
  const auto t0 = Clock::now();
  const cvt::CvtResult r = cvt::compute_cvt(mesh, co);
  row.mesh = cvt::restricted_delaunay(r).mesh;
  row.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  row.note = std::to_string(r.stats.iterations) + " iterations";
  return row;
}

void run(cli::Context& ctx, const Options& o) {
  const cli::LoadedMesh in = cli::load_input(ctx, o.input, o.load);
  const TopologyReport ti = analyze_topology(in.mesh, build_connectivity(in.mesh));
  std::vector<Row> rows;
  {
    auto progress = ctx.progress("gsp-cvt");
    rows.push_back(gsp_remesh(in.mesh, o.vertices, o));
  }
  {
    auto progress = ctx.progress("CGAL");
    rows.push_back(cgal_remesh(in.mesh, o.vertices, o));
  }
  std::printf("| method | vertices | min angle | angles < 30 | mean AR | Hausdorff (%% diag) | Euler / loops (input %lld / %zu) | manifold | time (s) |\n",
              static_cast<long long>(ti.euler_characteristic), ti.boundary_loops);
  std::printf("|---|---:|---:|---:|---:|---:|---:|:-:|---:|\n");
  cli::Json& list = ctx.stats()["rows"] = cli::Json::array();
  for (const Row& r : rows) {
    const cvt::MeshQuality q = cvt::measure_mesh_quality(r.mesh);
    cvt::HausdorffOptions ho;
    ho.samples = o.hausdorff_samples;
    const cvt::HausdorffDistance h = cvt::hausdorff_distance(in.mesh, r.mesh, ho);
    const TopologyReport t = analyze_topology(r.mesh, build_connectivity(r.mesh));
    std::printf("| %s | %zu | %.1f | %.2f%% | %.3f | %.3f | %lld / %zu | %s | %.2f |\n", r.method.c_str(),
                r.mesh.num_vertices(), q.min_angle, 100 * q.below_30, q.mean_aspect_ratio, 100 * h.relative,
                static_cast<long long>(t.euler_characteristic), t.boundary_loops, t.is_manifold() ? "yes" : "no",
                r.seconds);
    cli::Json j = cli::Json::object();
    j["method"] = r.method;
    j["note"] = r.note;
    j["vertices"] = r.mesh.num_vertices();
    j["min_angle"] = q.min_angle;
    j["mean_min_angle"] = q.mean_min_angle;
    j["percent_below_30"] = 100 * q.below_30;
    j["mean_aspect_ratio"] = q.mean_aspect_ratio;
    j["hausdorff_percent_of_diagonal"] = 100 * h.relative;
    j["euler_characteristic"] = static_cast<long long>(t.euler_characteristic);
    j["boundary_loops"] = t.boundary_loops;
    j["manifold"] = t.is_manifold();
    j["seconds"] = r.seconds;
    list.push_back(std::move(j));
  }
  if (!o.save_prefix.empty()) {
    io::write_mesh(o.save_prefix + "-gsp.ply", rows[0].mesh);
    io::write_mesh(o.save_prefix + "-cgal.ply", rows[1].mesh);
  }
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  return gsp::cli::run_app(
      argc, argv, "gsp-cvt-compare",
      "gsp-cvt against CGAL's isotropic remeshing at the same vertex count; prints a Markdown table (GPL: CGAL).",
      [&](CLI::App& app) {
        app.add_option("INPUT", o.input, "input mesh")->required();
        app.add_option("--vertices", o.vertices, "vertex count for both methods")->required()->check(CLI::PositiveNumber);
        app.add_option("--cvt-iterations", o.cvt_iterations, "gsp-cvt Lloyd iteration cap (default 50)");
        app.add_option("--cgal-iterations", o.cgal_iterations, "CGAL remeshing iterations (default 5)");
        app.add_option("--count-runs", o.count_runs, "CGAL runs to match the vertex count (default 3; the last is timed)")
            ->check(CLI::PositiveNumber);
        app.add_option("--hausdorff-samples", o.hausdorff_samples, "points per surface (default 200000)");
        app.add_option("--save", o.save_prefix, "write PREFIX-gsp.ply and PREFIX-cgal.ply");
        gsp::cli::add_load_options(app, o.load);
      },
      [&](gsp::cli::Context& ctx) { run(ctx, o); });
}
