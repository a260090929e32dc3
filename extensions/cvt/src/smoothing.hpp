#pragma once
// Angle-raising vertex moves on the dual, kept on the input surface (see remesh.hpp,
// RemeshOptions::smooth). Vertices and connectivity do not change; only positions move.
#include "boundary_curves.hpp"

#include <gsp/mesh.hpp>

#include <cstddef>

namespace gsp::cvt::detail {

struct SmoothParams {
  int passes = 8;
  double below_angle = 35.0;     // degrees: vertices whose worst incident angle is below this are tried
  double max_deviation = 0;      // model units: a moved triangle's centroid may lie this far off the surface
  double flip_max_normal_angle = 20.0;
  // Model units; 0: off. After the passes, surface points farther than this from the mesh pull
  // the best corner of their nearest triangle onto them (see smoothing.cpp).
  double pull_distance = 0;   // < 0: no flips
};

struct SmoothCounts {
  std::size_t moves = 0, boundary_moves = 0, flips = 0, pulls = 0;
};

// `surface`: the surface the vertices lie on (the working mesh: the input, split). Interior
// vertices move towards the mean of their neighbours in the tangent plane, then onto the
// surface (Embree closest point); boundary vertices slide along the surface's boundary curve
// towards the arc-length midpoint of their two boundary neighbours. A move (full, half or
// quarter step) is kept only if it raises the smallest angle of the vertex's triangles, folds
// none of them, and keeps their centroids within max(max_deviation, before) of the surface;
// so the mesh's minimum angle never falls. Edge flips (improve_by_flips) follow every pass.
// `curves`: the boundary loops of `surface`. `samples`: a mesh of the same surface whose
// vertices are dense enough to stand for it in the check that the surface stays close to the
// moved triangles (the working mesh; `surface` itself can be the coarser input). Vertices
// without triangles are left alone.
SmoothCounts smooth_vertices(TriangleMesh& mesh, const TriangleMesh& surface, const TriangleMesh& samples,
                             const BoundaryCurves& curves, const SmoothParams& params);

}  // namespace gsp::cvt::detail
