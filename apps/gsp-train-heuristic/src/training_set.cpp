#include "training_set.hpp"

#include <gsp/cli/load.hpp>
#include <gsp/errors.hpp>
#include <gsp/reference/exact_cache.hpp>
#include <gsp/reference/exact_geodesics.hpp>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>

namespace gsp::train {

TrainingMesh prepare_mesh(const std::string& path, int num_sources, std::uint64_t seed,
                          const reference::ExactCache& cache, const NoteFn& note) {
  cli::LoadOptions load;   // automatic: weld the formats that split vertices
  cli::LoadedMesh in = cli::load_mesh(path, load);
  TrainingMesh out;
  out.name = std::filesystem::path(path).filename().string();
  out.mesh = std::move(in.mesh);
  const std::uint64_t hash = reference::mesh_hash(out.mesh);
  out.sources = reference::pick_sources(out.mesh, num_sources, seed, hash);
  std::unique_ptr<reference::ExactGeodesicSolver> exact;   // built only on a cache miss
  for (Index s : out.sources) {
    if (auto d = cache.load(hash, s, out.mesh.num_vertices())) {
      out.exact.push_back(std::move(*d));
      continue;
    }
    if (!exact) exact = std::make_unique<reference::ExactGeodesicSolver>(out.mesh);   // may throw TopologyError
    const auto t0 = std::chrono::steady_clock::now();
    out.exact.push_back(exact->distances_from_vertex(s));
    const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    cache.store(hash, s, out.exact.back());
    char line[256];
    std::snprintf(line, sizeof line, "%s: exact distances from vertex %u (%.1f s)", out.name.c_str(), s, secs);
    note(line);
  }
  // Cached distances are no proof that CGAL accepts the mesh today; that was checked when they
  // were written (the key is the mesh content).
  return out;
}

}  // namespace gsp::train
