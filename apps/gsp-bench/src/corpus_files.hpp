#pragma once
// The files of a corpus run: every mesh file of each folder given (not recursive, sorted by
// name, so two runs list the same meshes in the same order) and each file given as is.
#include <string>
#include <vector>

namespace gsp::bench {

// True for the extensions gsp-bench reads (.obj .off .ply .stl .gltf .glb, any case).
bool is_mesh_file(const std::string& path);

// Folders expanded, files kept in the order given (a missing path is kept too: it becomes
// a failed row when it cannot be loaded, like any other bad file).
std::vector<std::string> corpus_files(const std::vector<std::string>& paths);

}  // namespace gsp::bench
