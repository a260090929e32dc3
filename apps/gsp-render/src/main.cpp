// gsp-render: a PNG preview of a mesh (or point cloud), optionally coloured by a per-vertex
// field with iso-lines or by per-face labels, with points, polylines and marked sources.
#include "overlays.hpp"
#include "view_options.hpp"

#include <gsp/cli/app.hpp>
#include <gsp/cli/load.hpp>
#include <gsp/cli/parse.hpp>
#include <gsp/errors.hpp>
#include <gsp/io/mesh_io.hpp>
#include <gsp/render/render.hpp>

#include <string>
#include <vector>

namespace {

struct Options {
  std::string input, output;
  std::string field, property, labels, label_property, points, polylines;
  std::vector<std::string> source_vertices, source_points;
  std::string size, view, range, background = "white", colormap = "viridis", up = "y";
  bool wireframe = false, antialias = false;
  gsp::render::RenderOptions render;
  gsp::cli::LoadOptions load;
};

void run(gsp::cli::Context& ctx, Options& opt) {
  using namespace gsp;
  // Option values first: a typo costs nothing.
  if (io::format_from_path(opt.output) != io::Format::unknown || opt.output.size() < 4 ||
      (opt.output.substr(opt.output.size() - 4) != ".png" && opt.output.substr(opt.output.size() - 4) != ".PNG"))
    throw cli::UsageError("-o: \"" + opt.output + "\": the picture must be a .png file");
  if (!opt.field.empty() && !opt.property.empty())
    throw cli::UsageError("--field and --property both give the field: choose one");
  if (!opt.labels.empty() && !opt.label_property.empty())
    throw cli::UsageError("--labels and --label-property both give the labels: choose one");
  render::RenderOptions& ro = opt.render;
  if (!opt.size.empty()) render_app::parse_size(opt.size, ro);
  if (!opt.view.empty()) render_app::parse_view(opt.view, ro);
  if (!opt.range.empty()) render_app::parse_range(opt.range, ro);
  ro.background = render_app::parse_color(opt.background, "--background");
  ro.colormap = opt.colormap == "turbo" ? io::ColorMap::turbo : io::ColorMap::viridis;
  ro.up = opt.up == "z" ? render::UpAxis::z : render::UpAxis::y;
  ro.wireframe = opt.wireframe;
  if (opt.antialias) ro.supersample = 2;

  opt.load.require_faces = false;   // a point cloud is drawn as points
  cli::LoadedMesh in = cli::load_input(ctx, opt.input, opt.load);

  render::Scene scene;
  const std::size_t nfile = in.file_vertices();
  auto to_mesh_order = [&](const std::vector<double>& file_values) {
    // Values are given per file vertex; welded copies of a vertex share one value.
    std::vector<double> v(in.mesh.num_vertices());
    for (std::size_t i = 0; i < nfile; ++i) v[in.vertex_map[i]] = file_values[i];
    return v;
  };
  ctx.timer().time("read", [&] {
    if (!opt.field.empty()) scene.vertex_field = to_mesh_order(render_app::read_field(opt.field, nfile, "vertices"));
    if (!opt.property.empty()) {
      std::vector<double> v = render_app::read_property(opt.input, opt.property);
      if (v.size() != nfile) throw IoError(opt.input, "", "property '" + opt.property + "' has the wrong length");
      scene.vertex_field = to_mesh_order(v);
    }
    if (!opt.labels.empty()) scene.face_labels = render_app::read_labels(opt.labels, in.mesh.num_faces());
    if (!opt.label_property.empty()) {
      std::vector<double> v = render_app::read_property(opt.input, opt.label_property);
      if (v.size() != nfile) throw IoError(opt.input, "", "property '" + opt.label_property + "' has the wrong length");
      scene.face_labels = render_app::face_labels_from_vertices(to_mesh_order(v), in.mesh.triangles, opt.input);
    }
    if (!opt.points.empty()) scene.points = render_app::read_points(opt.points);
    if (!opt.polylines.empty()) scene.polylines = render_app::read_polylines(opt.polylines);
  });
  for (const std::string& a : opt.source_vertices)
    for (Index v : cli::parse_index_list(a, "--source-vertex")) scene.sources.push_back(in.mesh.positions[in.mesh_vertex(v)]);
  for (const std::string& a : opt.source_points) scene.sources.push_back(cli::parse_vec3(a, "--source-point"));

  if (in.mesh.is_point_cloud()) {
    scene.points.insert(scene.points.end(), in.mesh.positions.begin(), in.mesh.positions.end());
    if (!scene.vertex_field.empty()) ctx.note("a point cloud has no surface to colour: the field is not shown");
    scene.vertex_field.clear();
  } else {
    scene.mesh = std::move(in.mesh);
  }

  render::RenderTimings t;
  const render::Image image = render::render(scene, ro, &t);
  ctx.timer().add("build", t.build);
  ctx.timer().add("compute", t.trace);
  ctx.timer().time("write", [&] { render::write_png(opt.output, image); });

  auto& s = ctx.settings();
  s["size"] = cli::Json::array_of(std::vector<int>{ro.width, ro.height});
  s["view"] = cli::Json::array_of(std::vector<double>{ro.azimuth, ro.elevation});
  s["up"] = opt.up;
  s["colormap"] = opt.colormap;
  s["iso_lines"] = ro.iso_lines;
  s["wireframe"] = ro.wireframe;
  s["supersample"] = ro.supersample;
  ctx.operations()["rays"] = static_cast<unsigned long long>(ro.width) * ro.height * ro.supersample * ro.supersample;
  ctx.stats()["output"]["path"] = opt.output;
}

}  // namespace

