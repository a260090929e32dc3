// Format dispatch for read_mesh/write_mesh and the plain-text value files.
#include <gsp/io/atomic_file.hpp>
#include <gsp/io/mesh_io.hpp>

#include "parse_util.hpp"
#include "readers.hpp"
#include "text_pieces.hpp"
#include "writers.hpp"

#include <sys/stat.h>

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>

namespace gsp::io {

Format format_from_path(const std::string& path) {
  const std::size_t dot = path.find_last_of('.');
  const std::size_t slash = path.find_last_of('/');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return Format::unknown;
  std::string ext = path.substr(dot + 1);
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (ext == "obj") return Format::obj;
  if (ext == "ply") return Format::ply;
  if (ext == "off") return Format::off;
  if (ext == "stl") return Format::stl;
  if (ext == "gltf") return Format::gltf;
  if (ext == "glb") return Format::glb;
  if (ext == "xyz") return Format::xyz;
  if (ext == "txt") return Format::txt;
  return Format::unknown;
}

const char* format_name(Format f) {
  switch (f) {
    case Format::obj: return "OBJ";
    case Format::ply: return "PLY";
    case Format::off: return "OFF";
    case Format::stl: return "STL";
    case Format::gltf: return "glTF";
    case Format::glb: return "GLB";
    case Format::xyz: return "XYZ";
    case Format::txt: return "TXT";
    case Format::unknown: break;
  }
  return "unknown";
}

namespace detail {

std::string read_whole_file(const std::string& path) {
  struct stat st;
  if (::stat(path.c_str(), &st) != 0) throw IoError(path, "", std::string("cannot open: ") + std::strerror(errno));
  if (!S_ISREG(st.st_mode)) throw IoError(path, "", "not a regular file");
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) throw IoError(path, "", std::string("cannot open: ") + std::strerror(errno));
  std::string bytes(static_cast<std::size_t>(st.st_size), '\0');
  const std::size_t got = bytes.empty() ? 0 : std::fread(&bytes[0], 1, bytes.size(), f);
  const bool failed = std::ferror(f) != 0;
  std::fclose(f);
  if (failed) throw IoError(path, byte_at(got), "read error");
  bytes.resize(got);   // the file may have shrunk since stat
  return bytes;
}

}  // namespace detail

ReadResult read_mesh(const std::string& path, const ReadOptions& options) {
  const Format format = format_from_path(path);
  if (format == Format::unknown || format == Format::txt)
    throw IoError(path, "", "unknown mesh format (expected .obj .ply .off .stl .gltf .glb .xyz)");
  const std::string bytes = detail::read_whole_file(path);
  if (bytes.empty()) throw IoError(path, "", "empty file");
  const unsigned threads = detail::reading_threads(options, bytes.size());
  switch (format) {
    case Format::obj: return detail::read_obj(path, bytes, threads);
    case Format::ply: return detail::read_ply(path, bytes, threads);
    case Format::off: return detail::read_off(path, bytes);
    case Format::stl: return detail::read_stl(path, bytes);
    case Format::xyz: return detail::read_xyz(path, bytes);
    case Format::gltf: return detail::read_gltf(path, bytes, false);
    case Format::glb: return detail::read_gltf(path, bytes, true);
    default: break;
  }
  throw IoError(path, "", "unknown mesh format");
}

void write_mesh(const std::string& path, const TriangleMesh& mesh, const VertexAttributes& attributes,
                const WriteOptions& options) {
  const Format format = format_from_path(path);
  if (format == Format::stl || format == Format::xyz)
    throw IoError(path, "", std::string(format_name(format)) + " is read-only: write .ply .obj .off .gltf or .glb");
  if (format == Format::unknown || format == Format::txt)
    throw IoError(path, "", "unknown mesh format (expected .ply .obj .off .gltf .glb)");
  detail::check_writable(mesh, attributes);
  switch (format) {
    case Format::ply: return detail::write_ply(path, mesh, attributes, options.ascii);
    case Format::obj: return detail::write_obj(path, mesh, attributes);
    case Format::off: return detail::write_off(path, mesh, attributes);
    case Format::gltf: return detail::write_gltf(path, mesh, attributes, false);
    case Format::glb: return detail::write_gltf(path, mesh, attributes, true);
    default: break;
  }
}

void write_values_txt(const std::string& path, const std::vector<double>& values) {
  std::string out;
  out.reserve(values.size() * 12);
  char buf[64];
  for (double v : values) {
    if (std::isinf(v)) out += v > 0 ? "inf" : "-inf";
    else if (std::isnan(v)) out += "nan";
    else out.append(buf, std::to_chars(buf, buf + sizeof buf, v, std::chars_format::general, 9).ptr);   // = %.9g, 10x faster
    out += '\n';
  }
  AtomicFile file(path);
  file.write(out.data(), out.size());
  file.commit();
}

std::vector<double> read_values_txt(const std::string& path) {
  const std::string bytes = detail::read_whole_file(path);
  detail::LineScanner lines(path, bytes);
  std::vector<double> values;
  std::string_view line;
  std::vector<std::string_view> tok;
  while (lines.next(line)) {
    detail::split(line, tok);
    if (tok.empty() || tok[0].front() == '#') continue;
    double v;
    if (tok.size() != 1 || !detail::parse_double(tok[0], v))
      lines.fail("expected one number, found '" + std::string(line.substr(0, 40)) + "'");
    values.push_back(v);
  }
  return values;
}

}  // namespace gsp::io
