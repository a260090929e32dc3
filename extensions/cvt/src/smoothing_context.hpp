#pragma once
// What the smoothing's moves, cap flips and pulls all read: the mesh being smoothed with its
// rings, the surface its vertices stay on, a sampling of that surface dense enough to stand for
// it, and where the boundary vertices lie on the surface's boundary curves.
#include "boundary_curves.hpp"
#include "point_grid.hpp"
#include "vertex_rings.hpp"

#include <gsp/closest_point.hpp>
#include <gsp/mesh.hpp>

#include <cstddef>
#include <vector>

namespace gsp::cvt {
class ClosestPointIndex;
}

namespace gsp::cvt::detail {

struct SmoothingContext {
  SmoothingContext(TriangleMesh& mesh, const TriangleMesh& on, const ClosestPointIndex& on_index,
                   const TriangleMesh& sampling, const BoundaryCurves& boundary);

  TriangleMesh& m;
  const TriangleMesh& surface;
  const ClosestPointIndex& index;   // over `surface`
  const TriangleMesh& samples;
  const BoundaryCurves& curves;
  const PointGrid grid;                  // over the samples' vertices
  const std::vector<Vec3> sample_normal;   // area-weighted, not normalised
  VertexRings rings;
  std::vector<Vec3> surf_n;   // the surface's unit normal at each vertex
  // Boundary vertices on the curves: loop (size_t(-1): none) and arc length.
  std::vector<std::size_t> loop_of;
  std::vector<double> arc;
  const std::vector<bool>* locked = nullptr;   // locked_vertices.hpp

  // The unit normal of the surface at a point of it (its face's); zero off the surface.
  Vec3 surface_normal(const ClosestPoint& sp) const;
  // The sum of the (unnormalised) normals of v's triangles: the side v's sheet faces.
  Vec3 ring_normal(Index v) const;
  // Keeps surf_n in step with the positions, as the checks of later moves read it.
  void move(Index v, Vec3 x);

 private:
  void place_on_curves();
};

}  // namespace gsp::cvt::detail
