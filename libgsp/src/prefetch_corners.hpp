#pragma once
// Software prefetch for passes over the faces in face order that read (or write) per-vertex
// records (internal). Where the file's vertex order is not the faces' order (new vertices
// appended after old ones, as midpoint splits and many exporters leave them), each corner's
// record is a cache miss, and the loop waits on one face's misses at a time: asking for the
// corners of the face kFacesAhead further on keeps several in flight (docs/scale.md, "Software
// prefetch", has the measurements). Results do not change: only loads are added.
#include <gsp/types.hpp>

#include <cstddef>
#include <vector>

namespace gsp::detail {

inline constexpr std::size_t kFacesAhead = 16;
// The same distance for passes over the halfedges (three per face) that read each one's partner.
inline constexpr Index kHalfedgesAhead = 3 * Index(kFacesAhead);

// The records of face f + kFacesAhead's corners, if there is such a face. Always inlined: GCC
// finds a function whose only effect is a prefetch free of side effects and deletes its calls
// (checked with objdump: none of the prefetches were left without the attribute).
template <class T>
[[gnu::always_inline]] inline void prefetch_corners(const std::vector<Triangle>& triangles, const std::vector<T>& per_vertex, std::size_t f) {
  if (f + kFacesAhead >= triangles.size()) return;
  const Triangle& t = triangles[f + kFacesAhead];
  __builtin_prefetch(per_vertex.data() + t[0]);
  __builtin_prefetch(per_vertex.data() + t[1]);
  __builtin_prefetch(per_vertex.data() + t[2]);
}

}  // namespace gsp::detail
