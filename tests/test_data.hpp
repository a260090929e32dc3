#pragma once
// Where the tests find their meshes: the shared set (GSP_DATA_DIR, overridable by the
// environment variable of the same name) and the small files bundled in tests/data.
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

namespace gsp::test {

inline std::string data_dir() {
  if (const char* env = std::getenv("GSP_DATA_DIR")) return env;
  return GSP_DATA_DIR;
}
inline std::string shared_mesh(const std::string& name) { return data_dir() + "/" + name; }
inline std::string bundled(const std::string& name) { return std::string(GSP_TEST_DIR) + "/data/" + name; }
inline bool have_shared_data() { return std::filesystem::exists(shared_mesh("SOURCES.md")); }

// Every mesh file of a folder (not point clouds), sorted; none if the folder is missing.
inline std::vector<std::string> mesh_files(const std::string& folder) {
  std::vector<std::string> files;
  if (!std::filesystem::is_directory(folder)) return files;
  for (const auto& e : std::filesystem::directory_iterator(folder)) {
    const std::string ext = e.path().extension().string();
    if (ext == ".obj" || ext == ".off" || ext == ".ply" || ext == ".stl" || ext == ".gltf" || ext == ".glb")
      files.push_back(e.path().string());
  }
  std::sort(files.begin(), files.end());
  return files;
}

// The shared meshes and the corpus beside them (docs/benchmarks.md, "Corpus").
inline std::vector<std::string> shared_and_corpus_files() {
  std::vector<std::string> files = mesh_files(data_dir());
  const std::vector<std::string> corpus = mesh_files(data_dir() + "/../corpus");
  files.insert(files.end(), corpus.begin(), corpus.end());
  return files;
}

}  // namespace gsp::test
