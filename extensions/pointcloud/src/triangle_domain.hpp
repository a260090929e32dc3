#pragma once
// Point-cloud GSP on the cloud's local triangles (PointMethod::gsp): the consistent triangles
// of the points' local one-rings (local_triangles.hpp) form a soup over the unique points, and
// the mesh core's propagation (virtual sources per face, intrinsic Delaunay flips, the
// visibility rules) runs on it as on any non-manifold soup. Points the triangles do not reach
// (isolated points, outliers, pieces the graph joins but no triangle does) are reached over
// the neighbour graph's links afterwards. docs/pointcloud.md ("Local triangles").
#include <gsp/geodesics.hpp>
#include <gsp/pointcloud/point_cloud_geodesics.hpp>

#include "point_propagation.hpp"

#include <memory>
#include <vector>

namespace gsp::pointcloud::detail {

// A source of the core (vertex = unique point, or a point in a soup face) and the label of
// the PointSource it stands for.
struct TriangleSource {
  Source source;
  Index label;
};

class TriangleDomain {
 public:
  // position: the unique points (centred); triangles over them.
  TriangleDomain(const std::vector<Vec3>& position, std::vector<Triangle> triangles);

  std::size_t num_triangles() const { return mesh_.triangles.size(); }
  const std::vector<Triangle>& triangles() const { return mesh_.triangles; }
  std::size_t num_components() const { return component_count_; }   // of the soup, over points with a face
  std::size_t num_points_without_face() const { return without_face_; }

  // The closest surface point to x over the faces around the given points (its nearest points);
  // false when none of them has a face.
  bool closest_point(Vec3 x, const Index* near, std::size_t count, Source& out) const;

  // GSP on the soup (the core's options: strategy, f, max_distance), then the fallback over
  // `graph` into points it left unreached. Fills state.distance / sigma / label per unique
  // point (virtual source at the point itself).
  void propagate(const std::vector<TriangleSource>& sources, const NeighbourGraph& graph,
                 const GeodesicOptions& options, PointState& state, PointPropagationStats& stats) const;

 private:
  // One GSP query; distances into state where they improve it.
  void run_core(const std::vector<TriangleSource>& sources, const GeodesicOptions& options, PointState& state,
                PointPropagationStats& stats) const;

  TriangleMesh mesh_;
  std::unique_ptr<GeodesicSolver> solver_;  // null without triangles
  std::vector<Index> face_begin_, faces_;   // CSR: the faces around each point
  std::vector<Index> component_;            // per point: soup component, kInvalidIndex without faces
  std::size_t component_count_ = 0;
  std::size_t without_face_ = 0;
};

}  // namespace gsp::pointcloud::detail
