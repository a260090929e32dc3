#pragma once
// The core's vertex relaxation for the extensions (internal layer shared by the core and the
// extensions; not a stable API): per-vertex distances lowered along the mesh's edges, so no
// vertex ends farther than the shortest edge path from a vertex with a value, and the vertices
// lowered by more than kPseudoSourceGain, where the propagation's sources failed and a new
// round from them pays (the core seeds them as point sources: docs/gsp-core.md, "Vertices as
// pseudo-sources").
#include <gsp/connectivity.hpp>
#include <gsp/mesh.hpp>

#include <cstddef>
#include <vector>

namespace gsp::intrinsic {

// The core's values (libgsp/src/query_propagate.hpp uses them, with the reasons): a vertex
// lowered by less than this (relative) keeps its lower value but seeds nothing; at most this
// many seeding rounds.
inline constexpr double kPseudoSourceGain = 1e-2;
inline constexpr int kMaxRelaxationRounds = 32;

// Lowers distance[b] to distance[a] + length of edge ab, in Dijkstra order, from every edge
// where that shortens something (from == nullptr) or from the edges at the vertices `from`
// lists; `length` per halfedge (halfedge_lengths, snapped), faces `skipped_face` take no part.
// label[b] follows the value. `relaxed` counts the lowerings. Returns the vertices lowered by
// more than kPseudoSourceGain, each once, in increasing order.
std::vector<Index> relax_along_edges(const TriangleMesh& mesh, const Connectivity& conn,
                                     const std::vector<double>& length, const std::vector<bool>& skipped_face,
                                     std::vector<double>& distance, std::vector<Index>& label, std::size_t& relaxed,
                                     const std::vector<Index>* from = nullptr);

}  // namespace gsp::intrinsic
