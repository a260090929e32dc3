#pragma once
// Edge flips that raise the smallest angle of the dual (see remesh.hpp, RemeshOptions).
#include <gsp/mesh.hpp>

#include <cstdint>
#include <functional>
#include <unordered_map>
#include <vector>

namespace gsp::cvt::detail {

// Directed edge (a, b) -> 3 * face + corner of a, kept up to date through improve_by_flips'
// flips. `unique`: no directed edge was in two faces, so the map is the mesh's edge set and
// stays it through the flips (a flip adds only an edge that does not exist); such a map can
// be handed from one improve_by_flips call to the next while only positions change between
// them, instead of being built again (a node per edge: malloc and free were half of the
// flips' instructions in the post-pass).
struct DirectedEdges {
  explicit DirectedEdges(const TriangleMesh& m);
  bool exists(Index a, Index b) const;
  // Faces f = (a, b, c) and g = (b, a, d) become (a, d, c) and (d, b, c).
  void flip(TriangleMesh& m, Index f, Index g, Index a, Index b, Index c, Index d);

  std::unordered_map<std::uint64_t, Index> map;
  bool unique = false;
};

// Flips an interior edge when the two angles opposite it sum to more than 180 degrees (it is
// not locally Delaunay), the flip raises the smaller of the two triangles' smallest angles,
// the two new triangles keep the orientation of the old ones (no fold), and the new edge does
// not exist yet (the mesh stays manifold). Vertices and topology do not change. Returns the
// number of flips.
//
// `touched` (per vertex): the mesh is what an earlier call left converged, changed since only
// by moving these vertices. Only edges whose quad holds one of them, or a corner of a flip
// made since, are examined: the same flips in the same order as examining all (an edge whose
// four corners did not move and whose neighbourhood no flip changed would be refused again),
// at a fraction of the cost when the moves are few. `converged` (optional): set to whether the
// last pass made no flip (within max_passes), the condition for the next call's `touched`.
// `edges` (optional): the mesh's DirectedEdges with `unique` set, kept up to date here;
// built anew when absent.
std::size_t improve_by_flips(TriangleMesh& mesh, double max_normal_angle_deg, int max_passes = 20,
                             const std::vector<bool>* locked = nullptr, const std::vector<bool>* touched = nullptr,
                             bool* converged = nullptr, DirectedEdges* edges = nullptr);

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
// close to the input, both ways). `flipped(f, g, unique)` is called after each flip (`unique`:
// no directed edge of the mesh is in two faces, DirectedEdges::unique). Unlike
// improve_by_flips no normal limit: the restricted Delaunay dual of a thin fold makes such
// caps, and the flip is what removes them. Returns the number of flips.
std::size_t remove_caps(TriangleMesh& mesh, double cap_angle_deg,
                        const std::function<bool(Index, Index, Index, Index, Index, Index)>& keeps_surface,
                        const std::function<void(Index, Index, bool)>& flipped);

}  // namespace gsp::cvt::detail
