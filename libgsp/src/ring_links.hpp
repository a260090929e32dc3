#pragma once
// How the propagation walks round an edge (internal): one link per halfedge.
#include <gsp/types.hpp>

namespace gsp::detail {

// Radial links: ring[h] = next halfedge g on h's undirected edge in the low 29 bits,
// bit 31 = g runs from its smaller to its larger vertex index, bit 30 = the same for h,
// bit 29 = the ring is just {h, g} (a manifold edge: g's link leads back to h, so the step
// need not load it). Two halfedges run the same way (inconsistent orientation) iff their
// direction bits are equal.
inline constexpr Index kRingIndexMask = 0x1fffffffu;
inline constexpr Index kRingPair = 0x20000000u;
inline constexpr Index kRingNextDir = 0x80000000u;
inline constexpr Index kRingSelfDir = 0x40000000u;

// h's link to g, the next halfedge of its edge (h itself for a ring of one): g with both
// direction bits (`up(x)`: x runs from its smaller to its larger vertex index) and, where
// `pair`, kRingPair.
template <class Up>
inline Index ring_link(Index h, Index g, bool pair, Up&& up) {
  if (g == h) return h;
  return g | (up(g) ? kRingNextDir : 0) | (up(h) ? kRingSelfDir : 0) | (pair ? kRingPair : 0);
}

}  // namespace gsp::detail
