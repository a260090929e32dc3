#pragma once
// Reading and writing meshes and point clouds. The format is chosen by the file extension.
// Every reader accounts for every face of the file (polygons are fan-triangulated) or throws
// gsp::IoError naming the file and the place; no reader allocates from a header count before
// the data to fill it is known to be there.
#include <gsp/errors.hpp>
#include <gsp/mesh.hpp>

#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace gsp::io {

enum class Format { obj, ply, off, stl, gltf, glb, xyz, txt, unknown };

// By extension, case-insensitive (".ply" -> ply, ".txt" -> txt, ...).
Format format_from_path(const std::string& path);
const char* format_name(Format f);

// Per-vertex data written next to the geometry (and read back where the format has it).
struct VertexAttributes {
  // PLY: `float NAME` vertex properties. glTF: accessor `_NAME` (upper-cased, FLOAT SCALAR).
  // OBJ/OFF: ignored (colours are written where the format has them).
  std::vector<std::pair<std::string, std::vector<float>>> scalars;
  // PLY: `int NAME`. glTF: `_NAME` as FLOAT SCALAR (custom integer attributes are not portable).
  std::vector<std::pair<std::string, std::vector<std::int32_t>>> labels;
  // Empty, or one RGBA colour per vertex. PLY red/green/blue/alpha uchar, glTF COLOR_0,
  // OBJ "v x y z r g b" (the MeshLab extension), OFF as COFF.
  std::vector<std::array<std::uint8_t, 4>> colors;
};

struct ReadInfo {
  Format format = Format::unknown;
  bool binary = false;
  std::size_t file_vertices = 0;      // vertices as stored in the file
  std::size_t file_faces = 0;         // faces/polygons as stored in the file
  std::size_t polygons_split = 0;     // faces with more than 3 corners that were fan-triangulated
  bool has_normals = false;
  std::vector<std::string> notes;     // ignored elements/properties, skipped primitives, ...
};

struct ReadResult {
  TriangleMesh mesh;
  ReadInfo info;
  // Per-vertex data the file carries besides positions and normals: PLY scalar vertex
  // properties (float/double -> scalars, integer types -> labels) and colours; glTF `_NAME`
  // attributes (-> scalars, name without the underscore) and COLOR_0; OBJ `v x y z r g b` and
  // COFF colours. An attribute present on only some glTF primitives is dropped (with a note).
  VertexAttributes attributes;
};

struct ReadOptions {
  // Threads for parsing big text files (PLY ascii and OBJ of 1 MB or more): 0 = the
  // machine's cores, 1 = the calling thread only; never more than one per half of
  // parallel_from_bytes of the file. The result does not depend on it.
  unsigned threads = 0;
  // Smallest file parsed on several threads (smaller ones: starting threads costs more than it
  // gains). The differential fuzz targets set 0 to send every input through both parsers.
  std::size_t parallel_from_bytes = std::size_t(1) << 20;
};

// Throws gsp::IoError (cannot open, unknown format, malformed, truncated, NaN/Inf coordinates,
// index out of range). Points without faces are returned as a point cloud.
ReadResult read_mesh(const std::string& path, const ReadOptions& options = {});

struct WriteOptions {
  bool ascii = false;   // PLY: binary little-endian by default
};

// Writes atomically: to a temporary file in the same folder, renamed over `path` at the end,
// so an error never leaves a partial or half-overwritten file. Throws gsp::IoError.
// Formats: .ply (binary little-endian, or ascii), .obj, .off (COFF with colours), .gltf
// (embedded base64 buffer), .glb. STL and XYZ are read-only: writing them throws IoError.
// Attribute arrays must have one entry per vertex (gsp::InvalidInput otherwise).
void write_mesh(const std::string& path, const TriangleMesh& mesh,
                const VertexAttributes& attributes = {}, const WriteOptions& options = {});

// One value per line, full float precision ("inf" for unreached values), atomically.
void write_values_txt(const std::string& path, const std::vector<double>& values);
// Reads what write_values_txt writes (used by gsp-render --field and tests).
std::vector<double> read_values_txt(const std::string& path);

}  // namespace gsp::io
