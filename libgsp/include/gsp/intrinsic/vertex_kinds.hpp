#pragma once
// What kind of vertex a shortest path meets (internal layer shared by the core's propagation
// and the extensions; not a stable API).
#include <gsp/connectivity.hpp>
#include <gsp/mesh.hpp>
#include <gsp/types.hpp>

#include <cstdint>
#include <array>
#include <vector>

namespace gsp::intrinsic {

// Per vertex, what the visibility test does at it (the core's update_step.hpp):
// - kFlatVertex where no shortest path can bend — interior vertices whose angle sum is 2 pi
//   and boundary vertices whose angle sum is at most pi (within a relative kFlatAngleTolerance). Unfolding
//   around such a vertex is the same from either side, so a source that the visibility probe
//   sees just past the vertex is still exact when carried straight on. This makes GSP exact on
//   flat and developable regions (planar CAD faces, fans) whatever the heuristic says.
//   Only inside a flat region: a flat vertex with a neighbour that is not flat (vertices
//   joining several fans aside) is plain, since a line carried past it can pass that
//   neighbour on a side no surface path takes (midpoint-split meshes: 1% short on average);
//   convex (below) where it is alone on its crease between two curved vertices and no
//   neighbour is a saddle or plain (the middle of an edge of a mesh split once). Nor on a
//   crease that ends at a saddle. Both from the 3D creases: apply_crease_rules()
//   (saddle_creases.hpp); vertex_kinds() runs it when given a crease partner.
// - kSaddleVertex for interior vertices whose angle sum exceeds 2 pi by more than
//   kSaddleExcess (relative): unfolded round such a vertex, a straight line passing it on the
//   wrong side is shorter than any path on the surface, so the probe is moved towards the
//   opposite corner there (stricter).
// - kConvexVertex for the other interior vertices whose angle sum is below 2 pi (positive
//   curvature). No shortest path turns at such a vertex, and bending a source there is never
//   shorter than carrying it straight on: the propagation keeps a source straight past one
//   wherever the probe says "bend" but the centroid is still seen through the edge.
//   So are the barely saddle vertices, whose angle sum exceeds 2 pi by at most
//   kStraightExcess (relative), unless a saddle vertex is next to them: a needless bend
//   over-estimates the whole face, a line passing such a vertex on the wrong side is short
//   by the little the vertex's excess turns it (docs/gsp-core.md, rule 6, has the corpus
//   figures both ways).
// The corner angles come from the 3D positions, or from `length` (per halfedge) when it is
// given: with caller-supplied intrinsic lengths (a metric) the 3D angles mean nothing.
inline constexpr std::uint8_t kPlainVertex = 0, kFlatVertex = 1, kSaddleVertex = 2, kConvexVertex = 3;
inline constexpr double kSaddleExcess = 0.01;
inline constexpr double kStraightExcess = 1e-3;
//
// boundary_halfedge[3 f + i] is non-zero where halfedge i of face f is alone on its edge;
// nonmanifold_vertices (ends of edges with more than two faces, bridges, coincident vertices)
// are plain: a vertex joining several fans has no single angle sum. Vertices no face uses are
// plain.
std::vector<std::uint8_t> vertex_kinds(const TriangleMesh& mesh, const std::vector<std::uint8_t>& boundary_halfedge,
                                       const std::vector<bool>& skipped_face,
                                       const std::vector<Index>& nonmanifold_vertices,
                                       const std::vector<double>* length = nullptr);

// vertex_kinds above in two steps. The angle sums need no connectivity, so the core computes
// them beside it (solver_build.cpp): per vertex the sum of its corner angles over the faces
// that take part, and whether such a face uses it. From positions, one cross product and two
// atan2 per face (the third angle is pi minus the two, on a face of non-zero area);
// from `length` (per halfedge) where given.
struct CornerAngleSums {
  std::vector<double> angle;
  std::vector<std::uint8_t> used;
  // Per face its unit normal (unit_normal() of face_normal(), gsp/intrinsic/coplanar_faces.hpp;
  // zero for a skipped face), written by add_corner_angles from 3D positions where the caller
  // sized it to the face count: the cross product it takes is the normal, and the crease rule
  // (apply_crease_rules) reads it instead of a pass of its own. Left empty, nothing is written.
  std::vector<std::array<float, 3>> normal;
};
CornerAngleSums corner_angle_sums(const TriangleMesh& mesh, const std::vector<bool>& skipped_face,
                                  const std::vector<double>* length = nullptr);
// The same, faces [begin, end) added to sums sized for the mesh: ranges taken in face order
// give the sums of one pass to the bit (each vertex adds its corners in face order).
void add_corner_angles(const TriangleMesh& mesh, const std::vector<bool>& skipped_face,
                       const std::vector<double>* length, CornerAngleSums& sums, std::size_t begin, std::size_t end);
// With `crease_links` (3D positions only: the core's radial links, see apply_crease_rules() in
// saddle_creases.hpp) the flat vertices on creases that end at saddles are plain too, and those
// alone on a crease between convex ones convex; sums.normal, where filled, are the faces'
// normals they read.
std::vector<std::uint8_t> vertex_kinds(const TriangleMesh& mesh, const CornerAngleSums& sums,
                                       const std::vector<std::uint8_t>& boundary_halfedge,
                                       const std::vector<bool>& skipped_face,
                                       const std::vector<Index>& nonmanifold_vertices,
                                       const std::vector<Index>* crease_links = nullptr);

// What vertex_kinds above needs from the connectivity, as the core's propagation sees the
// mesh. boundary_halfedges: per halfedge, whether the propagation crosses from it to no other
// face (next_crossed(h) == h, gsp/intrinsic/edge_lengths.hpp: alone on its edge among the
// faces that take part, in a skipped face, or on a zero-length edge); `length` per halfedge,
// after snap_zero_lengths. nonmanifold_vertices: the bridge vertices, the coincident vertices
// and the ends of edges with more than two faces.
std::vector<std::uint8_t> boundary_halfedges(const Connectivity& conn, const std::vector<bool>& skipped_face,
                                             const std::vector<double>& length);
// With skipped_face, an edge counts as non-manifold where more than two of its faces take part
// (a doubled face's edges do not: skip_duplicate_faces() in edge_lengths.hpp).
std::vector<Index> nonmanifold_vertices(const TriangleMesh& mesh, const Connectivity& conn,
                                        const std::vector<Index>& bridge_vertices,
                                        const std::vector<Index>& coincident_vertices,
                                        const std::vector<bool>* skipped_face = nullptr);

// The core's vertex kinds in one call: the two above, then vertex_kinds (with the crease limit
// for 3D angles). The corner angles come from the 3D positions, or from `length` with
// angles_from_length (caller-supplied intrinsic lengths: no creases). The core reads the
// boundary off its radial links instead (the same next_crossed), which it has made anyway.
std::vector<std::uint8_t> vertex_kinds(const TriangleMesh& mesh, const Connectivity& conn,
                                       const std::vector<bool>& skipped_face,
                                       const std::vector<Index>& bridge_vertices,
                                       const std::vector<Index>& coincident_vertices,
                                       const std::vector<double>& length, bool angles_from_length = false);

// Tight on purpose: finely tessellated smooth surfaces stored in float (STL tyres) have many
// vertices within 1e-5 of flat that geodesics must still bend around (docs/gsp-core.md).
inline constexpr double kFlatAngleTolerance = 1e-6;

// How far past a flat corner a source may still be carried straight on, in units of the
// mesh's mean edge length: the vertex is flat, its neighbours need not be, and a line carried
// far past it can pass a saddle on the wrong side (docs/gsp-core.md has the measurements).
inline constexpr double kFlatMiss = 0.5;

}  // namespace gsp::intrinsic
