#pragma once
// Assembling a glTF model in memory (tinygltf): one buffer, a view and an accessor per array.
// Shared by the mesh writer and the polyline writer.
#include <tiny_gltf.h>

#include <string>
#include <vector>

namespace gsp::io::detail {

struct Builder {
  tinygltf::Model model;
  std::vector<unsigned char>& data() { return model.buffers[0].data; }

  // Appends raw bytes as a new buffer view (4-byte aligned) and an accessor over it.
  int add(const void* bytes, std::size_t size, std::size_t count, int component, int type, bool normalized, int target) {
    auto& d = data();
    while (d.size() % 4) d.push_back(0);
    tinygltf::BufferView bv;
    bv.buffer = 0;
    bv.byteOffset = d.size();
    bv.byteLength = size;
    bv.target = target;
    const auto* p = static_cast<const unsigned char*>(bytes);
    d.insert(d.end(), p, p + size);
    model.bufferViews.push_back(bv);
    tinygltf::Accessor a;
    a.bufferView = static_cast<int>(model.bufferViews.size() - 1);
    a.byteOffset = 0;
    a.componentType = component;
    a.count = count;
    a.type = type;
    a.normalized = normalized;
    model.accessors.push_back(a);
    return static_cast<int>(model.accessors.size() - 1);
  }
  int add_floats(const std::vector<float>& v, int type, std::size_t count) {
    return add(v.data(), v.size() * sizeof(float), count, TINYGLTF_COMPONENT_TYPE_FLOAT, type, false, TINYGLTF_TARGET_ARRAY_BUFFER);
  }
};


// Serialises the model (.glb when binary, else .gltf with the buffer as base64) and writes it
// atomically; throws IoError.
void save_gltf(const std::string& path, tinygltf::Model& model, bool binary);

}  // namespace gsp::io::detail
