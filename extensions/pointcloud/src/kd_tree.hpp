#pragma once
// A nanoflann k-d tree over a std::vector<gsp::Vec3>, read in place (zero-copy adaptor).
// Internal to gsp::pointcloud: nanoflann stays out of the public headers.
#include <gsp/types.hpp>

#include <nanoflann.hpp>

#include <utility>
#include <vector>

namespace gsp::pointcloud::detail {

struct PointsAdaptor {
  const std::vector<Vec3>* points = nullptr;
  std::size_t kdtree_get_point_count() const { return points->size(); }
  double kdtree_get_pt(Index i, std::size_t dim) const { return (*points)[i][static_cast<int>(dim)]; }
  template <class BBox>
  bool kdtree_get_bbox(BBox&) const { return false; }
};

class PointTree {
 public:
  // `points` must outlive the tree and stay where it is.
  explicit PointTree(const std::vector<Vec3>& points)
      : adaptor_{&points}, tree_(3, adaptor_, nanoflann::KDTreeSingleIndexAdaptorParams(16)) {}

  std::size_t size() const { return adaptor_.points->size(); }

  // The k nearest points (the query point itself included when it is in the cloud), nearest
  // first; returns how many were found. Squared distances.
  std::size_t knn(Vec3 q, std::size_t k, Index* indices, double* squared) const {
    if (size() == 0 || k == 0) return 0;
    const double query[3] = {q.x, q.y, q.z};
    return tree_.knnSearch(query, k, indices, squared);
  }

  // Every point with squared distance < r2, nearest first.
  void within(Vec3 q, double r2, std::vector<std::pair<Index, double>>& out) const {
    out.clear();
    if (size() == 0) return;
    const double query[3] = {q.x, q.y, q.z};
    tree_.radiusSearch(query, r2, out, nanoflann::SearchParams(32, 0.0f, true));
  }

 private:
  using Tree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, PointsAdaptor>,
                                                   PointsAdaptor, 3, Index>;
  PointsAdaptor adaptor_;
  Tree tree_;
};

}  // namespace gsp::pointcloud::detail
