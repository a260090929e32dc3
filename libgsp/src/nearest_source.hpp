#pragma once
// The source nearest to a point by the straight-line bound, |x - s| + offset (internal;
// straight_line_bound.hpp): the first in source order on ties, as a scan over all of them
// finds it. A few sources are scanned; many get a k-d tree (nanoflann, header-only): the bound
// searches every source for the vertices found below it, and with CVT's thousands of sites
// those scans took 9% of a gsp-cvt run (the bunny at 5,000 sites: 70,000 scans of 5,000).
#include <gsp/types.hpp>

#include <nanoflann.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
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
  explicit NearestSource(const std::vector<SourcePoint>& sources) : adaptor_{&sources} {
    if (sources.size() <= kScanned) return;
    min_offset_ = std::numeric_limits<double>::infinity();
    for (const SourcePoint& s : sources) min_offset_ = std::min(min_offset_, s.offset);
    tree_ = std::make_unique<Tree>(3, adaptor_, nanoflann::KDTreeSingleIndexAdaptorParams(16));
  }

  // The least bound over the sources and the source that gives it.
  std::pair<double, Index> operator()(Vec3 x) const {
    const std::vector<SourcePoint>& sources = *adaptor_.sources;
    double bound = std::numeric_limits<double>::infinity();
    Index nearest = kInvalidIndex;
    auto consider = [&](Index s) {
      const double b = distance(x, sources[s].position) + sources[s].offset;
      if (b < bound || (b == bound && s < nearest)) bound = b, nearest = s;
    };
    if (!tree_) {
      for (std::size_t s = 0; s < sources.size(); ++s) consider(Index(s));
      return {bound, nearest};
    }
    const double query[3] = {x.x, x.y, x.z};
    Index first = 0;
    double squared = 0;
    tree_->knnSearch(query, 1, &first, &squared);
    consider(first);
    // Any source with a bound no larger is within bound - (least offset) of x; the margin
    // covers the rounding between the tree's squared distances and distance(), and the least
    // normal number keeps a source at x itself (the tree keeps squared distances below r2).
    const double r = bound - min_offset_;
    const double r2 = r * r * (1 + 1e-9) + std::numeric_limits<double>::min();
    std::vector<std::pair<Index, double>> within;
    tree_->radiusSearch(query, r2, within, nanoflann::SearchParams(32, 0.0f, false));
    for (const auto& [s, d2] : within) consider(s);
    return {bound, nearest};
  }

 private:
  static constexpr std::size_t kScanned = 64;
  struct Adaptor {
    const std::vector<SourcePoint>* sources;
    std::size_t kdtree_get_point_count() const { return sources->size(); }
    double kdtree_get_pt(Index i, std::size_t dim) const { return (*sources)[i].position[static_cast<int>(dim)]; }
    template <class BBox>
    bool kdtree_get_bbox(BBox&) const { return false; }
  };
  using Tree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, Adaptor>, Adaptor, 3, Index>;
  Adaptor adaptor_;
  double min_offset_ = 0;
  std::unique_ptr<Tree> tree_;
};

}  // namespace gsp::detail
