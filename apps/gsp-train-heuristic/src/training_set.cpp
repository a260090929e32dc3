#include "training_set.hpp"

#include <gsp/cli/load.hpp>
#include <gsp/errors.hpp>
#include <gsp/reference/exact_geodesics.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <random>

namespace gsp::train {

namespace {

std::vector<Index> pick_sources(const TriangleMesh& mesh, int count, std::uint64_t seed) {
  std::vector<std::uint8_t> used(mesh.num_vertices(), 0);
  for (const Triangle& t : mesh.triangles)
    if (t[0] != t[1] && t[1] != t[2] && t[2] != t[0]) used[t[0]] = used[t[1]] = used[t[2]] = 1;
  std::vector<Index> candidates;
  for (Index v = 0; v < mesh.num_vertices(); ++v)
    if (used[v]) candidates.push_back(v);
  // mt19937_64's output is fixed by the standard (unlike the distributions), so the picks are
  // the same on every platform.
  std::mt19937_64 rng(seed ^ reference::mesh_hash(mesh));
  std::vector<Index> out;
  const std::size_t n = std::min<std::size_t>(std::size_t(std::max(count, 0)), candidates.size());
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = i + rng() % (candidates.size() - i);   // partial Fisher-Yates
    std::swap(candidates[i], candidates[j]);
    out.push_back(candidates[i]);
  }
  return out;
}

}  // namespace

TrainingMesh prepare_mesh(const std::string& path, int num_sources, std::uint64_t seed,
                          const reference::ExactCache& cache, const NoteFn& note) {
  cli::LoadOptions load;   // automatic: weld the formats that split vertices
  cli::LoadedMesh in = cli::load_mesh(path, load);
  TrainingMesh out;
  out.name = std::filesystem::path(path).filename().string();
  out.mesh = std::move(in.mesh);
  out.sources = pick_sources(out.mesh, num_sources, seed);
  const std::uint64_t hash = reference::mesh_hash(out.mesh);
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
