#pragma once
// Loading the input mesh the way every app does it: read with gsp::io::read_mesh, then weld
// by position where the format needs it, so that distances cross the seams where STL and
// glTF split vertices. The vertex map is kept so results go back to the file's own vertices.
//
//   gsp::cli::LoadOptions load;                  // setup: gsp::cli::add_load_options(app, load);
//   auto in = gsp::cli::load_input(ctx, path, load);
//   std::vector<double> d = compute(in.mesh);    // one value per welded vertex
//   gsp::io::write_mesh(out, in.file_mesh(), {{{"distance", to_float(in.to_file_order(d))}}});
#include <gsp/io/mesh_io.hpp>
#include <gsp/mesh.hpp>
#include <gsp/types.hpp>
#include <gsp/weld.hpp>

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace gsp::cli {

class Context;

enum class WeldMode {
  automatic,  // weld formats that split vertices (STL, glTF, GLB); keep others as stored
  always,     // weld whatever the format (e.g. an OBJ with seams like the Newell teapot)
  never,      // compute on the file's vertices as they are
};

struct LoadOptions {
  WeldMode weld = WeldMode::automatic;
  double weld_tolerance = 0.0;   // 0: identical positions and rounding noise (weld_input); > 0: closer than this (model units)
  bool require_faces = true;     // a point cloud is an input error unless the app accepts one
  unsigned read_threads = 0;     // parsing a big text file: 0 = all cores, 1 = one (io::ReadOptions)
};

// --weld / --no-weld / --weld-tolerance T bound to `options`.
void add_load_options(CLI::App& app, LoadOptions& options);

// True for the formats that store no shared vertices or split them at seams.
bool format_needs_weld(io::Format format);

struct LoadedMesh {
  std::string path;
  io::ReadInfo info;                // format, counts as stored in the file, notes
  TriangleMesh mesh;                // what to compute on: welded when `welded` is true
  TriangleMesh raw;                 // the mesh as read, kept only when welded (else empty)
  std::vector<Index> vertex_map;    // file vertex -> mesh vertex (identity when not welded)
  bool welded = false;
  std::size_t merged = 0;           // file vertices merged into another one

  // The mesh in the file's own vertex order (for writing results next to the input geometry).
  const TriangleMesh& file_mesh() const { return welded ? raw : mesh; }
  std::size_t file_vertices() const { return vertex_map.size(); }
  // Per-mesh-vertex values in the file's vertex order.
  template <class T>
  std::vector<T> to_file_order(const std::vector<T>& values) const {
    return unweld_values(values, vertex_map);
  }
  // A vertex index as the user sees it (the file's numbering) -> mesh vertex.
  // Throws gsp::InvalidInput naming the file when it is out of range.
  Index mesh_vertex(std::size_t file_vertex) const;
};

// Reads and (per options) welds. Throws gsp::IoError naming the file for anything wrong
// with it (including non-finite coordinates and bad indices found by gsp::validate).
LoadedMesh load_mesh(const std::string& path, const LoadOptions& options);

// load_mesh, plus: declares the input for error messages, times it (phases "read" and
// "weld"), and fills the stats sections "input" (path, format, file and mesh counts) and
// "settings" (weld mode and tolerance).
LoadedMesh load_input(Context& ctx, const std::string& path, const LoadOptions& options);

}  // namespace gsp::cli
