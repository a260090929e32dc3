#pragma once
// What the propagation keeps per face (internal): the virtual source and the face's own edge
// lengths in one 32-byte record, so an update touches one cache line of the face it improves.
// Everything else the update step needs (the unfolding of the neighbour, the heuristic's probe)
// is recomputed from the three lengths — a division and a square root are cheaper than the
// cache misses that tables of precomputed constants cost (measured: 36% of the time stalled on
// a per-halfedge table load before this layout).
#include <gsp/heuristic.hpp>
#include <gsp/types.hpp>

#include <algorithm>
#include <cmath>

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
};

// The face seen from its halfedge j: A = corner j at the origin, B = corner j+1 at (e1, 0),
// P = corner j+2 at (px, py), py >= 0. A zero-length AB puts P straight above A.
template <class Real>
struct EdgeView {
  Real e1, px, py;
};

template <class Real>
inline EdgeView<Real> edge_view(const Real len[3], Index j) {
  const Real e1 = len[j], e2 = len[j == 2 ? 0 : j + 1], e3 = len[j == 0 ? 2 : j - 1];
  if (!(e1 > 0)) return {Real(0), Real(0), e3};
  const Real px = (e1 * e1 + e3 * e3 - e2 * e2) / (2 * e1);
  return {e1, px, std::sqrt(std::max(Real(0), e3 * e3 - px * px))};   // clamped: slivers round below 0
}

// The canonical frame inside the edge frame of view v (halfedge j): origin (ox, oy) = corner 0,
// unit x axis (ux, uy) towards corner 1 (towards corner 2 when corners 0 and 1 coincide).
template <class Real>
struct CanonicalFrame {
  Real ox, oy, ux, uy;

  // Edge-frame point -> canonical coordinates, and back.
  void to_canonical(Real x, Real y, Real& cx, Real& cy) const {
    const Real dx = x - ox, dy = y - oy;
    cx = dx * ux + dy * uy;
    cy = ux * dy - uy * dx;
  }
  void to_edge(Real cx, Real cy, Real& x, Real& y) const {
    x = ox + cx * ux - cy * uy;
    y = oy + cx * uy + cy * ux;
  }
};

template <class Real>
inline CanonicalFrame<Real> canonical_frame(const Real len[3], Index j, const EdgeView<Real>& v) {
  // Corner 0 and the direction to corner 1, in the edge frame of halfedge j (A = corner j at
  // the origin, B = corner j+1 at (e1, 0), P = corner j+2 at (px, py)). Written per case, not
  // through arrays indexed by j: this runs twice per update step.
  const Real l = len[0];
  if (l > 0) {
    if (j == 0) return {Real(0), Real(0), Real(1), Real(0)};   // the canonical frame (e1 = l)
    if (j == 1) return {v.px, v.py, -v.px / l, -v.py / l};
    return {v.e1, Real(0), (v.px - v.e1) / l, v.py / l};
  }
  // Corners 0 and 1 coincide: towards corner 2 instead.
  Real x[3], y[3];
  const Index a = j, b = j == 2 ? 0 : j + 1, p = j == 0 ? 2 : j - 1;
  x[a] = 0, y[a] = 0;
  x[b] = v.e1, y[b] = 0;
  x[p] = v.px, y[p] = v.py;
  const Real dx = x[2] - x[0], dy = y[2] - y[0], l2 = len[2];
  if (!(l2 > 0)) return {x[0], y[0], Real(1), Real(0)};
  return {x[0], y[0], dx / l2, dy / l2};
}

// The canonical position of corner 2 (corner 0 is the origin, corner 1 is (len[0], 0)).
template <class Real>
inline void canonical_corner2(const Real len[3], Real& x, Real& y) {
  if (len[0] > 0) {
    const EdgeView<Real> v = edge_view(len, 0);
    x = v.px, y = v.py;
  } else {
    x = len[2], y = 0;
  }
}

// The visibility heuristic's parameters in the propagation's scalar type.
template <class Real>
struct ProbeTable {
  Real c, g, hh, hg;
  Real lambda[16];

  explicit ProbeTable(const VisibilityHeuristic& h)
      : c(Real(h.c)), g(Real(h.g)), hh(Real(h.hh)), hg(Real(h.hg)) {
    for (int i = 0; i < 16; ++i) lambda[i] = Real(h.lambda[i]);
  }
  // lambda for the face with edge lengths len entered over an edge of length e1, height h.
  Real blend(const Real len[3], Real e1, Real h) const {
    const Real max_e = std::max({len[0], len[1], len[2]});
    const Real min_e = std::min({len[0], len[1], len[2]});
    const int index = (max_e > c * e1 ? 1 : 0) | (max_e > g * min_e ? 2 : 0) | (h < hh * e1 ? 4 : 0) |
                      (h < hg * max_e ? 8 : 0);
    return lambda[index];
  }
};

}  // namespace gsp::detail
