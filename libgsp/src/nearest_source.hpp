#pragma once
// The source nearest to a point by the straight-line bound, |x - s| + offset (internal;
// straight_line_bound.hpp): the first in source order on ties, as a scan over all of them
// finds it. A few sources are scanned; many are searched outwards from x in the order of their
// x coordinate, stopping where the x distance alone exceeds the best bound so far (less the
// least offset): the bound searches the sources for every vertex found below it, and with
// CVT's thousands of sites the scans took 9% of a gsp-cvt run (the bunny at 5,000 sites:
// 70,000 scans of 5,000). Why not a k-d tree (nanoflann, which the point clouds use): the core
// needs nothing but the standard library and threads (tests/consumer), and this sweep costs a
// sort and 12 bytes per source.
#include <gsp/types.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <utility>
#include <vector>

namespace gsp::detail {

// A source as the bound needs it: where it is in 3D, and its offset.
struct SourcePoint {
  Vec3 position;
  double offset = 0;
};

class NearestSource {
 public:
  // `sources` must outlive this and stay where it is.
  explicit NearestSource(const std::vector<SourcePoint>& sources) : sources_(sources) {
    if (sources.size() <= kScanned) return;
    min_offset_ = std::numeric_limits<double>::infinity();
    for (const SourcePoint& s : sources) min_offset_ = std::min(min_offset_, s.offset);
    order_.resize(sources.size());
    std::iota(order_.begin(), order_.end(), Index{0});
    std::sort(order_.begin(), order_.end(),
              [&](Index a, Index b) { return sources[a].position.x < sources[b].position.x; });
    xs_.resize(order_.size());
    for (std::size_t i = 0; i < order_.size(); ++i) xs_[i] = sources[order_[i]].position.x;
  }

  // The least bound over the sources and the source that gives it.
  std::pair<double, Index> operator()(Vec3 x) const {
    double bound = std::numeric_limits<double>::infinity();
    Index nearest = kInvalidIndex;
    auto consider = [&](Index s) {
      const double b = distance(x, sources_[s].position) + sources_[s].offset;
      if (b < bound || (b == bound && s < nearest)) bound = b, nearest = s;
    };
    if (order_.empty()) {
      for (std::size_t s = 0; s < sources_.size(); ++s) consider(Index(s));
      return {bound, nearest};
    }
    // A source with a bound no larger is within bound - (least offset) of x, so within that in
    // x; the margin covers rounding.
    auto out_of_reach = [&](double dx) { return dx > (bound - min_offset_) * (1 + 1e-9); };
    std::size_t up = std::size_t(std::lower_bound(xs_.begin(), xs_.end(), x.x) - xs_.begin());
    std::size_t down = up;   // next below: down - 1
    bool going_up = up < xs_.size(), going_down = down > 0;
    while (going_up || going_down) {
      if (going_up) {
        if (up == xs_.size() || out_of_reach(xs_[up] - x.x)) going_up = false;
        else consider(order_[up++]);
      }
      if (going_down) {
        if (down == 0 || out_of_reach(x.x - xs_[down - 1])) going_down = false;
        else consider(order_[--down]);
      }
    }
    return {bound, nearest};
  }

 private:
  static constexpr std::size_t kScanned = 64;
  const std::vector<SourcePoint>& sources_;
  double min_offset_ = 0;
  std::vector<Index> order_;   // sources by x coordinate
  std::vector<double> xs_;     // their x coordinates, in that order
};

}  // namespace gsp::detail
