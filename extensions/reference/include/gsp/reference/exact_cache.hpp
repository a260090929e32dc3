#pragma once
// Exact distances cached on disk. CGAL needs about a second per source on a 15k-vertex mesh
// (ten or more on 35k), while gsp-train-heuristic evaluates thousands of heuristics and
// gsp-bench runs the corpus again and again against the same references: compute them once,
// keyed by the mesh's content and the source vertex, so a renamed or re-welded file never
// reuses stale values. One cache for both apps (the same folder serves either).
#include <gsp/mesh.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace gsp::reference {

// FNV-1a over the bytes of positions and triangles (the mesh the distances were computed on).
std::uint64_t mesh_hash(const TriangleMesh& mesh);

// The random source vertices gsp-bench and gsp-train-heuristic measure a mesh from: vertices
// of a non-degenerate face, `count` of them (fewer if the mesh has fewer), drawn without
// replacement by a partial Fisher-Yates shuffle driven by mt19937_64(seed ^ hash), with `hash`
// the mesh's mesh_hash(). mt19937_64's output is fixed by the standard, so the picks are the
// same on every platform and in both apps, which is what lets them share cache entries.
std::vector<Index> pick_sources(const TriangleMesh& mesh, int count, std::uint64_t seed, std::uint64_t hash);

class ExactCache {
 public:
  explicit ExactCache(std::string dir);   // "" disables the cache; the folder is created on demand
  bool enabled() const { return !dir_.empty(); }

  // The cached distances, or nothing when absent or not matching `num_vertices`.
  std::optional<std::vector<double>> load(std::uint64_t hash, Index source, std::size_t num_vertices) const;
  // Written atomically (temporary file + rename); throws gsp::IoError when it cannot write.
  void store(std::uint64_t hash, Index source, const std::vector<double>& distances) const;

 private:
  std::string path(std::uint64_t hash, Index source) const;
  std::string dir_;
};

}  // namespace gsp::reference
