// gsp-info: what is in a mesh file (counts, topology before and after welding, edge and
// triangle statistics, optionally the cache-layout gain), and format conversion with -o.
#include "measures.hpp"
#include "report.hpp"

#include <gsp/cli/app.hpp>
#include <gsp/cli/load.hpp>
#include <gsp/cli/parse.hpp>
#include <gsp/io/mesh_io.hpp>
#include <gsp/layout.hpp>
#include <gsp/render/preview_cli.hpp>
#include <gsp/render/render.hpp>
#include <gsp/topology.hpp>
#include <gsp/weld.hpp>

#include <chrono>
#include <cstdio>
#include <string>

namespace {

struct Options {
  std::string input;
  std::string output;
  bool json = false;
  bool layout = false;
  bool ascii = false;
  gsp::render::PreviewRequest preview;   // --png (the mesh with its edges), --view, --png-size
  gsp::cli::LoadOptions load;
};

void run(gsp::cli::Context& ctx, Options& opt) {
  using namespace gsp;
  // Check the output names before any work: a typo in the extension costs nothing.
  render::RenderOptions view = render::preview_options(opt.preview);
  view.wireframe = true;
  if (!opt.output.empty())
    cli::output_format(opt.output, {io::Format::ply, io::Format::obj, io::Format::off, io::Format::glb,
                                    io::Format::gltf});

  opt.load.require_faces = false;  // gsp-info describes point clouds too
  cli::LoadedMesh in = cli::load_input(ctx, opt.input, opt.load);
  const TriangleMesh& raw = in.file_mesh();

  info::Report r;
  r.path = opt.input;
  r.info = in.info;
  r.triangles = raw.num_faces();
  r.point_cloud = raw.is_point_cloud();
  r.weld_enabled = opt.load.weld != cli::WeldMode::never;
  r.weld_tolerance = opt.load.weld_tolerance;

  // The report always shows the welded figures (SOURCES.md style), even for formats the
  // apps compute on unwelded; `welded_storage` holds that mesh when `in` did not weld.
  TriangleMesh welded_storage;
  const TriangleMesh* welded = &in.mesh;
  if (r.weld_enabled && !in.welded && !r.point_cloud) {
    welded_storage = ctx.timer().time("weld", [&] { return weld_input(raw, opt.load.weld_tolerance).mesh; });
    welded = &welded_storage;
  }
  r.welded_vertices = welded->num_vertices();
  r.merged_vertices = raw.num_vertices() - welded->num_vertices();

  r.bbox = gsp::bounding_box(raw);
  if (!r.point_cloud) {
    {
      auto t = ctx.timer().scope("build");
      const Connectivity raw_conn = build_connectivity(raw);
      r.raw = analyze_topology(raw, raw_conn);
    }
    const Connectivity conn = ctx.timer().time("build", [&] { return build_connectivity(*welded); });
    auto t = ctx.timer().scope("compute");
    r.welded = analyze_topology(*welded, conn);
    r.edge_length = info::edge_lengths(*welded, conn);
    r.shape = info::shape_measures(*welded);
    r.max_valence = info::max_valence(conn);
  }
  if (opt.layout && !r.point_cloud) {
    info::LayoutMeasure l;
    l.before = mean_neighbour_index_distance(*welded);
    const auto t0 = std::chrono::steady_clock::now();
    const Layout layout = compute_cache_layout(*welded);
    l.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    ctx.timer().add("layout", l.seconds);
    l.after = mean_neighbour_index_distance(apply_layout(*welded, layout));
    r.layout = l;
  }

  if (!opt.output.empty()) {
    // The mesh the other apps compute on: STL/glTF welded, other formats as stored.
    io::WriteOptions w;
    w.ascii = opt.ascii;
    ctx.timer().time("write", [&] { io::write_mesh(opt.output, in.mesh, {}, w); });
    ctx.stats()["output"]["path"] = opt.output;
    ctx.stats()["output"]["vertices"] = in.mesh.num_vertices();
    ctx.stats()["output"]["faces"] = in.mesh.num_faces();
  }

  if (opt.preview.wanted())
    ctx.timer().time("preview", [&] {
      render::Scene scene;
      scene.mesh = in.mesh;
      render::write_png(opt.preview.png, render::render(scene, view));
    });

  ctx.settings()["layout"] = opt.layout;
  cli::Json report = info::to_json(r);
  if (!ctx.stats_to_stdout()) {  // "--stats -" owns stdout; the report is in the stats then
    if (opt.json)
      std::printf("%s\n", report.dump().c_str());
    else
      info::print_text(r, stdout);
  }
  ctx.stats()["result"] = std::move(report);
}

}  // namespace

int main(int argc, char** argv) {
  Options opt;
  return gsp::cli::run_app(
      argc, argv, "gsp-info",
      "Describe a mesh file: counts, topology as stored and after welding, bounding box, edge "
      "lengths, triangle shape; optionally the cache-layout gain. With -o, convert it.",
      [&](CLI::App& app) {
        app.add_option("MESH", opt.input, "Input mesh (.obj .ply .off .stl .gltf .glb .xyz)")->required();
        app.add_flag("--json", opt.json, "Print the report as JSON instead of text");
        app.add_flag("--layout", opt.layout,
                     "Also measure the cache layout: mean neighbour index distance before/after, and its time");
        app.add_option("-o,--output", opt.output,
                       "Convert: write the mesh to OUT (.ply .obj .off .glb .gltf); STL and glTF input is "
                       "welded unless --no-weld")
            ->type_name("OUT");
        app.add_flag("--ascii", opt.ascii, "Write PLY output as ASCII (default: binary little-endian)");
        gsp::render::add_preview_options(app, opt.preview, "the mesh with its edges");
        gsp::cli::add_load_options(app, opt.load);
      },
      [&](gsp::cli::Context& ctx) { run(ctx, opt); });
}
