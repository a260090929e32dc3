#include "workload.hpp"

#include <gsp/reference/exact_cache.hpp>
#include "subdivide.hpp"

#include <gsp/cli/app.hpp>

#include <charconv>
#include <filesystem>
#include <string>

namespace gsp::bench {

BenchMesh load_bench_mesh(const std::string& path, const cli::LoadOptions& load, int sources, std::uint64_t seed,
                          int subdivide, bool midpoint) {
  cli::LoadedMesh in = cli::load_mesh(path, load);
  BenchMesh m;
  m.path = path;
  m.name = std::filesystem::path(path).filename().string();
  m.mesh = std::move(in.mesh);
  if (subdivide > 0) {
    m.mesh = midpoint ? midpoint_subdivide(m.mesh, subdivide) : loop_subdivide(m.mesh, subdivide);
    m.name += (midpoint ? "@mid" : "@loop") + std::to_string(subdivide);
  }
  m.hash = reference::mesh_hash(m.mesh);
  m.sources = reference::pick_sources(m.mesh, sources, seed, m.hash);
  return m;
}

Shard parse_shard(const std::string& text) {
  const auto fail = [&] {
    return cli::UsageError("--shard: \"" + text + "\" is not i/n with integers 0 <= i < n");
  };
  const auto slash = text.find('/');
  if (slash == std::string::npos) throw fail();
  Shard s;
  const char* b = text.data();
  const char* e = b + text.size();
  auto r1 = std::from_chars(b, b + slash, s.index);
  auto r2 = std::from_chars(b + slash + 1, e, s.count);
  if (r1.ec != std::errc() || r1.ptr != b + slash || r2.ec != std::errc() || r2.ptr != e || slash == 0 ||
      s.count == 0 || s.index >= s.count)
    throw fail();
  return s;
}

std::vector<WorkItem> work_items(const std::vector<BenchMesh>& meshes, Shard shard) {
  std::vector<WorkItem> out;
  std::size_t k = 0;
  for (std::size_t m = 0; m < meshes.size(); ++m)
    for (Index s : meshes[m].sources) {
      if (k % shard.count == shard.index) out.push_back({k, m, s});
      ++k;
    }
  return out;
}

std::size_t total_work_items(const std::vector<BenchMesh>& meshes) {
  std::size_t n = 0;
  for (const BenchMesh& m : meshes) n += m.sources.size();
  return n;
}

}  // namespace gsp::bench
