#pragma once
// Where the solver's vertices and faces sit in memory against where the caller numbered them
// (internal to libgsp). The solver works in its cache layout's order (layout.hpp); sources come
// in and results go out in the input's order, through these four maps and nothing else.
//
// A file whose order is already coherent keeps it (GeodesicSolver without optimize_layout, or
// gsp-geodesic --layout auto): then the maps are the identity and hold no arrays, which saves
// 24 bytes per vertex of a one-shot run (docs/scale.md).
#include <gsp/layout.hpp>

#include <utility>

namespace gsp::detail {

class IndexMaps {
 public:
  IndexMaps() = default;   // the identity
  explicit IndexMaps(Layout layout) : layout_(std::move(layout)) {}

  bool identity() const { return layout_.vertex_rank.empty(); }
  // Input index -> memory (layout) index, and back.
  Index vertex_to_layout(Index in) const { return identity() ? in : layout_.vertex_rank[in]; }
  Index vertex_to_input(Index v) const { return identity() ? v : layout_.vertex_order[v]; }
  Index face_to_layout(Index in) const { return identity() ? in : layout_.face_rank[in]; }
  Index face_to_input(Index f) const { return identity() ? f : layout_.face_order[f]; }
  // The layout itself (empty arrays for the identity); the maps are empty afterwards.
  Layout release() && { return std::move(layout_); }

 private:
  Layout layout_;   // all four arrays empty for the identity
};

}  // namespace gsp::detail
