#pragma once
// Cache-coherent mesh layout by bottom-up clustering (paper, Section 4.3).
#include <gsp/connectivity.hpp>

#include <cstddef>
#include <vector>

namespace gsp {

// Permutations as new -> old index lists: new vertex i is input vertex vertex_order[i].
struct Layout {
  std::vector<Index> vertex_order;
  std::vector<Index> face_order;
  // old -> new inverses, for mapping sources in and results out.
  std::vector<Index> vertex_rank;
  std::vector<Index> face_rank;
};

// Greedy bottom-up clustering of vertices with union-find: in round k clusters merge while the
// merged size stays <= 2^k, pairs with more connecting edges first; leaves of the merge tree
// in order give the vertex order. Faces follow by their smallest new vertex index.
Layout compute_cache_layout(const TriangleMesh& mesh);

// A random layout (for benchmarks showing what the optimisation buys).
Layout random_layout(const TriangleMesh& mesh, std::uint64_t seed);

// Vertices along a Z-order (Morton) curve through the bounding box, faces by their smallest
// new vertex: a sort of the positions' interleaved bits, no graph work (docs/layout.md).
Layout spatial_layout(const TriangleMesh& mesh);

// The vertices as they are, the faces by their smallest vertex (ties in input order): for one
// field on a file whose vertices are in a coherent order but whose faces are not
// (order_coherence's faces_coherent), one counting sort instead of a whole layout.
Layout face_order_layout(const TriangleMesh& mesh);

// The identity layout.
Layout identity_layout(const TriangleMesh& mesh);

// Positions, normals and triangles reordered by the layout (triangle indices renumbered).
TriangleMesh apply_layout(const TriangleMesh& mesh, const Layout& layout);
// The same in place: each array replaced as its reordered copy is ready (one array's worth of
// extra memory at a time, not a second mesh). Normals that do not match the vertices are
// dropped, as apply_layout() leaves them out.
void apply_layout_in_place(TriangleMesh& mesh, const Layout& layout);
// The layout that undoes `layout` (orders and ranks swapped): applied to a laid-out mesh it
// gives back the original order.
Layout inverse_layout(Layout layout);

// Mean |i - j| over the vertex pairs (i, j) joined by an edge: the measure of locality
// the layout should lower.
double mean_neighbour_index_distance(const TriangleMesh& mesh);

// Mean log2(1 + |i - j|) over the same pairs: closer to what caches see (an edge's cost grows
// with the number of doublings of its index gap, not with the gap itself). The plain mean is
// dominated by the few long jumps between top-level clusters, so a hierarchical layout of a
// row-major n x n grid scores about as badly as the rows there, while this measure drops from
// about (2/3) log2(n) to about 3 (see docs/layout.md).
double mean_log_neighbour_index_distance(const TriangleMesh& mesh);

// Whether a mesh's own vertex order is coherent enough that one query gains nothing from the
// layout (docs/scale.md: a whole one-field run 15-40% faster without it on such files, 10-35%
// slower on a shuffled one; over many queries the layout always pays). `file_log_gap` is
// mean_log_neighbour_index_distance estimated from 64 runs of consecutive faces (about 200,000
// faces, read in order: a few ms), `random_log_gap` the same expected of a random order,
// log2(V) - 2; coherent when the file is at least kCoherentLogGap below it.
struct OrderCoherence {
  double file_log_gap = 0;
  double random_log_gap = 0;
  bool coherent = false;
  // The faces' order: mean log2(1 + index span) of the faces round a vertex (a sample of
  // vertices, one read of the triangles), against what a random face order gives, log2(F) - 1;
  // coherent when at least kCoherentLogGap below it.
  double face_spread = 0;
  double random_face_spread = 0;
  bool faces_coherent = false;
  // Coherent vertices, scattered faces, and faces enough for their order to matter
  // (kSortFacesFrom): a one-field run gains from sorting the faces only (face_order_layout).
  bool sort_faces = false;
};
OrderCoherence order_coherence(const TriangleMesh& mesh);

// log2 steps: neighbours 8x closer in the index than in a random order. The files measured sit
// 3.1-9.9 below in their own order (57 of 92 corpus meshes) and about 0 shuffled.
inline constexpr double kCoherentLogGap = 3.0;

// Faces from which sorting a scattered face order pays back in one field: below, the state
// fits the caches anyway and the sort costs more than it saves (measured across sizes in
// docs/layout.md, "Faces out of order").
inline constexpr std::size_t kSortFacesFrom = std::size_t(1) << 19;

}  // namespace gsp
