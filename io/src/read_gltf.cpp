// glTF 2.0 (.gltf and .glb) through tinygltf. tinygltf parses the JSON and loads buffers; all
// geometry is then read through accessors that are checked here against their buffer views
// and buffers first, so a broken file is an IoError naming the accessor, never a stray read.
// Images are not decoded (no-op loader) and no file system path expansion is done.
#include "parse_util.hpp"
#include "readers.hpp"

#include <tiny_gltf.h>

#include <sys/stat.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <map>

namespace gsp::io::detail {

namespace {

// ---- tinygltf callbacks: no image decoding, plain files only (no wordexp, no /dev/zero) ----

bool skip_image(tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int, void*) {
  return true;
}
bool regular_file(const std::string& p, void*) {
  struct stat st;
  return ::stat(p.c_str(), &st) == 0 && S_ISREG(st.st_mode);
}
std::string same_path(const std::string& p, void*) { return p; }
bool read_file(std::vector<unsigned char>* out, std::string* err, const std::string& p, void*) {
  if (!regular_file(p, nullptr)) {
    if (err) *err += "cannot open '" + p + "'\n";
    return false;
  }
  std::ifstream in(p, std::ios::binary);
  out->assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  return static_cast<bool>(in) || in.eof();
}
bool no_write(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
  if (err) *err += "writing is disabled while reading\n";
  return false;
}

// ---- column-major 4x4 transforms ----
using Mat4 = std::array<double, 16>;
constexpr Mat4 kIdentity = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

Mat4 mul(const Mat4& a, const Mat4& b) {
  Mat4 c{};
  for (int col = 0; col < 4; ++col)
    for (int row = 0; row < 4; ++row) {
      double s = 0;
      for (int k = 0; k < 4; ++k) s += a[k * 4 + row] * b[col * 4 + k];
      c[col * 4 + row] = s;
    }
  return c;
}

Mat4 local_transform(const tinygltf::Node& n) {
  if (n.matrix.size() == 16) {
    Mat4 m;
    std::copy(n.matrix.begin(), n.matrix.end(), m.begin());
    return m;
  }
  Mat4 t = kIdentity, r = kIdentity, s = kIdentity;
  if (n.translation.size() == 3) {
    t[12] = n.translation[0];
    t[13] = n.translation[1];
    t[14] = n.translation[2];
  }
  if (n.rotation.size() == 4) {
    const double x = n.rotation[0], y = n.rotation[1], z = n.rotation[2], w = n.rotation[3];
    r = {1 - 2 * (y * y + z * z), 2 * (x * y + z * w), 2 * (x * z - y * w), 0,
         2 * (x * y - z * w), 1 - 2 * (x * x + z * z), 2 * (y * z + x * w), 0,
         2 * (x * z + y * w), 2 * (y * z - x * w), 1 - 2 * (x * x + y * y), 0,
         0, 0, 0, 1};
  }
  if (n.scale.size() == 3) {
    s[0] = n.scale[0];
    s[5] = n.scale[1];
    s[10] = n.scale[2];
  }
  return mul(t, mul(r, s));
}

Vec3 apply_point(const Mat4& m, Vec3 p) {
  return {m[0] * p.x + m[4] * p.y + m[8] * p.z + m[12], m[1] * p.x + m[5] * p.y + m[9] * p.z + m[13],
          m[2] * p.x + m[6] * p.y + m[10] * p.z + m[14]};
}

// Normals transform with the inverse transpose of the linear part (cofactor matrix up to scale).
Vec3 apply_normal(const Mat4& m, Vec3 n) {
  const Vec3 c0{m[0], m[1], m[2]}, c1{m[4], m[5], m[6]}, c2{m[8], m[9], m[10]};
  const Vec3 r0 = cross(c1, c2), r1 = cross(c2, c0), r2 = cross(c0, c1);
  Vec3 out = n.x * r0 + n.y * r1 + n.z * r2;
  if (dot(c0, r0) < 0) out = -1.0 * out;   // mirrored transform: cofactors flip the normal
  const double len = norm(out);
  return len > 0 ? (1.0 / len) * out : n;
}

// ---- accessors ----

struct View {
  const std::uint8_t* base = nullptr;
  std::size_t stride = 0, count = 0;
  int comps = 0, type = 0;
  bool normalized = false;

