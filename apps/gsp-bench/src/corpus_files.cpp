#include "corpus_files.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>

namespace gsp::bench {

namespace fs = std::filesystem;

bool is_mesh_file(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  for (const char* known : {".obj", ".off", ".ply", ".stl", ".gltf", ".glb"})
    if (ext == known) return true;
  return false;
}

std::vector<std::string> corpus_files(const std::vector<std::string>& paths) {
  std::vector<std::string> out;
  for (const std::string& path : paths) {
    std::error_code ec;
    if (!fs::is_directory(path, ec)) {
      out.push_back(path);
      continue;
    }
    std::vector<std::string> in_folder;
    for (const fs::directory_entry& e : fs::directory_iterator(path))
      if (e.is_regular_file(ec) && is_mesh_file(e.path().string())) in_folder.push_back(e.path().string());
    std::sort(in_folder.begin(), in_folder.end());
    out.insert(out.end(), in_folder.begin(), in_folder.end());
  }
  return out;
}

}  // namespace gsp::bench
