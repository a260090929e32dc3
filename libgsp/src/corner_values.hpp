#pragma once
// A vertex's value from the faces around it (internal): each face's virtual source gives its
// corners sigma + |corner - source|, and a vertex takes the smallest of its faces' values
// (query_gather.hpp) or is lowered by it (the relaxation's rounds).
//
// At a saddle corner (angle sum above 2 pi by more than kSaddleExcess, vertex_kinds.hpp) a
// face's value counts only when its source lies in the face's own angle at that corner, i.e.
// the segment reaches the corner through the face. A source outside that angle reaches the
// corner through other faces of the fan, unfolded round the saddle, where a line can pass on a
// side no surface path takes and come out short. Where none of a saddle's faces sees its
// source (a front arriving along an edge), the plain smallest value stands. The case it
// mends: a hole in a CAD plate whose face is a fan of slivers from rim to rim (the fence
// panels: a source on the hole's rim gave the rim's far side the straight line across the
// hole, 19% short); docs/gsp-core.md, "Values at saddle vertices".
#include "face_record.hpp"

#include <cmath>
#include <cstddef>
#include <cstdint>

namespace gsp {

using detail::FaceRecord;

// How far outside a corner's angle (relative: of the edge's length times its length plus the
// source's distance) a source still counts as inside: rounding of the canonical frames and of
// a source placed exactly on an edge's line or at a corner.
inline constexpr double kCornerConeSlack = 1e-5;

// Distance of corner c's vertex through its face's virtual source (normalised units).
template <class Real>
inline Real corner_distance(const FaceRecord<Real>& r, Index corner) {
  Real x = 0, y = 0;
  if (corner == 1) x = r.len[0];
  if (corner == 2) detail::canonical_corner2(r.len, x, y);
  return r.sigma + std::sqrt((r.sx - x) * (r.sx - x) + (r.sy - y) * (r.sy - y));
}

// One face's corner values from its record's fields: d_i = sigma + |corner i - source|, and
// seen bit i: whether the source gives corner i its value (see above; always at a corner that
// is not a saddle, `saddles` bit i). Branch-free, so that corner_distances() vectorises it;
// every caller goes through this one expression, so the tests agree to the bit wherever they
// are asked (the full gather, the bounded queries' gather, the relaxation).
template <class Real>
[[gnu::always_inline]] inline void corner_values(Real sx, Real sy, Real sigma, Real l0, Real l1, Real l2,
                                                 std::uint8_t saddles, Real& d0, Real& d1, Real& d2,
                                                 std::uint8_t& seen) {
  // Every operation unconditional, then selects: a division or square root under a condition
  // keeps the loop scalar.
  const bool edge = l0 > 0;
  const Real base = edge ? l0 : Real(1);
  const Real x_edge = (l0 * l0 + l2 * l2 - l1 * l1) / (2 * base);
  const Real x2 = edge ? x_edge : l2;
  const Real h2 = l2 * l2 - x2 * x2;
  const Real y_edge = std::sqrt(h2 > Real(0) ? h2 : Real(0));
  const Real y2 = edge ? y_edge : Real(0);
  const Real r0 = std::sqrt(sx * sx + sy * sy);
  const Real r1 = std::sqrt((sx - l0) * (sx - l0) + sy * sy);
  const Real r2 = std::sqrt((sx - x2) * (sx - x2) + (sy - y2) * (sy - y2));
  d0 = sigma + r0;
  d1 = sigma + r1;
  d2 = sigma + r2;
  // The source against each edge's line (edge i from corner i to i + 1; >= 0: the face's side).
  const Real e0 = l0 * sy;
  const Real e1 = (x2 - l0) * sy - y2 * (sx - l0);
  const Real e2 = y2 * (sx - x2) - x2 * (sy - y2);
  const Real slack = Real(kCornerConeSlack);
  const bool in0 = e0 >= -slack * l0 * (l0 + r0) && e2 >= -slack * l2 * (l2 + r0);
  const bool in1 = e1 >= -slack * l1 * (l1 + r1) && e0 >= -slack * l0 * (l0 + r1);
  const bool in2 = e2 >= -slack * l2 * (l2 + r2) && e1 >= -slack * l1 * (l1 + r2);
  const std::uint8_t inside = std::uint8_t(in0 | in1 << 1 | in2 << 2);
  seen = edge ? std::uint8_t((~saddles | inside) & 7) : std::uint8_t(7);
}

template <class Real>
inline std::uint8_t saddle_bits(const FaceRecord<Real>& r) {
  return std::uint8_t(r.saddle_corner(0) | r.saddle_corner(1) << 1 | r.saddle_corner(2) << 2);
}

// Whether face r's source gives corner c its value (corner_values()).
template <class Real>
inline bool corner_sees_source(const FaceRecord<Real>& r, Index c) {
  if (!r.saddle_corner(c)) return true;
  Real d0, d1, d2;
  std::uint8_t seen;
  corner_values(r.sx, r.sy, r.sigma, r.len[0], r.len[1], r.len[2], saddle_bits(r), d0, d1, d2, seen);
  return (seen >> c) & 1;
}

// The corner values of n <= 256 consecutive faces, d[3k + i] for corner i of face k and
// seen[k] (corner_values()), copied into one array per field first so that the compiler
// vectorises the square roots (4 or 8 at a time instead of one). +inf for an unreached face
// (its sigma is +inf). Same values as corner_distance().
template <class Real>
inline void corner_distances(const FaceRecord<Real>* r, std::size_t n, Real* d, std::uint8_t* seen) {
  constexpr std::size_t kMax = 256;
  Real sx[kMax], sy[kMax], sigma[kMax], l0[kMax], l1[kMax], l2[kMax], d0[kMax], d1[kMax], d2[kMax];
  std::uint8_t saddles[kMax];
  for (std::size_t k = 0; k < n; ++k)
    sx[k] = r[k].sx, sy[k] = r[k].sy, sigma[k] = r[k].sigma, l0[k] = r[k].len[0], l1[k] = r[k].len[1],
    l2[k] = r[k].len[2], saddles[k] = saddle_bits(r[k]);
  for (std::size_t k = 0; k < n; ++k)
    corner_values(sx[k], sy[k], sigma[k], l0[k], l1[k], l2[k], saddles[k], d0[k], d1[k], d2[k], seen[k]);
  for (std::size_t k = 0; k < n; ++k) d[3 * k] = d0[k], d[3 * k + 1] = d1[k], d[3 * k + 2] = d2[k];
}

}  // namespace gsp
