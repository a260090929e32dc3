#pragma once
// The probe (internal): where the update step compares a candidate virtual source with the
// face's own, as the visibility heuristic (paper Section 3.2; gsp/heuristic.hpp, one formula:
// visibility_signature) places it for the face's shape, with the heuristic's parameters in the
// propagation's scalar type; and rule 7's looser probe at saddle corners
// (gsp/intrinsic/corner_rules.hpp).
#include <gsp/heuristic.hpp>
#include <gsp/intrinsic/corner_rules.hpp>

#include <algorithm>

namespace gsp::detail {

// The visibility heuristic's parameters in the propagation's scalar type.
template <class Real>
struct ProbeTable {
  Real c, g, hh, hg;
  Real lambda[16];
  Real saddle_loose;   // rule 7's probe (gsp/intrinsic/corner_rules.hpp)

  // delaunay: the faces are an intrinsic Delaunay triangulation (rule 7's looser probe).
  ProbeTable(const VisibilityHeuristic& h, bool delaunay)
      : c(Real(h.c)), g(Real(h.g)), hh(Real(h.hh)), hg(Real(h.hg)),
        saddle_loose(Real(delaunay ? intrinsic::kSaddleLooseLambda : intrinsic::kSaddleLooseLambdaInputFaces)) {
    for (int i = 0; i < 16; ++i) lambda[i] = Real(h.lambda[i]);
  }
  // lambda for the face with edge lengths len entered over an edge of length e1, height h.
  Real blend(const Real len[3], Real e1, Real h) const {
    const Real max_e = std::max({len[0], len[1], len[2]});
    const Real min_e = std::min({len[0], len[1], len[2]});
    return lambda[visibility_signature(c, g, hh, hg, e1, max_e, min_e, h)];
  }
};

}  // namespace gsp::detail
