#pragma once
// Angle-raising vertex moves on the dual and distance-lowering pulls, kept on the input
// surface (see remesh.hpp, RemeshOptions::smooth). Only positions move (and flips).
#include "boundary_curves.hpp"

#include <gsp/mesh.hpp>

#include <cstddef>
#include <vector>

namespace gsp::cvt {
class ClosestPointIndex;
}

namespace gsp::cvt::detail {

struct SmoothParams {
  int passes = 8;
  double below_angle = 40.0;     // degrees: vertices whose worst incident angle is below this are tried
  double max_deviation = 0;      // model units: the surface checks' bound (see below)
  double flip_max_normal_angle = 20.0;   // < 0: no flips
  // Model units; 0: off. After the passes, surface points farther than this from the mesh pull
  // a corner of their nearest triangle part of the way towards them (see pulls.hpp).
  double pull_distance = 0;
  // The cap flips first (remove_caps); and which vertices the moves try first (nullptr: all;
  // others only once their triangles change). The second run after the insertions of
  // refine.hpp tries the new vertices' neighbourhoods only, without caps.
  bool cap_flips = true;
  const std::vector<bool>* only = nullptr;
  const std::vector<bool>* locked = nullptr;   // never moved, their edges never flipped (locked_vertices.hpp)
  // The vertices that may move at all (nullptr: all): refine.hpp's moves after its insertions
  // keep to the insertions' neighbourhoods.
  const std::vector<bool>* movable = nullptr;
  // An index over `surface` built by the caller (nullptr: built here; the working mesh's takes
  // a few tenths of a second).
  const ClosestPointIndex* surface_index = nullptr;
};

struct SmoothCounts {
  std::size_t moves = 0, boundary_moves = 0, flips = 0, pulls = 0;
};

// `surface`: the surface the vertices lie on (the working mesh: the input, split). Interior
// vertices move towards the mean of their neighbours in the tangent plane, then by a pattern
// search on the smallest angle of their triangles, every point projected onto the surface
// (Embree closest point); boundary vertices slide along the surface's boundary curve the
// same way. A point is kept only if it raises the smallest angle of the vertex's triangles,
// folds none of them, keeps them within max(max_deviation, before) of the surface and the
// surface under them within the same bound of them; so the mesh's minimum angle never
// falls. Edge flips (improve_by_flips) follow every pass; then the pulls.
// `curves`: the boundary loops of `surface`. `samples`: a mesh of the same surface whose
// vertices are dense enough to stand for it in the check that the surface stays close to the
// moved triangles (the working mesh; `surface` itself can be the coarser input). Vertices
// without triangles are left alone.
SmoothCounts smooth_vertices(TriangleMesh& mesh, const TriangleMesh& surface, const TriangleMesh& samples,
                             const BoundaryCurves& curves, const SmoothParams& params);

}  // namespace gsp::cvt::detail