int main(int argc, char** argv) {
  Options opt;
  return gsp::cli::run_app(
      argc, argv, "gsp-render",
      "Render a PNG preview of a mesh: plain, coloured by a per-vertex field with iso-lines, or by "
      "per-face labels; with points, polylines and marked sources. No viewer needed.",
      [&](CLI::App& app) {
        app.add_option("MESH", opt.input, "Input mesh or point cloud (.obj .ply .off .stl .gltf .glb .xyz)")
            ->required();
        app.add_option("-o,--output", opt.output, "Output picture (.png)")->required()->type_name("OUT.png");
        app.add_option("--field", opt.field, "Per-vertex values, one per line in the file's vertex order "
                                             "(e.g. gsp-geodesic -o out.txt); NaN/inf drawn grey")
            ->type_name("FILE.txt");
        app.add_option("--property", opt.property,
                       "Use the mesh file's own per-vertex property NAME as the field (PLY 'distance', "
                       "'quality', glTF _NAME)")
            ->type_name("NAME");
        app.add_option("--labels", opt.labels, "Per-face integer labels, one per line (e.g. Voronoi regions); "
                                               "each label gets its own colour, < 0 none")
            ->type_name("FILE.txt");
        app.add_option("--label-property", opt.label_property,
                       "Colour faces by the mesh file's per-vertex integer property NAME (e.g. gsp-geodesic's "
                       "'source': geodesic Voronoi regions); a face takes its corners' majority label")
            ->type_name("NAME");
        app.add_option("--points", opt.points, "Draw these points as small spheres (any mesh/point format)")
            ->type_name("FILE");
        app.add_option("--polylines", opt.polylines,
                       "Draw polylines as tubes: 'x y z' per line, a blank line between polylines")
            ->type_name("FILE");
        app.add_option("--source-vertex", opt.source_vertices, "Mark these vertices (file indices) with red spheres")
            ->type_name("I[,J,...]");
        app.add_option("--source-point", opt.source_points, "Mark this point with a red sphere (repeatable)")
            ->type_name("x,y,z");
        app.add_option("--size", opt.size, "Picture size, WxH or N for N x N (default 1024)")->type_name("WxH");
        app.add_option("--view", opt.view, "Camera azimuth,elevation in degrees (default 30,20; 0,90 = from above)")
            ->type_name("AZ,EL");
        app.add_option("--up", opt.up, "The model's up axis")->check(CLI::IsMember({"y", "z"}))->capture_default_str();
        app.add_option("--iso", opt.render.iso_lines, "Number of iso-line intervals over the field's range (0 = none)")
            ->check(CLI::Range(0, 1000))
            ->capture_default_str();
        app.add_option("--range", opt.range, "Field values mapped to the colour map's ends (default: min,max)")
            ->type_name("LO,HI");
        app.add_option("--colormap", opt.colormap, "Colour map")
            ->check(CLI::IsMember({"viridis", "turbo"}))
            ->capture_default_str();
        app.add_flag("--wireframe", opt.wireframe, "Darken the mesh edges");
        app.add_flag("--aa", opt.antialias, "Anti-aliasing: 2x2 samples per pixel (about 4x slower)");
        app.add_option("--background", opt.background, "white, black, transparent or r,g,b")->capture_default_str();
        app.add_option("--threads", opt.render.threads, "Threads (0 = all cores)")
            ->check(CLI::Range(0, 1024))
            ->capture_default_str();
        gsp::cli::add_load_options(app, opt.load);
      },
      [&](gsp::cli::Context& ctx) { run(ctx, opt); });
}
