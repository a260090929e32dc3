#pragma once
// A training (or validation) mesh: the mesh GSP and CGAL both run on, random source vertices
// and the exact distances from each of them.
#include <gsp/reference/exact_cache.hpp>

#include <gsp/mesh.hpp>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace gsp::train {

struct TrainingMesh {
  std::string name;                         // file name without folder
  TriangleMesh mesh;                        // welded where the format splits vertices
  std::vector<Index> sources;               // vertex indices of `mesh`
  std::vector<std::vector<double>> exact;   // per source, per vertex (+inf where unreachable)
};

using NoteFn = std::function<void(const std::string&)>;

// Reads `path` (welding STL/glTF by position), picks `num_sources` distinct vertices that
// belong to a face (deterministic for a given seed and mesh content) and fetches their exact
// distances from `cache`, computing the missing ones with CGAL. Throws gsp::IoError for an
// unreadable file and gsp::TopologyError when CGAL cannot handle the mesh (non-manifold,
// degenerate faces).
TrainingMesh prepare_mesh(const std::string& path, int num_sources, std::uint64_t seed,
                          const reference::ExactCache& cache, const NoteFn& note);

}  // namespace gsp::train
