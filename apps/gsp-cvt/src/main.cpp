// gsp-cvt: geodesic centroidal Voronoi tessellation of a triangle mesh by Lloyd iterations
// with GSP, and the isotropic remesh it defines (the restricted Delaunay dual: one vertex per
// site, one triangle where three regions meet), component by component: what cannot be
// remeshed as a surface is kept as it is, with a note saying why.
#include "report.hpp"

#include <gsp/cli/app.hpp>
#include <gsp/cli/load.hpp>
#include <gsp/cli/parse.hpp>
#include <gsp/cvt/cvt.hpp>
#include <gsp/cvt/quality.hpp>
#include <gsp/cvt/remesh.hpp>
#include <gsp/cvt/surface.hpp>
#include <gsp/io/mesh_io.hpp>
#include <gsp/topology.hpp>

#include <CLI/CLI.hpp>

#include <cstdio>
#include <memory>
#include <string>

namespace {

using namespace gsp;

struct Options {
  std::string input, output, regions, edge_length, init = "poisson", method = "cvt";
  std::size_t vertices = 0, faces_per_site = cvt::CvtOptions{}.min_faces_per_site;
  int iterations = 50;
  double tolerance = 1e-4, over_relaxation = 1.6, smooth_below = 40.0, feature_angle = 0.0;
  double cone_angle = cvt::CvtOptions{}.cone_angle;
  double sizing_angle = cvt::SurfaceRemeshOptions{}.edge_sizing_angle;
  std::uint64_t seed = 1;
  std::size_t hausdorff_samples = 200000;
  unsigned threads = 0;
  bool no_fix = false, no_flip = false, no_smooth = false, no_planar_flips = false, ascii = false;
  cli::LoadOptions load;
};

void add_options(CLI::App& app, Options& o) {
  app.add_option("INPUT", o.input, "input mesh (.ply .obj .off .stl .gltf .glb)")->required();
  app.add_option("-o,--output", o.output, "remeshed surface (.obj .ply .off .glb .gltf)")->required();
  app.add_option("--vertices", o.vertices, "number of sites = output vertices (before region fixes)")
      ->check(CLI::PositiveNumber);
  app.add_option("--edge-length", o.edge_length,
                 "target edge length: model units, or \"1%\" of the bounding-box diagonal")
      ->type_name("L");
  app.add_option("--method", o.method,
                 "cvt (default: Lloyd iterations with GSP, the restricted Delaunay dual; regions) or edges (splits, "
                 "collapses, flips and smoothing on the surface, several times faster; the CVT where that fails)")
      ->check(CLI::IsMember({"cvt", "edges"}));
  app.add_option("--iterations", o.iterations, "Lloyd iteration cap (default 50)")->check(CLI::NonNegativeNumber);
  app.add_option("--tolerance", o.tolerance, "stop when the energy's relative decrease is below this (default 1e-4)")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--over-relaxation", o.over_relaxation,
                 "Lloyd steps first try this multiple of the step to the centroid (1 = off; default 1.6)")
      ->check(CLI::Range(1.0, 1.99));
  app.add_option("--init", o.init, "initial sites: poisson (default), farthest or random (area-uniform)")
      ->check(CLI::IsMember({"poisson", "farthest", "random"}));
  app.add_option("--seed", o.seed, "random seed of the initial sites");
  app.add_option("--faces-per-site", o.faces_per_site,
                 "working-mesh resolution: the input is split 1-to-4 until it has at least this many faces per "
                 "site (default " + std::to_string(o.faces_per_site) + "; more: slower, slightly finer regions; 0: no split)")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--threads", o.threads,
                 "threads of the geodesic propagations (default 0: automatic, two or more on working meshes of 200k+ "
                 "faces, where ties make the remesh vary slightly from run to run); 1: the same output every run")
      ->check(CLI::Range(0, 1024));
  app.add_option("--regions", o.regions,
                 "also write the input mesh with an int vertex `label` (its region) and a colour per region "
                 "(.ply .obj .off .glb .gltf)");
  app.add_option("--feature-angle", o.feature_angle,
                 "keep sharp features: edges whose faces' normals differ by more than this many degrees form "
                 "curves kept as chains of edges, their corners as vertices (0 = off; default 0)")
      ->check(CLI::Range(0.0, 180.0));
  app.add_option("--cone-angle", o.cone_angle,
                 "keep spike tips: an interior vertex whose angles sum to less than this many degrees but at least "
                 "half of it gets a fixed site, so the tip is a vertex of the remesh instead of being cut off "
                 "(0 = off, the default; 240 is a good value)")
      ->check(CLI::Range(0.0, 360.0));
  app.add_option("--sizing-angle", o.sizing_angle,
                 "edge operations: shorter edges where the surface bends tightly, each spanning at most this many "
                 "degrees of a bend, down to a quarter of the spacing (0 = one spacing everywhere)")
      ->check(CLI::Range(0.0, 180.0));
  app.add_flag("--no-fix", o.no_fix, "do not repair regions that are not disks (split, annuli)");
  app.add_flag("--no-planar-flips", o.no_planar_flips,
               "keep the working mesh's slivers inside planes (CAD fans) instead of flipping them to Delaunay "
               "triangles of the same plane (docs/cvt.md)");
  app.add_flag("--no-flip", o.no_flip, "write the restricted Delaunay dual as it is, without the angle-raising edge flips");
  app.add_flag("--no-smooth", o.no_smooth,
               "leave the vertices at the sites (no angle-raising moves along the input surface)");
  app.add_option("--smooth-below", o.smooth_below,
                 "post-pass: try to move vertices with an angle below this many degrees (default 40)")
      ->check(CLI::Range(1.0, 60.0));
  app.add_option("--hausdorff-samples", o.hausdorff_samples,
                 "with --stats: area-uniform points per surface for the Hausdorff distance (default 200000)");
  app.add_flag("--ascii", o.ascii, "ASCII PLY instead of binary");
  cli::add_load_options(app, o.load);
}

