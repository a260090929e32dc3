// gsp-cvt-compare: gsp-cvt's remesh and CGAL's isotropic remeshing of the same mesh at the
// same vertex count, side by side (minimum angle, angles below 30 degrees, aspect ratio,
// Hausdorff distance, topology per component, time). GPL because of CGAL; gsp::cvt itself
// does not use it. A method that throws is a row with its reason, so a corpus run
// (scripts/cvt_corpus.py) loses no mesh to one method's failure.
#include "measure.hpp"
#include "memory_cap.hpp"

#include <gsp/adapters/cgal.hpp>
#include <gsp/cli/app.hpp>
#include <gsp/cli/load.hpp>
#include <gsp/connectivity.hpp>
#include <gsp/cvt/cvt.hpp>
#include <gsp/cvt/quality.hpp>
#include <gsp/cvt/remesh.hpp>
#include <gsp/cvt/surface.hpp>
#include <gsp/io/mesh_io.hpp>
#include <gsp/topology.hpp>

#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CLI/CLI.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <new>
#include <stdexcept>
#include <string>

namespace {

using namespace gsp;
using Clock = std::chrono::steady_clock;

struct Options {
  std::string input, save_prefix;
  std::size_t vertices = 0;
  int cvt_iterations = 50, cgal_iterations = 5, count_runs = 3;
  double feature_angle = 0;
  double cone_angle = cvt::CvtOptions{}.cone_angle;
  std::string method = "cvt";
  double sizing_angle = cvt::SurfaceRemeshOptions{}.edge_sizing_angle;
  double cvt_tolerance = cvt::CvtOptions().tolerance;
  std::size_t hausdorff_samples = 200000;
  cli::LoadOptions load;
};

struct Row {
  std::string method;
  TriangleMesh mesh;
  double seconds = 0;
  std::string note;
  std::string error;                  // non-empty: the method failed, nothing else is valid
  cli::Json phases = cli::Json::object();   // seconds per phase (gsp)
  cli::Json components = cli::Json::array();  // per input component: outcome and reason (gsp)
  // The mesh's first triangles that are the method's own remesh: gsp-cvt appends the
  // components it kept as they were (their input triangles) after the remeshed ones.
  std::size_t remeshed_faces = std::size_t(-1);
};

double surface_area(const TriangleMesh& m) {
  double a = 0;
  for (const Triangle& t : m.triangles)
    a += 0.5 * norm(cross(m.positions[t[1]] - m.positions[t[0]], m.positions[t[2]] - m.positions[t[0]]));
  return a;
}

// Two faces on the same three vertices (one folded onto the other, as in a soup's
// back-to-back duplicates) make a closed pillow whose every edge flip would join a vertex to
// itself; CGAL's isotropic_remeshing asserts there in a debug build and crashes in a release
// one, so such an input is refused before CGAL sees it.
std::size_t folded_face_pairs(const adapters::CgalSurfaceMesh& m) {
  std::size_t n = 0;
  for (auto h : m.halfedges()) {
    const auto o = m.opposite(h);
    if (h > o || m.is_border(h) || m.is_border(o)) continue;
    if (m.target(m.next(h)) == m.target(m.next(o))) ++n;
  }
  return n;
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
    if (const std::size_t folded = folded_face_pairs(c.mesh))
      throw std::runtime_error("not run: " + std::to_string(folded) +
                               " edges between two faces on the same three vertices (CGAL crashes there)");
    const auto t0 = Clock::now();
    {
      const cvt_compare::AddressSpaceCap cap;
      try {
        PMP::isotropic_remeshing(faces(c.mesh), length, c.mesh, CGAL::parameters::number_of_iterations(o.cgal_iterations));
        c.mesh.collect_garbage();
      } catch (const std::bad_alloc&) {
        char what[160];
        std::snprintf(what, sizeof what, "ran out of memory (capped at %.3g GB, 90%% of what was free when it started)",
                      double(cap.headroom()) / 1e9);
        throw std::runtime_error(what);
      }
    }
    row.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
    row.mesh = adapters::from_cgal(c.mesh);
    row.note = "target edge " + std::to_string(length) + ", " + std::to_string(o.cgal_iterations) + " iterations";
    if (!c.skipped_faces.empty()) row.note += ", " + std::to_string(c.skipped_faces.size()) + " input faces refused";
    length *= std::sqrt(double(row.mesh.num_vertices()) / double(wanted));
  }
  return row;
}

