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

// How much longer the path behind a virtual source at s (3D, in the plane of the face
// `corners3d`) must be for sigma + |x - s| to reach the straight line offset + |x - p| from the
// true source p at every point x of the face (0 if it does). Exact, in absolute terms: the
// shortfall |x - p| - |x - s| has no critical point inside the face (its gradient is a unit
// vector less one shorter, p lying off the plane; with p in the plane it is constant along the
// ray from p through s, which leaves the face across an edge), so its largest value is at a
// corner, at s when s lies inside, or on an edge where the two distances change alike:
// (t - a) d = +-(t - c) b, s at distance b from the edge's line with foot a, p at d and c.
// Relative to the line it may peak elsewhere (a sliver passing by the source: 0.003 short at
// a far corner is 0.4% short beside the source), so no relative slack is taken off.
double line_shortfall(const Vec3 corners3d[3], Vec3 s, double sigma, Vec3 p, double offset);

}  // namespace gsp::detail
