#pragma once
// Edge flips that raise the smallest angle of the dual (see remesh.hpp, RemeshOptions).
#include <gsp/mesh.hpp>

#include <functional>

namespace gsp::cvt::detail {

// Flips an interior edge when the two angles opposite it sum to more than 180 degrees (it is
// not locally Delaunay), the flip raises the smaller of the two triangles' smallest angles,
// the two new triangles keep the orientation of the old ones (no fold), and the new edge does
// not exist yet (the mesh stays manifold). Vertices and topology do not change. Returns the
// number of flips.
std::size_t improve_by_flips(TriangleMesh& mesh, double max_normal_angle_deg, int max_passes = 20);

// Caps across creases: a triangle with an angle above `cap_angle_deg` (its vertex nearly on
// the opposite edge) has that edge flipped when the flip raises the smaller of the pair's
// smallest angles, both new triangles face the way the pair faces on the whole, the new edge
// does not exist yet, and the surface stays close: `distance(p)` (to the input surface) of the
// new edge's midpoint is at most max(bound, that of the old edge's midpoint), and the input
// point nearest the old edge's midpoint (`nearest(p)`) is at most max(bound, before) from the
// new pair. Unlike improve_by_flips no normal limit: the restricted Delaunay dual of a thin
// fold makes such caps, and the flip is what removes them. Returns the number of flips.
std::size_t remove_caps(TriangleMesh& mesh, double cap_angle_deg, double bound,
                        const std::function<double(Vec3)>& distance, const std::function<Vec3(Vec3)>& nearest);

}  // namespace gsp::cvt::detail
