#pragma once
// Points of a face bucketed into cubes of one size, for the faces of Poisson-disk sampling
// that hold many samples (a CAD part's large flat faces, a single triangle): a scan of every
// point of such a face per candidate makes the sampling quadratic in the count.
#include <gsp/mesh.hpp>

#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace gsp::sampling::detail {

class FaceCells {
 public:
  // Cubes a little larger than `reach`, so that a point within `reach` of p lies in one of
  // the 27 cubes around p's whatever the rounding of the division.
  explicit FaceCells(double reach) : inverse_(1.0 / (reach * (1 + 1e-9))) {}

  void add(Index face, Vec3 p, std::int32_t item) { cells_[key(face, p, 0, 0, 0)].push_back(item); }

  // Calls visit(item) for every item of `face` within `reach` of p (and some farther ones).
  template <class Visit>
  void near(Index face, Vec3 p, Visit&& visit) const {
    for (int dz = -1; dz <= 1; ++dz)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const auto it = cells_.find(key(face, p, dx, dy, dz));
          if (it == cells_.end()) continue;
          for (std::int32_t item : it->second) visit(item);
        }
  }

 private:
  struct Key {
    Index face;
    std::int64_t x, y, z;
    bool operator==(const Key& o) const { return face == o.face && x == o.x && y == o.y && z == o.z; }
  };
  struct Hash {
    std::size_t operator()(const Key& k) const {
      std::uint64_t h = k.face * 0x9e3779b97f4a7c15ULL;
      h ^= std::uint64_t(k.x) * 0xc2b2ae3d27d4eb4fULL + (h << 6) + (h >> 2);
      h ^= std::uint64_t(k.y) * 0x165667b19e3779f9ULL + (h << 6) + (h >> 2);
      h ^= std::uint64_t(k.z) * 0x27d4eb2f165667c5ULL + (h << 6) + (h >> 2);
      return std::size_t(h);
    }
  };
  // Clamped: a far virtual source (or a non-finite one) must not overflow the conversion.
  std::int64_t cell(double c) const {
    const double q = std::floor(c * inverse_);
    return q >= 1e15 ? std::int64_t(1e15) : (q > -1e15 ? std::int64_t(q) : std::int64_t(-1e15));
  }
  Key key(Index face, Vec3 p, int dx, int dy, int dz) const {
    return {face, cell(p.x) + dx, cell(p.y) + dy, cell(p.z) + dz};
  }
  double inverse_;
  std::unordered_map<Key, std::vector<std::int32_t>, Hash> cells_;
};

}  // namespace gsp::sampling::detail
