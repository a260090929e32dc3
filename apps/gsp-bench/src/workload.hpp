#pragma once
// What is benchmarked: the meshes, the random source vertices of each (seeded, the same for
// every method), and the (mesh, source) work items a shard takes.
#include <gsp/cli/load.hpp>
#include <gsp/mesh.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace gsp::bench {

struct BenchMesh {
  std::string path;
  std::string name;             // file name, as in the reports
  TriangleMesh mesh;            // welded where the format needs it (gsp::cli::load_mesh)
  std::uint64_t hash = 0;       // content hash of `mesh` (the exact cache's key)
  std::vector<Index> sources;   // all picks, before sharding
};

// Loads (gsp::cli::load_mesh; throws gsp::IoError for a bad file) and picks the sources.
// `subdivide` > 0: Loop-subdivided that many times (subdivide.hpp), named "<file>@loop<K>",
// or split at the edge midpoints with `midpoint`, named "<file>@mid<K>".
BenchMesh load_bench_mesh(const std::string& path, const cli::LoadOptions& load, int sources, std::uint64_t seed,
                          int subdivide = 0, bool midpoint = false);

// --shard i/n: work items k with k % n == i.
struct Shard {
  std::size_t index = 0, count = 1;
};
Shard parse_shard(const std::string& text);   // UsageError unless "i/n" with 0 <= i < n

// A (mesh, source) pair; `index` numbers all pairs of all meshes in order (mesh by mesh,
// sources in pick order), before sharding.
struct WorkItem {
  std::size_t index = 0;
  std::size_t mesh = 0;
  Index source = 0;
};
std::vector<WorkItem> work_items(const std::vector<BenchMesh>& meshes, Shard shard);
std::size_t total_work_items(const std::vector<BenchMesh>& meshes);

}  // namespace gsp::bench
