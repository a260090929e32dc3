#pragma once
// Points hashed into cubes of side `cell`, for the points within a radius of a query (internal
// to gsp::cvt: the post-pass's surface checks look up the working mesh's vertices near a spot).
#include <gsp/types.hpp>

#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace gsp::cvt::detail {

class PointGrid {
 public:
  PointGrid(const std::vector<Vec3>& points, double cell) : points_(points), cell_(cell > 0 ? cell : 1.0) {
    for (Index i = 0; i < points.size(); ++i) cells_[cell_key(points[i])].push_back(i);
  }
  template <class Fn>
  void near(Vec3 p, double r, Fn&& fn) const {
    const long long x0 = coord(p.x - r), x1 = coord(p.x + r), y0 = coord(p.y - r), y1 = coord(p.y + r),
                    z0 = coord(p.z - r), z1 = coord(p.z + r);
    for (long long x = x0; x <= x1; ++x)
      for (long long y = y0; y <= y1; ++y)
        for (long long z = z0; z <= z1; ++z) {
          const auto it = cells_.find(pack(x, y, z));
          if (it == cells_.end()) continue;
          for (Index i : it->second)
            if (distance(points_[i], p) <= r) fn(i);
        }
  }

 private:
  long long coord(double v) const { return static_cast<long long>(std::floor(v / cell_)); }
  static std::uint64_t pack(long long x, long long y, long long z) {
    return (std::uint64_t(x & 0x1FFFFF) << 42) | (std::uint64_t(y & 0x1FFFFF) << 21) | std::uint64_t(z & 0x1FFFFF);
  }
  std::uint64_t cell_key(Vec3 p) const { return pack(coord(p.x), coord(p.y), coord(p.z)); }
  const std::vector<Vec3>& points_;
  double cell_;
  std::unordered_map<std::uint64_t, std::vector<Index>> cells_;
};

}  // namespace gsp::cvt::detail
