#pragma once
// Vertices the post-pass must leave where they are, with the edges between two of them: the
// samples of sharp feature curves (CvtOptions::feature_angle), whose edges are the curves.
// Vertices added after the list was made (splits, insertions) are not locked.
#include <gsp/mesh.hpp>

#include <vector>

namespace gsp::cvt::detail {

inline bool is_locked(const std::vector<bool>* locked, Index v) { return locked && v < locked->size() && (*locked)[v]; }

// An edge between two locked vertices is a piece of a feature curve: no flip or split.
inline bool is_locked_edge(const std::vector<bool>* locked, Index a, Index b) {
  return is_locked(locked, a) && is_locked(locked, b);
}

}  // namespace gsp::cvt::detail
