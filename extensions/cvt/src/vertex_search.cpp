#include "vertex_search.hpp"
#include "move_checks.hpp"
#include "triangle_geometry.hpp"

#include <gsp/connectivity.hpp>
#include <gsp/cvt/closest_point_index.hpp>

#include <algorithm>
#include <cmath>

namespace gsp::cvt::detail {

namespace {

constexpr double kPi = 3.14159265358979323846;

// The mean of v's neighbours, the unit normal of its triangles and their mean edge length at
// v: the search's tangent plane and step scale. False where they are degenerate.
struct Frame {
  Vec3 mean, normal;
  double h = 0;
};
bool tangent_frame(const SmoothingContext& c, Index v, Frame& f) {
  const Vec3 x0 = c.m.positions[v];
  std::size_t n = 0;
  for (Index h : c.rings.around(v)) {
    const Triangle& t = c.m.triangles[face_of(h)];
    const Vec3 nb = c.m.positions[t[(corner_of(h) + 1) % 3]];
    f.mean = f.mean + nb;
    f.h += distance(nb, x0);
    ++n;
  }
  f.normal = c.ring_normal(v);
  const double nn = norm(f.normal);
  if (nn == 0 || f.h == 0) return false;
  f.normal = (1.0 / nn) * f.normal;
  f.mean = (1.0 / double(n)) * f.mean;
  f.h /= double(n);
  return true;
}

// The best point so far and the candidates' checks, kept together because every candidate
// must beat the best one and the surface checks' reference figures are taken once per vertex.
class MoveSearch {
 public:
  MoveSearch(const SmoothingContext& c, Index v, double q0, const Frame& f, double max_deviation)
      : x(c.m.positions[v]), sx(c.arc[v]), best(q0), c_(c), v_(v), x0_(c.m.positions[v]), frame_(f),
        bound_(max_deviation), guard_(c, v, f.normal, max_deviation) {}

  bool slide_along_boundary();
  void search_on_surface();

  // The best position so far (its arc length on the boundary) and its quality.
  Vec3 x;
  double sx, best;

 private:
  bool chords_stay_close(double sy) const;
  bool try_arc(double offset);
  bool try_point(Vec3 target);

