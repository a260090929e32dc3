// libFuzzer target: arbitrary bytes as a .gltf file through gsp::io::read_mesh.
#include "fuzz_common.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return gsp::fuzz::read_as(".gltf", data, size);
}
