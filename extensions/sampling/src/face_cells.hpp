#pragma once
// Points of a face bucketed into cubes of one size, for the faces of Poisson-disk sampling
// that hold many samples (a CAD part's large flat faces, a single triangle): a scan of every
// point of such a face per candidate makes the sampling quadratic in the count.
#include <gsp/mesh.hpp>

#include <cmath>
#include <cstdint>
#include <vector>

namespace gsp::sampling::detail {

class FaceCells {
 public:
  // Cubes a little larger than `reach`, so that a point within `reach` of p lies in one of
  // the 27 cubes around p's whatever the rounding of the division.
  explicit FaceCells(double reach) : inverse_(1.0 / (reach * (1 + 1e-9))), table_(1024) {}

  // Items are small non-negative ids (indices into the caller's arrays), each added once.
  void add(Index face, Vec3 p, std::int32_t item) {
    if (2 * (used_ + 1) > table_.size()) grow();
    const Key k = key(face, p, 0, 0, 0);
    Slot& s = table_[find(k)];
    if (!s.used) s.used = true, s.key = k, ++used_;
    if (std::size_t(item) >= next_.size()) next_.resize(std::size_t(item) + 1, -1);
    next_[std::size_t(item)] = s.head;
    s.head = item;
  }

  // Calls visit(item) for every item of `face` within `reach` of p (and some farther ones).
  template <class Visit>
  void near(Index face, Vec3 p, Visit&& visit) const {
    for (int dz = -1; dz <= 1; ++dz)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const Slot& s = table_[find(key(face, p, dx, dy, dz))];
          for (std::int32_t i = s.used ? s.head : -1; i >= 0; i = next_[std::size_t(i)]) visit(i);
        }
  }

 private:
  struct Key {
    Index face;
    std::int64_t x, y, z;
    bool operator==(const Key& o) const { return face == o.face && x == o.x && y == o.y && z == o.z; }
  };
  // Open addressing, linear probing; a cube's items are a list through next_ (no allocation per
  // cube: the first version kept a vector per cube in an unordered_map, and on a mesh whose
  // every face holds dozens of sources the inserts took a third of the run).
  struct Slot {
    Key key{};
    std::int32_t head = -1;
    bool used = false;
  };
  static std::size_t hash(const Key& k) {
    std::uint64_t h = k.face * 0x9e3779b97f4a7c15ULL;
    h ^= std::uint64_t(k.x) * 0xc2b2ae3d27d4eb4fULL + (h << 6) + (h >> 2);
    h ^= std::uint64_t(k.y) * 0x165667b19e3779f9ULL + (h << 6) + (h >> 2);
    h ^= std::uint64_t(k.z) * 0x27d4eb2f165667c5ULL + (h << 6) + (h >> 2);
    return std::size_t(h ^ (h >> 29));
  }
  // The slot holding k, or the empty slot where it would go.
  std::size_t find(const Key& k) const {
    const std::size_t mask = table_.size() - 1;
    std::size_t i = hash(k) & mask;
    while (table_[i].used && !(table_[i].key == k)) i = (i + 1) & mask;
    return i;
  }
  void grow() {
    std::vector<Slot> old(table_.size() * 2);
    old.swap(table_);
    for (const Slot& s : old)
      if (s.used) table_[find(s.key)] = s;
  }
  // Clamped: a far virtual source (or a non-finite one) must not overflow the conversion.
  std::int64_t cell(double c) const {
    const double q = std::floor(c * inverse_);
    return q >= 1e15 ? std::int64_t(1e15) : (q > -1e15 ? std::int64_t(q) : std::int64_t(-1e15));
  }
  Key key(Index face, Vec3 p, int dx, int dy, int dz) const {
    return {face, cell(p.x) + dx, cell(p.y) + dy, cell(p.z) + dz};
  }
  double inverse_;
  std::vector<Slot> table_;   // a power of two, at most half full
  std::size_t used_ = 0;
  std::vector<std::int32_t> next_;   // per item: the next item of its cube
};

}  // namespace gsp::sampling::detail