Row gsp_remesh(const TriangleMesh& mesh, std::size_t wanted, const Options& o) {
  Row row;
  row.method = "gsp-cvt (Lloyd + restricted Delaunay)";
  cvt::SurfaceRemeshOptions so;
  so.cvt.sites = wanted;
  so.cvt.max_iterations = o.cvt_iterations;
  so.cvt.tolerance = o.cvt_tolerance;
  so.cvt.feature_angle = o.feature_angle;
  so.cvt.cone_angle = o.cone_angle;
  so.method = cvt::remesh_method(o.method);
  so.edge_sizing_angle = o.sizing_angle;
  const auto t0 = Clock::now();
  const cvt::SurfaceRemeshResult r = cvt::remesh_surface(mesh, so);
  row.mesh = r.mesh;
  row.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  row.note = std::to_string(r.cvt_stats.iterations) + " iterations, " + std::to_string(r.remeshed()) + " of " +
             std::to_string(r.components.size()) + " components remeshed";
  const cvt::CvtTimings& t = r.cvt_stats.timings;
  row.phases["subdivide"] = t.subdivide;
  row.phases["prepare"] = t.prepare;
  row.phases["initial"] = t.initial;
  row.phases["propagate"] = t.propagate;
  row.phases["centroids"] = t.centroids;
  row.phases["fix"] = t.fix;
  row.phases["remesh"] = r.remesh_seconds;
  row.remeshed_faces = 0;
  for (const cvt::ComponentReport& c : r.components)
    if (c.outcome == cvt::ComponentOutcome::remeshed) row.remeshed_faces += c.output_faces;
  for (const cvt::ComponentReport& c : r.components) {
    cli::Json j = cli::Json::object();
    j["input_faces"] = c.input_faces;
    j["sites"] = c.sites;
    j["outcome"] = cvt::outcome_name(c.outcome);
    j["reason"] = c.reason;
    j["features_dropped"] = c.features_dropped;
    j["retries"] = c.retries;
    j["grown"] = c.grown;
    j["by_edge_operations"] = c.by_edge_operations;
    j["edge_failure"] = c.edge_failure;
    row.components.push_back(std::move(j));
  }
  return row;
}

// The method's row, or its failure as a row.
template <class Method>
Row guarded(const char* name, Method&& method) {
  try {
    return method();
  } catch (const std::exception& e) {
    Row row;
    row.method = name;
    row.error = e.what();
    return row;
  }
}

