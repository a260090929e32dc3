#pragma once
// Turning a point of a face's canonical 2D frame back into 3D (internal).
#include <gsp/mesh.hpp>

namespace gsp::detail {

// The canonical frame of face f (intrinsic_geometry.hpp) placed in 3D: corner 0 at the origin,
// x towards corner 1, y towards corner 2. (x, y) in model units.
Vec3 canonical_to_3d(const TriangleMesh& mesh, Index f, double x, double y);

// A point of another face's frame carried into face `corners3d`'s plane: `corners2d` are that
// face's corners in the other frame (an isometric unfolding), (x, y) the point there. False
// where the corners span no area (a degenerate face: no plane to place the point in).
bool unfolded_to_3d(const Vec3 corners3d[3], const double corners2d[3][2], double x, double y, Vec3& out);

// A point (x, y) of a neighbour's canonical frame in this face's, unfolded across their shared
// edge with the propagation's own frames (gsp/intrinsic/face_frame.hpp): this face's halfedge
// at corner i and the neighbour's at corner j lie on one edge; same_dir when both start at the
// same vertex (the faces disagree in orientation). `mine`, `theirs`: the faces' three lengths.
void across_edge(const double mine[3], Index i, const double theirs[3], Index j, bool same_dir, double x, double y,
                 double out[2]);

}  // namespace gsp::detail
