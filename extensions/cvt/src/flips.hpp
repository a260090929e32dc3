#pragma once
// Edge flips that raise the smallest angle of the dual (see remesh.hpp, RemeshOptions).
#include <gsp/mesh.hpp>

#include <functional>
#include <vector>

namespace gsp::cvt::detail {

// Flips an interior edge when the two angles opposite it sum to more than 180 degrees (it is
// not locally Delaunay), the flip raises the smaller of the two triangles' smallest angles,
// the two new triangles keep the orientation of the old ones (no fold), and the new edge does
// not exist yet (the mesh stays manifold). Vertices and topology do not change. Returns the
// number of flips.
std::size_t improve_by_flips(TriangleMesh& mesh, double max_normal_angle_deg, int max_passes = 20,
                             const std::vector<bool>* locked = nullptr);

// Lawson's Delaunay flips restricted to planes: an interior edge whose two opposite angles sum
// to more than 180 degrees is flipped when the four corners lie in one plane (each off the
// other triangle's plane by at most `max_height`, so the surface moves by no more than that),
// the new triangles face the old pair's way, the smaller of the pair's smallest angles rises
// and the new edge does not exist yet. Flipped edges' neighbours are checked again until none
// is left (at most `max_flips`). `changed` (sized to the faces) marks the faces rewritten.
// Returns the number of flips.
std::size_t delaunay_flips_in_planes(TriangleMesh& mesh, double max_height, std::size_t max_flips,
                                     std::vector<bool>& changed);

// Caps across creases: a triangle with an angle above `cap_angle_deg` (its vertex nearly on
// the opposite edge) has that edge flipped when the flip raises the smaller of the pair's
// smallest angles, both new triangles face the way the pair faces on the whole, the new edge
// does not exist yet, and `keeps_surface(f, g, a, b, c, d)` agrees: faces f = (a, b, c) and
// g = (b, a, d) would become (a, d, c) and (d, b, c) (the caller checks that the surface stays
// close to the input, both ways). `flipped()` is called after each flip. Unlike
// improve_by_flips no normal limit: the restricted Delaunay dual of a thin fold makes such
// caps, and the flip is what removes them. Returns the number of flips.
std::size_t remove_caps(TriangleMesh& mesh, double cap_angle_deg,
                        const std::function<bool(Index, Index, Index, Index, Index, Index)>& keeps_surface,
                        const std::function<void()>& flipped);

}  // namespace gsp::cvt::detail