// "0.02" (model units) or "1%" (of the bounding-box diagonal, returned negative).
double parse_length(std::string text) {
  const bool percent = !text.empty() && text.back() == '%';
  if (percent) text.pop_back();
  const double value = cli::parse_number(text, "--edge-length");
  if (!(value > 0)) throw cli::UsageError("--edge-length: must be > 0");
  return percent ? -value : value;
}

void run(cli::Context& ctx, const Options& o) {
  if ((o.vertices > 0) == !o.edge_length.empty()) throw cli::UsageError("give exactly one of --vertices and --edge-length");
  const double length_arg = o.edge_length.empty() ? 0.0 : parse_length(o.edge_length);
  const std::initializer_list<io::Format> meshes{io::Format::obj, io::Format::ply, io::Format::off, io::Format::glb,
                                                 io::Format::gltf};
  cli::output_format(o.output, meshes);
  if (!o.regions.empty()) cli::output_format(o.regions, meshes, "--regions");
  if (!o.regions.empty() && o.method != "cvt") throw cli::UsageError("--regions needs --method cvt (edge operations make no regions)");

  const cli::LoadedMesh in = cli::load_input(ctx, o.input, o.load);
  cvt::SurfaceRemeshOptions so;
  cvt::CvtOptions& co = so.cvt;
  co.sites = o.vertices;
  co.edge_length = length_arg < 0 ? -length_arg / 100.0 * bounding_box(in.mesh).diagonal() : length_arg;
  co.max_iterations = o.iterations;
  co.tolerance = o.tolerance;
  co.over_relaxation = o.over_relaxation;
  co.initial = o.init == "farthest" ? cvt::InitialSites::farthest
               : o.init == "random"  ? cvt::InitialSites::random
                                     : cvt::InitialSites::poisson;
  co.seed = o.seed;
  co.min_faces_per_site = o.faces_per_site;
  co.threads = o.threads;
  co.fix_regions = !o.no_fix;
  co.planar_flips = !o.no_planar_flips;
  co.feature_angle = o.feature_angle;
  co.cone_angle = o.cone_angle;
  so.method = cvt::remesh_method(o.method);
  so.edge_sizing_angle = o.sizing_angle;
  ctx.settings()["method"] = o.method == "cvt" ? "lloyd-gsp" : "edges";
  if (o.vertices) ctx.settings()["vertices"] = o.vertices;
  else ctx.settings()["edge_length"] = co.edge_length;
  ctx.settings()["max_iterations"] = o.iterations;
  ctx.settings()["tolerance"] = o.tolerance;
  ctx.settings()["over_relaxation"] = o.over_relaxation;
  ctx.settings()["init"] = o.init;
  ctx.settings()["seed"] = o.seed;
  ctx.settings()["faces_per_site"] = o.faces_per_site;
  ctx.settings()["threads"] = o.threads;
  ctx.settings()["fix_regions"] = co.fix_regions;
  ctx.settings()["planar_flips"] = co.planar_flips;
  ctx.settings()["feature_angle"] = o.feature_angle;
  ctx.settings()["cone_angle"] = o.cone_angle;
  ctx.settings()["sizing_angle"] = o.sizing_angle;
  ctx.settings()["flip_edges"] = !o.no_flip;
  ctx.settings()["smooth"] = !o.no_smooth;
  ctx.settings()["smooth_below"] = o.smooth_below;

  // A progress line per iteration: the bar counts iterations against the cap, the label
  // carries the energy.
  std::unique_ptr<cli::Progress> progress = ctx.progress("initial sites");
  progress->update(0.0);
  co.on_iteration = [&](const cvt::IterationInfo& info) {
    char label[96];
    std::snprintf(label, sizeof label, "lloyd %d/%d energy %.6g", info.iteration, info.max_iterations, info.energy);
    progress.reset();
    progress = ctx.progress(label);
    progress->update(info.max_iterations ? double(info.iteration) / info.max_iterations : 1.0);
  };
  cvt::RemeshOptions& ro = so.remesh;
  ro.flip_edges = !o.no_flip;
  ro.smooth = !o.no_smooth;
  ro.smooth_below_angle = o.smooth_below;
  const cvt::SurfaceRemeshResult result = cvt::remesh_surface(in.mesh, so);
  progress.reset();
  cvt_app::report_cvt(ctx, result);
  ctx.timer().add("remesh", result.remesh_seconds);
  const TopologyReport topo_in = analyze_topology(in.mesh, build_connectivity(in.mesh));
  const TopologyReport topo_out = analyze_topology(result.mesh, build_connectivity(result.mesh));
  cvt_app::report_remesh(ctx, result, topo_in, topo_out);
  cvt_app::note_kept_components(ctx, result);
  // Fewer vertices asked for than the components' topology needs: said, not silently raised.
  std::size_t raised = 0, sites = 0;
  for (const cvt::ComponentReport& c : result.components)
    if (c.outcome == cvt::ComponentOutcome::remeshed) sites += c.sites, raised += c.sites == so.min_component_sites;
  if (o.vertices && raised && sites > o.vertices)
    ctx.note(std::to_string(o.vertices) + " vertices asked for, " + std::to_string(sites) + " sites used: " +
             std::to_string(raised) + (raised == 1 ? " component got " : " components got ") +
             std::to_string(so.min_component_sites) + " sites, the fewest a component is remeshed with");

  if (ctx.stats_requested()) {
    auto q = ctx.timer().scope("quality");
    cvt::HausdorffOptions ho;
    ho.samples = o.hausdorff_samples;
    ho.seed = o.seed;
    const cvt::MeshQuality mq = cvt::measure_mesh_quality(result.mesh);
    const cvt::HausdorffDistance hd = cvt::hausdorff_distance(in.mesh, result.mesh, ho);
    cvt_app::report_quality(ctx, mq, hd);
  }

  io::WriteOptions wo;
  wo.ascii = o.ascii;
  ctx.timer().time("write", [&] {
    io::write_mesh(o.output, result.mesh, {}, wo);
    if (!o.regions.empty()) cvt_app::write_regions(o.regions, in, result.vertex_label);
  });
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  return gsp::cli::run_app(
      argc, argv, "gsp-cvt",
      "Geodesic centroidal Voronoi tessellation (Lloyd iterations with GSP) and isotropic remeshing by its "
      "restricted Delaunay dual.",
      [&](CLI::App& app) { add_options(app, options); },
      [&](gsp::cli::Context& ctx) { run(ctx, options); });
}
