#pragma once
// Where the tests find their meshes: the shared set (GSP_DATA_DIR, overridable by the
// environment variable of the same name) and the small files bundled in tests/data.
#include <cstdlib>
#include <filesystem>
#include <string>

namespace gsp::test {

inline std::string data_dir() {
  if (const char* env = std::getenv("GSP_DATA_DIR")) return env;
  return GSP_DATA_DIR;
}
inline std::string shared_mesh(const std::string& name) { return data_dir() + "/" + name; }
inline std::string bundled(const std::string& name) { return std::string(GSP_TEST_DIR) + "/data/" + name; }
inline bool have_shared_data() { return std::filesystem::exists(shared_mesh("SOURCES.md")); }

}  // namespace gsp::test