  double get(std::size_t i, int c) const {
    const std::uint8_t* p = base + i * stride;
    switch (type) {
      case TINYGLTF_COMPONENT_TYPE_BYTE: { std::int8_t v; std::memcpy(&v, p + c, 1); return normalized ? std::max(v / 127.0, -1.0) : v; }
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: { std::uint8_t v; std::memcpy(&v, p + c, 1); return normalized ? v / 255.0 : v; }
      case TINYGLTF_COMPONENT_TYPE_SHORT: { std::int16_t v; std::memcpy(&v, p + 2 * c, 2); return normalized ? std::max(v / 32767.0, -1.0) : v; }
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: { std::uint16_t v; std::memcpy(&v, p + 2 * c, 2); return normalized ? v / 65535.0 : v; }
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: { std::uint32_t v; std::memcpy(&v, p + 4 * c, 4); return v; }
      default: { float v; std::memcpy(&v, p + 4 * c, 4); return v; }
    }
  }
};

struct Reader {
  const std::string& path;
  const tinygltf::Model& model;

  [[noreturn]] void fail(int accessor, const std::string& what) const {
    throw IoError(path, "accessor " + std::to_string(accessor), what);
  }

  // Checks everything an element read depends on; `allowed_comps` lists accepted widths.
  View view(int index, std::initializer_list<int> allowed_comps, bool indices) const {
    if (index < 0 || static_cast<std::size_t>(index) >= model.accessors.size())
      throw IoError(path, "accessor " + std::to_string(index), "no such accessor (" + std::to_string(model.accessors.size()) + " accessors)");
    const tinygltf::Accessor& a = model.accessors[index];
    if (a.sparse.isSparse) fail(index, "sparse accessors are not supported");
    View v;
    switch (a.type) {
      case TINYGLTF_TYPE_SCALAR: v.comps = 1; break;
      case TINYGLTF_TYPE_VEC2: v.comps = 2; break;
      case TINYGLTF_TYPE_VEC3: v.comps = 3; break;
      case TINYGLTF_TYPE_VEC4: v.comps = 4; break;
      default: fail(index, "unsupported accessor type " + std::to_string(a.type));
    }
    if (std::find(allowed_comps.begin(), allowed_comps.end(), v.comps) == allowed_comps.end())
      fail(index, "has " + std::to_string(v.comps) + " components per element, which this attribute does not allow");
    std::size_t csize = 0;
    switch (a.componentType) {
      case TINYGLTF_COMPONENT_TYPE_BYTE: case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: csize = 1; break;
      case TINYGLTF_COMPONENT_TYPE_SHORT: case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: csize = 2; break;
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: case TINYGLTF_COMPONENT_TYPE_FLOAT: csize = 4; break;
      default: fail(index, "invalid componentType " + std::to_string(a.componentType));
    }
    if (indices && (a.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT || a.componentType == TINYGLTF_COMPONENT_TYPE_BYTE ||
                    a.componentType == TINYGLTF_COMPONENT_TYPE_SHORT || a.normalized))
      fail(index, "indices must be unsigned byte, short or int");
    v.type = a.componentType;
    v.normalized = a.normalized;
    v.count = a.count;
    if (a.count == 0) return v;
    if (a.bufferView < 0 || static_cast<std::size_t>(a.bufferView) >= model.bufferViews.size())
      fail(index, "bufferView " + std::to_string(a.bufferView) + " does not exist");
    const tinygltf::BufferView& bv = model.bufferViews[a.bufferView];
    if (bv.buffer < 0 || static_cast<std::size_t>(bv.buffer) >= model.buffers.size())
      fail(index, "bufferView " + std::to_string(a.bufferView) + " names buffer " + std::to_string(bv.buffer) + ", which does not exist");
    const std::size_t buffer_size = model.buffers[bv.buffer].data.size();
    if (bv.byteOffset > buffer_size || bv.byteLength > buffer_size - bv.byteOffset)
      fail(index, "bufferView " + std::to_string(a.bufferView) + " (offset " + std::to_string(bv.byteOffset) + ", length " +
                      std::to_string(bv.byteLength) + ") exceeds buffer " + std::to_string(bv.buffer) + " (" + std::to_string(buffer_size) + " bytes)");
    const std::size_t elem = csize * static_cast<std::size_t>(v.comps);
    v.stride = bv.byteStride ? bv.byteStride : elem;
    if (v.stride < elem || v.stride > 252)
      fail(index, "byteStride " + std::to_string(v.stride) + " is invalid for " + std::to_string(elem) + "-byte elements");
    if (a.byteOffset > bv.byteLength || a.count > bv.byteLength ||
        v.stride * (a.count - 1) + elem > bv.byteLength - a.byteOffset)
      fail(index, "count " + std::to_string(a.count) + " with stride " + std::to_string(v.stride) + " at offset " +
                      std::to_string(a.byteOffset) + " exceeds bufferView " + std::to_string(a.bufferView) + " (" +
                      std::to_string(bv.byteLength) + " bytes)");
    v.base = model.buffers[bv.buffer].data.data() + bv.byteOffset + a.byteOffset;
    return v;
  }
};

struct Instance {
  const tinygltf::Primitive* prim;
  Mat4 world;
};

// Depth-first over the scene; a node reached twice (a cycle or a shared child) is skipped once.
void collect(const tinygltf::Model& model, const std::string& path, int node, const Mat4& parent,
             std::vector<char>& seen, std::vector<Instance>& out, ReadInfo& info) {
  if (node < 0 || static_cast<std::size_t>(node) >= model.nodes.size())
    throw IoError(path, "node " + std::to_string(node), "no such node");
  if (seen[node]) {
    info.notes.push_back("node " + std::to_string(node) + " reached twice (cycle or shared child); skipped");
    return;
  }
  seen[node] = 1;
  const tinygltf::Node& n = model.nodes[node];
  const Mat4 world = mul(parent, local_transform(n));
  if (n.mesh >= 0) {
    if (static_cast<std::size_t>(n.mesh) >= model.meshes.size())
      throw IoError(path, "node " + std::to_string(node), "mesh " + std::to_string(n.mesh) + " does not exist");
    for (const tinygltf::Primitive& p : model.meshes[n.mesh].primitives) out.push_back({&p, world});
  }
  for (int c : n.children) collect(model, path, c, world, seen, out, info);
}

int attribute(const tinygltf::Primitive& p, const std::string& name) {
  const auto it = p.attributes.find(name);
  return it == p.attributes.end() ? -1 : it->second;
}

void check_glb_layout(const std::string& path, const std::string& bytes) {
  ByteCursor cur(path, reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
  cur.need(12, "the GLB header");
  if (bytes.compare(0, 4, "glTF") != 0) throw IoError(path, byte_at(0), "not a GLB file (no 'glTF' magic)");
  cur.skip(4, "magic");
  const auto version = cur.read<std::uint32_t>(false, "the version");
  if (version != 2) throw IoError(path, byte_at(4), "GLB version " + std::to_string(version) + " (only 2 is supported)");
  const auto length = cur.read<std::uint32_t>(false, "the length");
  if (length > bytes.size())
    throw IoError(path, byte_at(bytes.size()), "truncated: GLB header declares " + std::to_string(length) + " bytes, file has " + std::to_string(bytes.size()));
  const auto json_len = cur.read<std::uint32_t>(false, "the JSON chunk length");
  const auto json_type = cur.read<std::uint32_t>(false, "the JSON chunk type");
  if (json_type != 0x4E4F534Au) throw IoError(path, byte_at(16), "first GLB chunk is not JSON");
  if (20ull + json_len > length)
    throw IoError(path, byte_at(20), "truncated: JSON chunk of " + std::to_string(json_len) + " bytes exceeds the GLB length " + std::to_string(length));
  if (20ull + json_len + 8 <= length) {   // a BIN chunk follows
    ByteCursor bin(path, reinterpret_cast<const std::uint8_t*>(bytes.data()), length, 20 + json_len);
    const auto bin_len = bin.read<std::uint32_t>(false, "the BIN chunk length");
    if (28ull + json_len + bin_len > length)
      throw IoError(path, byte_at(20 + json_len), "truncated: BIN chunk of " + std::to_string(bin_len) + " bytes exceeds the GLB length " + std::to_string(length));
  }
}

}  // namespace

ReadResult read_gltf(const std::string& path, const std::string& bytes, bool binary) {
  ReadResult r;
  r.info.format = binary ? Format::glb : Format::gltf;
  r.info.binary = binary;
  if (binary) check_glb_layout(path, bytes);
  if (bytes.size() >= 0xFFFFFFFFu) throw IoError(path, "", "glTF files of 4 GiB or more are not supported");

  tinygltf::Model model;
  {
    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(&skip_image, nullptr);
    loader.SetFsCallbacks({&regular_file, &same_path, &read_file, &no_write, nullptr});
    std::string err, warn, base_dir = ".";
    const std::size_t slash = path.find_last_of('/');
    if (slash != std::string::npos) base_dir = path.substr(0, slash == 0 ? 1 : slash);
    bool ok = false;
    try {
      ok = binary ? loader.LoadBinaryFromMemory(&model, &err, &warn, reinterpret_cast<const unsigned char*>(bytes.data()),
                                                static_cast<unsigned int>(bytes.size()), base_dir)
                  : loader.LoadASCIIFromString(&model, &err, &warn, bytes.data(), static_cast<unsigned int>(bytes.size()), base_dir);
    } catch (const std::exception& e) {
      err = e.what();
      ok = false;
    }
    if (!ok) {
      while (!err.empty() && (err.back() == '\n' || err.back() == ' ')) err.pop_back();
      throw IoError(path, "", "glTF: " + (err.empty() ? std::string("cannot parse") : err.substr(0, 300)));
    }
  }

  // Which primitives are drawn, with their world transforms.
  std::vector<Instance> instances;
  std::vector<char> seen(model.nodes.size(), 0);
  std::vector<int> roots;
  if (model.defaultScene >= 0 && static_cast<std::size_t>(model.defaultScene) < model.scenes.size()) {
    roots = model.scenes[model.defaultScene].nodes;
  } else if (!model.scenes.empty()) {
    roots = model.scenes[0].nodes;
  } else {
    std::vector<char> is_child(model.nodes.size(), 0);
    for (const auto& n : model.nodes)
      for (int c : n.children)
        if (c >= 0 && static_cast<std::size_t>(c) < model.nodes.size()) is_child[c] = 1;
    for (std::size_t i = 0; i < model.nodes.size(); ++i)
      if (!is_child[i]) roots.push_back(static_cast<int>(i));
  }
  for (int n : roots) collect(model, path, n, kIdentity, seen, instances, r.info);
  if (model.nodes.empty() && !model.meshes.empty()) {
    r.info.notes.push_back("no nodes: every mesh read untransformed");
    for (const auto& mesh : model.meshes)
      for (const auto& p : mesh.primitives) instances.push_back({&p, kIdentity});
  }

  bool any_triangles = false;
  for (const Instance& in : instances)
    any_triangles |= in.prim->mode == TINYGLTF_MODE_TRIANGLES || in.prim->mode == TINYGLTF_MODE_TRIANGLE_STRIP ||
                     in.prim->mode == TINYGLTF_MODE_TRIANGLE_FAN;
  const int wanted_points = any_triangles ? -1 : TINYGLTF_MODE_POINTS;
  std::vector<Instance> used;
  std::map<int, std::size_t> skipped_modes;
  std::size_t no_position = 0;
  for (const Instance& in : instances) {
    const int mode = in.prim->mode;
    const bool take = any_triangles ? (mode >= TINYGLTF_MODE_TRIANGLES && mode <= TINYGLTF_MODE_TRIANGLE_FAN) : mode == wanted_points;
    if (!take) {
      ++skipped_modes[mode];
    } else if (attribute(*in.prim, "POSITION") < 0) {
      ++no_position;
    } else {
      used.push_back(in);
    }
  }
  for (const auto& [mode, count] : skipped_modes)
    r.info.notes.push_back("skipped " + std::to_string(count) + " primitive(s) of mode " + std::to_string(mode));
  if (no_position) r.info.notes.push_back("skipped " + std::to_string(no_position) + " primitive(s) without POSITION");

  // Optional per-vertex data is kept only when every used primitive has it.
  auto on_all = [&](const std::string& name) {
    return !used.empty() && std::all_of(used.begin(), used.end(), [&](const Instance& in) { return attribute(*in.prim, name) >= 0; });
  };
  const bool normals = on_all("NORMAL"), colors = on_all("COLOR_0");
  std::vector<std::string> customs;
  if (!used.empty())
    for (const auto& [name, acc] : used.front().prim->attributes)
      if (!name.empty() && name[0] == '_') {
        if (on_all(name)) customs.push_back(name);
        else r.info.notes.push_back("attribute " + name + " dropped: not on every primitive");
      }
  for (const std::string& c : customs) r.attributes.scalars.push_back({c.substr(1), {}});

  const Reader rd{path, model};
  TriangleMesh& m = r.mesh;
  for (const Instance& in : used) {
    const tinygltf::Primitive& p = *in.prim;
    const int pos_acc = attribute(p, "POSITION");
    const View pos = rd.view(pos_acc, {3}, false);
    const std::size_t base = m.positions.size();
    if (base + pos.count >= kInvalidIndex) rd.fail(pos_acc, "too many vertices for 32-bit indices");
    for (std::size_t i = 0; i < pos.count; ++i) {
      const Vec3 q = apply_point(in.world, {pos.get(i, 0), pos.get(i, 1), pos.get(i, 2)});
      if (!is_finite(q)) rd.fail(pos_acc, "vertex " + std::to_string(i) + " (vertex " + std::to_string(m.positions.size()) + " of the mesh) is not finite");
      m.positions.push_back(q);
    }
    if (normals) {
      const int acc = attribute(p, "NORMAL");
      const View nv = rd.view(acc, {3}, false);
      if (nv.count != pos.count) rd.fail(acc, "NORMAL count " + std::to_string(nv.count) + " differs from POSITION count " + std::to_string(pos.count));
      for (std::size_t i = 0; i < nv.count; ++i) m.normals.push_back(apply_normal(in.world, {nv.get(i, 0), nv.get(i, 1), nv.get(i, 2)}));
    }
    if (colors) {
      const int acc = attribute(p, "COLOR_0");
      const View cv = rd.view(acc, {3, 4}, false);
      if (cv.count != pos.count) rd.fail(acc, "COLOR_0 count differs from POSITION count");
      const bool unit = cv.normalized || cv.type == TINYGLTF_COMPONENT_TYPE_FLOAT;
      for (std::size_t i = 0; i < cv.count; ++i) {
        std::array<std::uint8_t, 4> c = {0, 0, 0, 255};
        for (int k = 0; k < cv.comps; ++k) {
          const double x = unit ? cv.get(i, k) * 255.0 : cv.get(i, k);
          c[k] = static_cast<std::uint8_t>(std::isfinite(x) ? std::lround(std::clamp(x, 0.0, 255.0)) : 0);
        }
        r.attributes.colors.push_back(c);
      }
    }
    for (std::size_t k = 0; k < customs.size(); ++k) {
      const int acc = attribute(p, customs[k]);
      const View av = rd.view(acc, {1}, false);
      if (av.count != pos.count) rd.fail(acc, customs[k] + " count differs from POSITION count");
      for (std::size_t i = 0; i < av.count; ++i) r.attributes.scalars[k].second.push_back(static_cast<float>(av.get(i, 0)));
    }

    if (p.mode == TINYGLTF_MODE_POINTS) continue;
    // Corner list: the indices, or 0..n-1 for a non-indexed primitive.
    std::vector<Index> idx;
    const int idx_acc = p.indices >= 0 ? p.indices : pos_acc;
    if (p.indices >= 0) {
      const View iv = rd.view(p.indices, {1}, true);
      idx.reserve(iv.count);
      for (std::size_t i = 0; i < iv.count; ++i) {
        const double v = iv.get(i, 0);
        if (v >= static_cast<double>(pos.count))
          rd.fail(p.indices, "index " + std::to_string(static_cast<std::uint64_t>(v)) + " at element " + std::to_string(i) +
                                 " out of range (" + std::to_string(pos.count) + " vertices)");
        idx.push_back(static_cast<Index>(base + static_cast<std::size_t>(v)));
      }
    } else {
      idx.resize(pos.count);
      for (std::size_t i = 0; i < pos.count; ++i) idx[i] = static_cast<Index>(base + i);
    }
    const std::size_t n = idx.size();
    if (p.mode == TINYGLTF_MODE_TRIANGLES) {
      if (n % 3 != 0) rd.fail(idx_acc, std::to_string(n) + " corners is not a multiple of 3 for TRIANGLES");
      for (std::size_t i = 0; i + 2 < n; i += 3) m.triangles.push_back({idx[i], idx[i + 1], idx[i + 2]});
    } else if (p.mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
      // Alternate the winding so every triangle keeps the strip's orientation.
      for (std::size_t i = 0; i + 2 < n; ++i)
        m.triangles.push_back(i % 2 == 0 ? Triangle{idx[i], idx[i + 1], idx[i + 2]} : Triangle{idx[i + 1], idx[i], idx[i + 2]});
    } else {
      for (std::size_t i = 1; i + 1 < n; ++i) m.triangles.push_back({idx[0], idx[i], idx[i + 1]});
    }
  }
  r.info.file_vertices = m.positions.size();
  r.info.file_faces = m.triangles.size();
  r.info.has_normals = normals && !m.normals.empty();
  if (!r.info.has_normals) m.normals.clear();
  if (m.positions.empty() && instances.empty()) r.info.notes.push_back("the scene draws no mesh");
  return r;
}

}  // namespace gsp::io::detail
