#pragma once
// Edge flips that raise the smallest angle of the dual (see remesh.hpp, RemeshOptions).
#include <gsp/mesh.hpp>

namespace gsp::cvt::detail {

// Flips an interior edge when the two angles opposite it sum to more than 180 degrees (it is
// not locally Delaunay), the flip raises the smaller of the two triangles' smallest angles,
// the two new triangles keep the orientation of the old ones (no fold), and the new edge does
// not exist yet (the mesh stays manifold). Vertices and topology do not change. Returns the
// number of flips.
std::size_t improve_by_flips(TriangleMesh& mesh, double max_normal_angle_deg, int max_passes = 20);

}  // namespace gsp::cvt::detail