  const SmoothingContext& c_;
  const Index v_;
  const Vec3 x0_;
  const Frame& frame_;
  const double bound_;
  SurfaceGuard guard_;
  std::size_t l_ = 0;   // v's boundary loop
  double back_ = 0, ahead_ = 0;   // arc lengths to the previous and the next boundary vertex
  Index face_ = kInvalidIndex;    // the surface face of the last candidate: where the next one's search starts
};

// The chords to the boundary neighbours must stay as close to the boundary curve as the
// surface checks keep the triangles to the surface.
bool MoveSearch::chords_stay_close(double sy) const {
  const BoundaryCurves& curves = c_.curves;
  const std::size_t l = l_;
  const double sa = c_.arc[c_.rings.prev_b[v_]], sv = c_.arc[v_], sb = c_.arc[c_.rings.next_b[v_]];
  const double before = std::max(curves.chord_deviation(l, sa, curves.wrap(l, sv - sa)),
                                 curves.chord_deviation(l, sv, curves.wrap(l, sb - sv)));
  const double after = std::max(curves.chord_deviation(l, sa, curves.wrap(l, sy - sa)),
                                curves.chord_deviation(l, sy, curves.wrap(l, sb - sy)));
  return after <= std::max(before, bound_);
}

// Never past a neighbour: the slide stays inside (arc[a], arc[b]).
bool MoveSearch::try_arc(double offset) {
  if (offset <= -0.9 * back_ || offset >= 0.9 * ahead_) return false;
  const double s = c_.curves.wrap(l_, c_.arc[v_] + offset);
  const Vec3 y = c_.curves.at(l_, s);
  const ClosestPoint sp = c_.index.closest(y, face_);
  face_ = sp.point.element;
  const double q = signed_quality(c_, v_, y, true, c_.surface_normal(sp));
  if (q <= best + 1e-9 || !chords_stay_close(s) || !guard_.keeps(y)) return false;
  best = q, x = y, sx = s;
  return true;
}

// A boundary vertex slides only along its own curve, between neighbours on the same curve in
// the curve's order; false where it cannot.
bool MoveSearch::slide_along_boundary() {
  const Index a = c_.rings.prev_b[v_], b = c_.rings.next_b[v_];
  l_ = c_.loop_of[v_];
  if (a == kInvalidIndex || b == kInvalidIndex || l_ == std::size_t(-1) || c_.loop_of[a] != l_ || c_.loop_of[b] != l_)
    return false;
  const double L = c_.curves.loops[l_].length;
  back_ = c_.curves.wrap(l_, c_.arc[v_] - c_.arc[a]), ahead_ = c_.curves.wrap(l_, c_.arc[b] - c_.arc[v_]);
  if (back_ + ahead_ > 0.75 * L) return false;   // not in the curve's order: leave it
  const double shift = 0.5 * (ahead_ - back_);
  for (double t : {1.0, 0.5, 0.25})
    if (try_arc(t * shift)) break;
  // Then a pattern search along the curve.
  double offset = c_.curves.wrap(l_, sx - c_.arc[v_]);
  if (offset > 0.5 * L) offset -= L;
  double step = 0.1 * frame_.h;
  for (int it = 0; it < 40 && step > 0.005 * frame_.h; ++it) {
    if (try_arc(offset + step)) offset += step;
    else if (try_arc(offset - step)) offset -= step;
    else step *= 0.5;
  }
  return true;
}

// Candidates are projected onto the surface; a projection onto another sheet (across a slit or
// a thin wall) or too far from the target would take v off its own sheet.
bool MoveSearch::try_point(Vec3 target) {
  const ClosestPoint sp = c_.index.closest(target, face_);
  face_ = sp.point.element;
  if (sp.point.element == kInvalidIndex || sp.distance > 0.5 * frame_.h) return false;
  const Triangle& st = c_.surface.triangles[sp.point.element];
  const Vec3 sn = normal(c_.surface.positions[st[0]], c_.surface.positions[st[1]], c_.surface.positions[st[2]]);
  if (dot(sn, frame_.normal) <= 0.5 * norm(sn)) return false;   // another sheet
  const double q = signed_quality(c_, v_, sp.position, true, c_.surface_normal(sp));
  if (q <= best + 1e-9 || !guard_.keeps(sp.position)) return false;
  best = q, x = sp.position;
  return true;
}

// The pattern search in the tangent plane (8 directions, halving steps) after the step towards
// the neighbours' mean: the smallest angle is not smooth in the position, the mean of the
// neighbours only roughly raises it.
void MoveSearch::search_on_surface() {
  const Vec3 normal = frame_.normal;
  Vec3 lap = frame_.mean - x0_;
  lap = lap - dot(lap, normal) * normal;
  for (double t : {1.0, 0.5, 0.25})
    if (try_point(x0_ + t * lap)) break;
  Vec3 e1 = cross(normal, Vec3{1, 0, 0});
  if (norm(e1) < 0.5) e1 = cross(normal, Vec3{0, 1, 0});
  e1 = (1.0 / norm(e1)) * e1;
  const Vec3 e2 = cross(normal, e1);
  double step = 0.1 * frame_.h;
  for (int it = 0; it < 60 && step > 0.005 * frame_.h; ++it) {
    bool moved_here = false;
    for (int k = 0; k < 8 && !moved_here; ++k) {
      const double phi = k * kPi / 4;
      moved_here = try_point(x + step * (std::cos(phi) * e1 + std::sin(phi) * e2));
    }
    if (!moved_here) step *= 0.5;
  }
}

}  // namespace

bool find_move(const SmoothingContext& c, Index v, double below, double max_deviation, Move& move) {
  const Vec3 x0 = c.m.positions[v];
  const double q0 = signed_quality(c, v, x0, false, c.surf_n[v]);
  if (q0 >= below) return false;
  Frame frame;
  if (!tangent_frame(c, v, frame)) return false;
  MoveSearch search(c, v, q0, frame, max_deviation);
  if (c.rings.on_boundary(v)) {
    if (!search.slide_along_boundary()) return false;
  } else {
    search.search_on_surface();
  }
  if (search.best <= q0 + 1e-9 || plain_quality(c, v, search.x) < plain_quality(c, v, x0)) return false;
  move = {search.x, search.sx};
  return true;
}

}  // namespace gsp::cvt::detail
