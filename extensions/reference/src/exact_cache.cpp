#include <gsp/reference/exact_cache.hpp>

#include <gsp/errors.hpp>
#include <gsp/io/atomic_file.hpp>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <random>

namespace gsp::reference {

namespace {

constexpr char kMagic[8] = {'G', 'S', 'P', 'E', 'X', 'A', 'C', '1'};

void fnv(std::uint64_t& h, const void* data, std::size_t bytes) {
  const auto* p = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < bytes; ++i) h = (h ^ p[i]) * 1099511628211ull;
}

}  // namespace

std::uint64_t mesh_hash(const TriangleMesh& mesh) {
  std::uint64_t h = 14695981039346656037ull;
  const std::uint64_t counts[2] = {mesh.num_vertices(), mesh.num_faces()};
  fnv(h, counts, sizeof counts);
  for (const Vec3& p : mesh.positions) fnv(h, &p, sizeof p);
  for (const Triangle& t : mesh.triangles) fnv(h, t.data(), sizeof(Index) * 3);
  return h;
}

std::vector<Index> pick_sources(const TriangleMesh& mesh, int count, std::uint64_t seed, std::uint64_t hash) {
  std::vector<std::uint8_t> used(mesh.num_vertices(), 0);
  for (const Triangle& t : mesh.triangles)
    if (t[0] != t[1] && t[1] != t[2] && t[2] != t[0]) used[t[0]] = used[t[1]] = used[t[2]] = 1;
  std::vector<Index> candidates;
  for (Index v = 0; v < mesh.num_vertices(); ++v)
    if (used[v]) candidates.push_back(v);
  std::mt19937_64 rng(seed ^ hash);
  const std::size_t n = std::min<std::size_t>(std::size_t(std::max(count, 0)), candidates.size());
  std::vector<Index> picks;
  for (std::size_t i = 0; i < n; ++i) {
    std::swap(candidates[i], candidates[i + rng() % (candidates.size() - i)]);
    picks.push_back(candidates[i]);
  }
  return picks;
}

ExactCache::ExactCache(std::string dir) : dir_(std::move(dir)) {}

std::string ExactCache::path(std::uint64_t hash, Index source) const {
  char name[64];
  std::snprintf(name, sizeof name, "%016llx_%u.bin", static_cast<unsigned long long>(hash), source);
  return (std::filesystem::path(dir_) / name).string();
}

std::optional<std::vector<double>> ExactCache::load(std::uint64_t hash, Index source,
                                                    std::size_t num_vertices) const {
  if (!enabled()) return std::nullopt;
  std::FILE* f = std::fopen(path(hash, source).c_str(), "rb");
  if (!f) return std::nullopt;
  char magic[8];
  std::uint64_t n = 0;
  std::vector<double> d;
  bool ok = std::fread(magic, 1, 8, f) == 8 && std::memcmp(magic, kMagic, 8) == 0 &&
            std::fread(&n, sizeof n, 1, f) == 1 && n == num_vertices;
  if (ok) {
    d.resize(n);
    ok = std::fread(d.data(), sizeof(double), n, f) == n;
  }
  std::fclose(f);
  if (!ok) return std::nullopt;   // a foreign or truncated file: recompute (and overwrite)
  return d;
}

void ExactCache::store(std::uint64_t hash, Index source, const std::vector<double>& distances) const {
  if (!enabled()) return;
  std::error_code ec;
  std::filesystem::create_directories(dir_, ec);
  if (ec) throw IoError(dir_, "", "cannot create the cache folder: " + ec.message());
  io::AtomicFile out(path(hash, source));
  const std::uint64_t n = distances.size();
  out.write(kMagic, 8);
  out.write(&n, sizeof n);
  out.write(distances.data(), n * sizeof(double));
  out.commit();
}

}  // namespace gsp::reference
