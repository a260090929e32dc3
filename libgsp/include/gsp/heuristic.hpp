#pragma once
// The data-driven visibility heuristic of the paper's Section 3.2, as plain data.
//
// When a virtual source is carried from face U into face T over their shared edge e1, the
// source stays visible (a straight geodesic) if the segment from a probe point Q in T to the
// source crosses e1. Q = (1 - lambda) * P + lambda * C, with P the corner of T opposite e1 and
// C the centroid of T. lambda comes from a 16-entry table indexed by four anisotropy bits of T:
//   b0: maxE > c  * e1     b1: maxE > g  * minE
//   b2: h    < hh * e1     b3: h    < hg * maxE        (h: height of T over e1)
#include <array>
#include <string>

namespace gsp {

// The table index (the four bits above) for a face entered over an edge of length e1, with
// longest and shortest edges max_e and min_e and height h over e1. One formula for every
// scalar type: the propagation evaluates it in float or double (ProbeTable, face_record.hpp),
// the line sources and the training tool in double.
template <class Real>
inline int visibility_signature(Real c, Real g, Real hh, Real hg, Real e1, Real max_e, Real min_e, Real h) {
  return (max_e > c * e1 ? 1 : 0) | (max_e > g * min_e ? 2 : 0) | (h < hh * e1 ? 4 : 0) | (h < hg * max_e ? 8 : 0);
}

struct VisibilityHeuristic {
  double c = 5.1424;
  double g = 4.20638;
  double hh = 0.504201;
  double hg = 2.84918;
  std::array<double, 16> lambda{0.320991, 0.446887, 0.595879, 0.270094, 0.236679, 0.159685,
                                0.0872932, 0.434132, 1.0, 0.726262, 0.0635997, 0.0515979,
                                0.56903, 0.0447586, 0.0612103, 0.718198};

  // The values published with the paper's supplemental code (the default).
  static VisibilityHeuristic published() { return {}; }
  // lambda = 1 everywhere: always probe at the centroid (the paper's baseline).
  static VisibilityHeuristic centroid();
  // lambda = 0 everywhere: probe at the opposite corner (conservative: over-estimates).
  static VisibilityHeuristic opposite_corner();
  // Retrained on our own meshes by gsp-train-heuristic (docs/heuristic.md).
  static VisibilityHeuristic trained();

  // Table index for a triangle with shared edge e1, longest/shortest edges max_e/min_e and
  // height h over e1.
  int signature(double e1, double max_e, double min_e, double h) const {
    return visibility_signature(c, g, hh, hg, e1, max_e, min_e, h);
  }
  double blend(double e1, double max_e, double min_e, double h) const {
    return lambda[signature(e1, max_e, min_e, h)];
  }

  // 20 numbers "c g hh hg l0 .. l15" (for the training tool and --heuristic FILE).
  std::string to_string() const;
  static VisibilityHeuristic from_string(const std::string& text);   // throws InvalidInput
};

}  // namespace gsp
