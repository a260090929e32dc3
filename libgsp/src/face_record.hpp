#pragma once
// What the propagation keeps per face (internal): the virtual source and the face's own edge
// lengths in one 32-byte record, so an update touches one cache line of the face it improves.
// Everything else the update step needs (the unfolding of the neighbour, the heuristic's probe:
// probe_table.hpp) is recomputed from the three lengths — a division and a square root are cheaper than the
// cache misses that tables of precomputed constants cost (docs/performance.md, "Single-thread
// propagation", item 7).
#include "state_allocator.hpp"

#include <gsp/intrinsic/face_frame.hpp>
#include <gsp/types.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace gsp::detail {

inline constexpr Index kSourceMask = 0x03ffffffu;     // tag bits 0..25: source index
inline constexpr Index kNoSource = kSourceMask;       // unreached
inline constexpr Index kFlatCorner0 = 0x04000000u;    // tag bit 26 + i: corner i is flat
inline constexpr Index kSaddleCorner0 = 0x20000000u;  // tag bit 29 + i: corner i is a saddle
// Both bits of a corner set: the corner is convex (angle sum below 2 pi, not flat).

template <class Real>
struct FaceRecord {
  Real sx, sy;    // the virtual source, in the face's canonical frame (corner 0 at the origin,
                  // corner 1 on +x, corner 2 above)
  Real sigma;     // path length behind the virtual source
  Real dT;        // distance of the centroid (the key of every comparison)
  Real len[3];    // len[i] = |corner i -> corner i+1|, in mean edge lengths
  Index tag;      // source index and two bits per corner: flat, saddle or convex

  Index source() const { return tag & kSourceMask; }
  bool reached() const { return source() != kNoSource; }
  // Corner i's two bits, compared in place (one mask and one compare per test).
  bool corner_bits(Index i, Index bits) const { return (tag & ((kFlatCorner0 | kSaddleCorner0) << i)) == (bits << i); }
  bool flat_corner(Index i) const { return corner_bits(i, kFlatCorner0); }
  bool saddle_corner(Index i) const { return corner_bits(i, kSaddleCorner0); }
  bool convex_corner(Index i) const { return corner_bits(i, kFlatCorner0 | kSaddleCorner0); }
  // The corner's kind as gsp/intrinsic/vertex_kinds.hpp numbers them (flat 1, saddle 2, convex 3).
  static_assert(kFlatCorner0 == 1u << 26 && kSaddleCorner0 == 1u << 29, "corner_kind reads bits 26 + i and 29 + i");
  std::uint8_t corner_kind(Index i) const {
    return std::uint8_t(((tag >> (26 + i)) & 1u) | (((tag >> (29 + i)) & 1u) << 1));
  }
};

// A query's face records.
template <class Real>
using RecordArray = std::vector<FaceRecord<Real>, StateAllocator<FaceRecord<Real>>>;

// The frames of a face (gsp/intrinsic/face_frame.hpp), shared with the extensions.
using intrinsic::canonical_corner2;
using intrinsic::canonical_frame;
using intrinsic::CanonicalFrame;
using intrinsic::edge_view;
using intrinsic::EdgeView;

}  // namespace gsp::detail
