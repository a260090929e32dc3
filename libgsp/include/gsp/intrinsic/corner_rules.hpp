#pragma once
// The corner rules of the update step (internal layer shared by the core's propagation and the
// extensions' update steps; not a stable API). The visibility probe decides whether a source
// crosses edge AB straight or bends at A or B; where that decision concerns an end whose kind
// says more (vertex_kinds.hpp), the kind has the last word. docs/gsp-core.md ("The update
// step", rules 4-7) has the measurements behind each rule and constant.
//
// Both functions take `crossing(lambda)`: where the segment from the probe at lambda (0: the
// face's corner opposite AB, 1: its centroid) to the source crosses AB's line: 0 within AB,
// 1 before A, 2 beyond B. It is called only where a rule needs it.
#include <gsp/intrinsic/vertex_kinds.hpp>

#include <cstdint>

namespace gsp::intrinsic {

// The strict probe at a saddle end (angle sum over 2 pi (1 + kSaddleExcess)): this far from
// the opposite corner towards the centroid.
inline constexpr double kSaddleLambda = 0.75;
// The loose probe that can overrule a "bend" at a saddle end: on an intrinsic Delaunay
// triangulation (the core's default) and on a mesh's own triangles (GSP with the flips off,
// the line sources' kernel), whose slivers need the stricter one (docs/gsp-core.md, rule 7).
inline constexpr double kSaddleLooseLambda = 0.15;
inline constexpr double kSaddleLooseLambdaInputFaces = 0.3;

// A bend at `end_kind`'s vertex (kind 1: at A, 2: at B) reconsidered; returns 0 to go on
// straight, else `kind`. `saddle_loose`: kSaddleLooseLambda or kSaddleLooseLambdaInputFaces.
// - flat: every unfolding round the vertex agrees and no geodesic turns there, so straight on
//   where the probe's line passes the vertex closely (`within_flat_miss()`: it crosses AB's
//   line at most kFlatMiss mean edges beyond it; farther out it could pass vertices not flat);
// - convex: a bend there never beats the straight line, and where the line misses AB the
//   true path comes round the vertex's other side; straight on wherever the centroid is still
//   seen through AB (unconditionally straight lets the line pass saddles farther on at the
//   wrong side);
// - saddle: a bend is right for the hidden part of the face and over-estimates the rest; the
//   loose probe has the last word (the table probes needles almost at the opposite corner).
template <class FlatMiss, class Crossing>
[[gnu::always_inline]] inline int reconsider_bend(int kind, std::uint8_t end_kind, double saddle_loose, FlatMiss&& within_flat_miss,
                    Crossing&& crossing) {
  switch (end_kind) {
    case kFlatVertex: return within_flat_miss() ? 0 : kind;
    case kConvexVertex: return crossing(1.0) == 0 ? 0 : kind;
    case kSaddleVertex: return crossing(saddle_loose) == 0 ? 0 : kind;
    default: return kind;
  }
}

// A straight crossing checked at saddle ends: round a saddle the unfolded line can pass on the
// wrong side and come out shorter than any surface path, and the centroid probe lets such
// lines through. Where AB has a saddle end, the strict probe decides: a bend at that end if
// its line passes it, else straight (0).
template <class Crossing>
[[gnu::always_inline]] inline int straight_past_saddles(bool saddle_a, bool saddle_b, Crossing&& crossing) {
  if (!saddle_a && !saddle_b) return 0;
  const int strict = crossing(kSaddleLambda);
  return strict != 0 && (strict == 1 ? saddle_a : saddle_b) ? strict : 0;
}

}  // namespace gsp::intrinsic