void run(cli::Context& ctx, const Options& o) {
  const cli::LoadedMesh in = cli::load_input(ctx, o.input, o.load);
  ctx.stats()["input_topology"] = cvt_compare::describe_input(in.mesh);
  const TopologyReport ti = analyze_topology(in.mesh, build_connectivity(in.mesh));
  std::vector<Row> rows;
  {
    auto progress = ctx.progress("gsp-cvt");
    rows.push_back(guarded("gsp-cvt", [&] { return gsp_remesh(in.mesh, o.vertices, o); }));
  }
  {
    auto progress = ctx.progress("CGAL");
    rows.push_back(guarded("CGAL isotropic_remeshing", [&] { return cgal_remesh(in.mesh, o.vertices, o); }));
  }
  std::printf("| method | vertices | min angle | angles < 30 | Hausdorff (%% diag) | Euler / loops / components (input %lld / %zu / %zu) | manifold | topology per component | time (s) |\n",
              static_cast<long long>(ti.euler_characteristic), ti.boundary_loops, ti.components);
  std::printf("|---|---:|---:|---:|---:|---:|:-:|---|---:|\n");
  cli::Json& list = ctx.stats()["rows"] = cli::Json::array();
  for (const Row& r : rows) {
    cli::Json j = cli::Json::object();
    j["method"] = r.method;
    if (!r.error.empty()) {
      j["error"] = r.error;
      std::printf("| %s | failed: %s |\n", r.method.c_str(), r.error.c_str());
      list.push_back(std::move(j));
      continue;
    }
    j["note"] = r.note;
    j["seconds"] = r.seconds;
    j["phases"] = r.phases;
    j["components"] = r.components;
    const cvt_compare::Measures m = cvt_compare::measure_output(in.mesh, r.mesh, o.hausdorff_samples);
    std::printf("| %s | %zu | %.1f | %.2f%% | %.3f | %lld / %zu / %zu | %s | %s | %.2f |\n", r.method.c_str(),
                m.topology.vertices, m.min_angle, m.percent_below_30, m.hausdorff_percent,
                static_cast<long long>(m.topology.euler_characteristic), m.topology.boundary_loops,
                m.topology.components, m.topology.is_manifold() ? "yes" : "no",
                m.topology_kept ? "kept" : m.topology_difference.c_str(), r.seconds);
    j["measures"] = cvt_compare::to_json(m);
    // The quality floor of issue 22 judges the remesh, not the input triangles of components
    // kept as they were (too small a share, non-manifold, ...): their figures apart.
    TriangleMesh own;
    own.positions = r.mesh.positions;
    own.triangles.assign(r.mesh.triangles.begin(),
                         r.mesh.triangles.begin() + std::ptrdiff_t(std::min(r.remeshed_faces, r.mesh.num_faces())));
    const cvt::MeshQuality q = cvt::measure_mesh_quality(own);
    j["measures"]["remeshed_faces"] = own.num_faces();
    j["measures"]["remeshed_min_angle"] = own.num_faces() ? q.min_angle : NAN;
    j["measures"]["remeshed_percent_below_30"] = own.num_faces() ? 100 * q.below_30 : NAN;
    list.push_back(std::move(j));
  }
  if (!o.save_prefix.empty()) {
    if (rows[0].error.empty()) io::write_mesh(o.save_prefix + "-gsp.ply", rows[0].mesh);
    if (rows[1].error.empty()) io::write_mesh(o.save_prefix + "-cgal.ply", rows[1].mesh);
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
        app.add_option("--cvt-tolerance", o.cvt_tolerance, "gsp-cvt's --tolerance (default: gsp-cvt's)")
            ->check(CLI::NonNegativeNumber);
        app.add_option("--feature-angle", o.feature_angle, "gsp-cvt's --feature-angle (default 0: off)");
        app.add_option("--cone-angle", o.cone_angle, "gsp-cvt's --cone-angle (default 0: off)")->check(CLI::Range(0.0, 360.0));
        app.add_option("--method", o.method, "gsp-cvt's --method (cvt or edges; default cvt)")
            ->check(CLI::IsMember({"cvt", "edges"}));
        app.add_option("--sizing-angle", o.sizing_angle, "gsp-cvt's --sizing-angle (degrees; 0: one spacing)")
            ->check(CLI::Range(0.0, 180.0));
        app.add_option("--cgal-iterations", o.cgal_iterations, "CGAL remeshing iterations (default 5)");
        app.add_option("--count-runs", o.count_runs, "CGAL runs to match the vertex count (default 3; the last is timed)")
            ->check(CLI::PositiveNumber);
        app.add_option("--hausdorff-samples", o.hausdorff_samples, "points per surface (default 200000)");
        app.add_option("--save", o.save_prefix, "write PREFIX-gsp.ply and PREFIX-cgal.ply");
        gsp::cli::add_load_options(app, o.load);
      },
      [&](gsp::cli::Context& ctx) { run(ctx, o); });
}
