#include <gsp/cli/load.hpp>

#include <gsp/cli/app.hpp>
#include <gsp/errors.hpp>
#include <gsp/weld.hpp>

#include <cmath>
#include <cstdlib>
#include <numeric>

namespace gsp::cli {

void add_load_options(CLI::App& app, LoadOptions& options) {
  // Flag callbacks run during parsing, so a contradiction is a parse error (exit code 2).
  auto set_mode = [&options](WeldMode mode) {
    if (options.weld != WeldMode::automatic && options.weld != mode)
      throw CLI::ValidationError("--weld and --no-weld contradict each other");
    options.weld = mode;
  };
  app.add_flag_callback(
      "--weld", [set_mode] { set_mode(WeldMode::always); },
      "Merge vertices at the same position whatever the format (default: only STL and glTF/GLB)");
  app.add_flag_callback(
      "--no-weld", [set_mode] { set_mode(WeldMode::never); },
      "Use the file's vertices as stored, even for STL and glTF/GLB");
  app.add_option("--weld-tolerance", options.weld_tolerance,
                 "Merge vertices closer than T (model units) when welding; 0 = identical positions and rounding noise (1e-10 of the bounding box's diagonal)")
      ->type_name("T")
      ->check(CLI::Validator(
          [](std::string& text) -> std::string {
            char* end = nullptr;
            const double t = std::strtod(text.c_str(), &end);
            if (text.empty() || *end != '\0' || !std::isfinite(t) || t < 0)
              return "\"" + text + "\" is not a finite number >= 0";
            return {};
          },
          "", "non-negative"))
      ->capture_default_str();
}

bool format_needs_weld(io::Format format) {
  return format == io::Format::stl || format == io::Format::gltf || format == io::Format::glb;
}

Index LoadedMesh::mesh_vertex(std::size_t file_vertex) const {
  if (file_vertex >= vertex_map.size())
    throw InvalidInput(path + ": vertex " + std::to_string(file_vertex) + " does not exist (the file has " +
                       std::to_string(vertex_map.size()) + " vertices)");
  return vertex_map[file_vertex];
}

namespace {

bool should_weld(const LoadOptions& options, io::Format format) {
  switch (options.weld) {
    case WeldMode::always: return true;
    case WeldMode::never: return false;
    case WeldMode::automatic: return format_needs_weld(format);
  }
  return false;
}

io::ReadResult read_checked(const std::string& path, const LoadOptions& options) {
  io::ReadResult r = io::read_mesh(path, io::ReadOptions{options.read_threads});
  // The readers validate already; this keeps the promise for any reader that forgets, and
  // turns the library's message into one that names the file.
  try {
    validate(r.mesh);
  } catch (const InvalidInput& e) {
    throw IoError(path, "", e.what());
  }
  if (options.require_faces && r.mesh.is_point_cloud())
    throw IoError(path, "", r.mesh.num_vertices() == 0 ? "no vertices and no faces"
                                                       : "no faces (a point cloud); this tool needs a triangle mesh");
  return r;
}

void weld_into(LoadedMesh& out, const LoadOptions& options) {
  WeldResult w = weld_input(out.mesh, options.weld_tolerance);
  out.raw = std::move(out.mesh);
  out.mesh = std::move(w.mesh);
  out.vertex_map = std::move(w.vertex_map);
  out.merged = w.merged;
  out.welded = true;
}

void identity_map(LoadedMesh& out) {
  out.vertex_map.resize(out.mesh.num_vertices());
  std::iota(out.vertex_map.begin(), out.vertex_map.end(), Index{0});
}

const char* weld_mode_name(WeldMode m) {
  switch (m) {
    case WeldMode::automatic: return "auto";
    case WeldMode::always: return "always";
    case WeldMode::never: return "never";
  }
  return "?";
}

}  // namespace

LoadedMesh load_mesh(const std::string& path, const LoadOptions& options) {
  LoadedMesh out;
  out.path = path;
  io::ReadResult r = read_checked(path, options);
  out.info = std::move(r.info);
  out.mesh = std::move(r.mesh);
  if (should_weld(options, out.info.format) && !out.mesh.is_point_cloud())
    weld_into(out, options);
  else
    identity_map(out);
  return out;
}

LoadedMesh load_input(Context& ctx, const std::string& path, const LoadOptions& options) {
  ctx.set_input(path);
  LoadedMesh out;
  out.path = path;
  io::ReadResult r = ctx.timer().time("read", [&] { return read_checked(path, options); });
  out.info = std::move(r.info);
  out.mesh = std::move(r.mesh);
  if (should_weld(options, out.info.format) && !out.mesh.is_point_cloud())
    ctx.timer().time("weld", [&] { weld_into(out, options); });
  else
    identity_map(out);

  Json& in = ctx.input();
  in["path"] = path;
  in["format"] = io::format_name(out.info.format);
  in["binary"] = out.info.binary;
  in["file_vertices"] = out.info.file_vertices;
  in["file_faces"] = out.info.file_faces;
  in["triangles"] = out.mesh.num_faces();
  in["vertices"] = out.mesh.num_vertices();
  ctx.set_vertices(out.mesh.num_vertices());
  in["welded"] = out.welded;
  in["merged_vertices"] = out.merged;
  Json& s = ctx.settings();
  s["weld"] = weld_mode_name(options.weld);
  s["weld_tolerance"] = options.weld_tolerance;
  return out;
}

}  // namespace gsp::cli
