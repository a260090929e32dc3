#include <gsp/io/atomic_file.hpp>
#include <gsp/io/mesh_io.hpp>
#include <gsp/io/polyline_io.hpp>

#include "gltf_builder.hpp"
#include "writers.hpp"

#include <cmath>
#include <cstdint>
#include <limits>

namespace gsp::io {

namespace {

void append_point(std::string& out, Vec3 p) {
  detail::append_number(out, p.x);
  out += ' ';
  detail::append_number(out, p.y);
  out += ' ';
  detail::append_number(out, p.z);
}

void write_text(const std::string& path, const std::string& text) {
  AtomicFile file(path);
  file.write(text.data(), text.size());
  file.commit();
}

void write_obj_lines(const std::string& path, const std::vector<std::vector<Vec3>>& lines) {
  std::string out = "# written by gsp: " + std::to_string(lines.size()) + " polylines\n";
  for (const auto& line : lines)
    for (const Vec3& p : line) {
      out += "v ";
      append_point(out, p);
      out += '\n';
    }
  long long first = 1;
  for (const auto& line : lines) {
    if (line.size() >= 2) {
      out += 'l';
      for (std::size_t i = 0; i < line.size(); ++i) {
        out += ' ';
        detail::append_number(out, first + static_cast<long long>(i));
      }
      out += '\n';
    }
    first += static_cast<long long>(line.size());
  }
  write_text(path, out);
}

void write_ply_lines(const std::string& path, const std::vector<std::vector<Vec3>>& lines) {
  std::size_t points = 0, edges = 0;
  for (const auto& line : lines) points += line.size(), edges += line.empty() ? 0 : line.size() - 1;
  std::string out = "ply\nformat ascii 1.0\ncomment written by gsp: polylines\nelement vertex " +
                    std::to_string(points) +
                    "\nproperty double x\nproperty double y\nproperty double z\nproperty int polyline\nelement edge " +
                    std::to_string(edges) + "\nproperty int vertex1\nproperty int vertex2\nend_header\n";
  for (std::size_t l = 0; l < lines.size(); ++l)
    for (const Vec3& p : lines[l]) {
      append_point(out, p);
      out += ' ';
      detail::append_number(out, static_cast<long long>(l));
      out += '\n';
    }
  long long first = 0;
  for (const auto& line : lines) {
    for (std::size_t i = 0; i + 1 < line.size(); ++i) {
      detail::append_number(out, first + static_cast<long long>(i));
      out += ' ';
      detail::append_number(out, first + static_cast<long long>(i) + 1);
      out += '\n';
    }
    first += static_cast<long long>(line.size());
  }
  write_text(path, out);
}

void write_gltf_lines(const std::string& path, const std::vector<std::vector<Vec3>>& lines, bool binary) {
  detail::Builder b;
  b.model.asset.version = "2.0";
  b.model.asset.generator = "gsp";
  b.model.buffers.emplace_back();
  tinygltf::Mesh mesh;
  for (const auto& line : lines) {
    if (line.size() < 2) continue;
    std::vector<float> pos;
    std::vector<double> lo(3, std::numeric_limits<double>::infinity()), hi(3, -std::numeric_limits<double>::infinity());
    for (const Vec3& p : line)
      for (int k = 0; k < 3; ++k) {
        pos.push_back(static_cast<float>(p[k]));
        lo[k] = std::min(lo[k], double(pos.back()));
        hi[k] = std::max(hi[k], double(pos.back()));
      }
    const int accessor = b.add_floats(pos, TINYGLTF_TYPE_VEC3, line.size());
    b.model.accessors[accessor].minValues = lo;
    b.model.accessors[accessor].maxValues = hi;
    tinygltf::Primitive prim;
    prim.mode = TINYGLTF_MODE_LINE_STRIP;
    prim.attributes["POSITION"] = accessor;
    mesh.primitives.push_back(prim);
  }
  tinygltf::Node node;
  if (!mesh.primitives.empty()) {
    b.model.meshes.push_back(mesh);
    node.mesh = 0;
  }
  while (b.data().size() % 4) b.data().push_back(0);
  if (b.data().empty()) b.model.buffers.clear();
  b.model.nodes.push_back(node);
  tinygltf::Scene scene;
  scene.nodes.push_back(0);
  b.model.scenes.push_back(scene);
  b.model.defaultScene = 0;
  detail::save_gltf(path, b.model, binary);
}

}  // namespace

void write_polylines(const std::string& path, const std::vector<std::vector<Vec3>>& polylines) {
  for (const auto& line : polylines)
    for (const Vec3& p : line)
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
        throw InvalidInput("polyline point is not finite");
  switch (format_from_path(path)) {
    case Format::obj: return write_obj_lines(path, polylines);
    case Format::ply: return write_ply_lines(path, polylines);
    case Format::gltf: return write_gltf_lines(path, polylines, false);
    case Format::glb: return write_gltf_lines(path, polylines, true);
    default: throw IoError(path, "", "polylines are written as .obj, .ply, .gltf or .glb");
  }
}

}  // namespace gsp::io
