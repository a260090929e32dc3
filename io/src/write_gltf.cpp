// glTF 2.0 writer (.gltf with the buffer embedded as base64, or .glb) through tinygltf: one
// node, one mesh, one primitive (TRIANGLES, or POINTS for a point cloud). POSITION carries the
// min/max the spec requires; NORMAL when present; indices as UNSIGNED_INT; each scalar or label
// attribute as `_NAME` (upper case, FLOAT SCALAR); colours as COLOR_0 (normalized UNSIGNED_BYTE
// VEC4). tinygltf serialises to memory and the bytes go through AtomicFile.
#include <gsp/io/atomic_file.hpp>

#include "gltf_builder.hpp"
#include "writers.hpp"

#include <tiny_gltf.h>

#include <algorithm>
#include <cctype>
#include <cstring>
#include <limits>
#include <sstream>

namespace gsp::io::detail {

namespace {

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

}  // namespace

void write_gltf(const std::string& path, const TriangleMesh& mesh, const VertexAttributes& attributes, bool binary) {
  Builder b;
  b.model.asset.version = "2.0";
  b.model.asset.generator = "gsp";
  b.model.buffers.emplace_back();
  const std::size_t n = mesh.num_vertices();

  tinygltf::Primitive prim;
  prim.mode = mesh.is_point_cloud() ? TINYGLTF_MODE_POINTS : TINYGLTF_MODE_TRIANGLES;
  if (n > 0) {
    std::vector<float> pos(3 * n);
    std::vector<double> lo(3, std::numeric_limits<double>::infinity()), hi(3, -std::numeric_limits<double>::infinity());
    for (std::size_t v = 0; v < n; ++v)
      for (int k = 0; k < 3; ++k) {
        pos[3 * v + k] = static_cast<float>(mesh.positions[v][k]);
        lo[k] = std::min(lo[k], double(pos[3 * v + k]));   // bounds of the stored (float) values
        hi[k] = std::max(hi[k], double(pos[3 * v + k]));
      }
    const int pa = b.add_floats(pos, TINYGLTF_TYPE_VEC3, n);
    b.model.accessors[pa].minValues = lo;
    b.model.accessors[pa].maxValues = hi;
    prim.attributes["POSITION"] = pa;
    if (!mesh.normals.empty()) {
      std::vector<float> nrm(3 * n);
      for (std::size_t v = 0; v < n; ++v)
        for (int k = 0; k < 3; ++k) nrm[3 * v + k] = static_cast<float>(mesh.normals[v][k]);
      prim.attributes["NORMAL"] = b.add_floats(nrm, TINYGLTF_TYPE_VEC3, n);
    }
    for (const auto& [name, values] : attributes.scalars) prim.attributes["_" + upper(name)] = b.add_floats(values, TINYGLTF_TYPE_SCALAR, n);
    for (const auto& [name, values] : attributes.labels) {
      std::vector<float> f(values.begin(), values.end());   // exact for |label| < 2^24
      prim.attributes["_" + upper(name)] = b.add_floats(f, TINYGLTF_TYPE_SCALAR, n);
    }
    if (!attributes.colors.empty())
      prim.attributes["COLOR_0"] = b.add(attributes.colors.data(), 4 * n, n, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
                                         TINYGLTF_TYPE_VEC4, true, TINYGLTF_TARGET_ARRAY_BUFFER);
    if (!mesh.is_point_cloud()) {
      std::vector<std::uint32_t> idx;
      idx.reserve(3 * mesh.num_faces());
      for (const Triangle& t : mesh.triangles) idx.insert(idx.end(), t.begin(), t.end());
      prim.indices = b.add(idx.data(), idx.size() * 4, idx.size(), TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT,
                           TINYGLTF_TYPE_SCALAR, false, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
    }
    tinygltf::Mesh m;
    m.primitives.push_back(prim);
    b.model.meshes.push_back(m);
  }
  while (b.data().size() % 4) b.data().push_back(0);
  if (b.data().empty()) b.model.buffers.clear();

  tinygltf::Node node;
  node.mesh = b.model.meshes.empty() ? -1 : 0;
  b.model.nodes.push_back(node);
  tinygltf::Scene scene;
  scene.nodes.push_back(0);
  b.model.scenes.push_back(scene);
  b.model.defaultScene = 0;

  save_gltf(path, b.model, binary);
}

void save_gltf(const std::string& path, tinygltf::Model& model, bool binary) {
  std::ostringstream stream;
  tinygltf::TinyGLTF writer;
  bool ok = false;
  try {
    ok = writer.WriteGltfSceneToStream(&model, stream, !binary, binary);
  } catch (const std::exception& e) {
    throw IoError(path, "", std::string("glTF serialisation failed: ") + e.what());
  }
  if (!ok) throw IoError(path, "", "glTF serialisation failed");
  const std::string bytes = stream.str();
  AtomicFile file(path);
  file.write(bytes.data(), bytes.size());
  file.commit();
}

}  // namespace gsp::io::detail
