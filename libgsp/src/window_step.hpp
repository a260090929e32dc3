#pragma once
// The windows of gsp::WindowGeodesics (window_geodesics.hpp): a window in a face's 2D frame,
// the value it gives a point, and the two operations of the propagation, stepping a window
// across an edge into the next face and merging two windows of one source.
#include <gsp/types.hpp>

#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>

namespace gsp::detail::windows {

constexpr double kInf = std::numeric_limits<double>::infinity();

struct V2 {
  double x = 0, y = 0;
};
inline V2 operator+(V2 a, V2 b) { return {a.x + b.x, a.y + b.y}; }
inline V2 operator-(V2 a, V2 b) { return {a.x - b.x, a.y - b.y}; }
inline V2 operator*(double t, V2 a) { return {t * a.x, t * a.y}; }
inline double cross(V2 a, V2 b) { return a.x * b.y - a.y * b.x; }
inline double dot(V2 a, V2 b) { return a.x * b.x + a.y * b.y; }
// sqrt, not std::hypot: hypot guards against overflow at 1e154 and took 42% of a query here.
inline double norm(V2 a) { return std::sqrt(a.x * a.x + a.y * a.y); }

// Shadow kinds beyond a ray: none, a wedge bounded by W -> U, or all of the face (W is one of
// its corners).
enum : std::uint8_t { kNoShadow = 0, kBounded = 1, kWholeFace = 2 };

struct Window {
  V2 s;
  double sigma = 0;
  Index label = 0;     // which source it comes from
  bool rays = false;   // false: S is a corner of the face and sees all of it
  V2 w[2], u[2];
  std::uint8_t shadow[2] = {kNoShadow, kNoShadow};
  // A point of the face the window sees (the middle of what it sees of its entry edge; S for a
  // corner window): a window that reaches no sample point of a sliver may still be the only
  // one that reaches this part of it.
  V2 mid;
};

inline Window corner_window(V2 corner, double value) {
  Window w;
  w.s = corner, w.sigma = value, w.mid = corner;
  return w;
}

inline double ray_side(const Window& win) { return cross(win.w[0] - win.s, win.w[1] - win.s); }

inline bool beyond_ray(const Window& win, int r, V2 p, double o) {
  const double c = cross(win.w[r] - win.s, p - win.s) * o;
  const double tol = 1e-12 * std::abs(o) * (1 + norm(p - win.s));
  return r == 0 ? c < -tol : c > tol;
}

// Whether p (beyond ray r) lies in the shadow wedge at W: between the ray's continuation past
// W and the ray W -> U. A wedge of no width (U on the continuation: collinear vertices, as on
// CAD grids) holds nothing; its cross products are rounding noise of either sign.
inline bool in_shadow(const Window& win, int r, V2 p) {
  if (win.shadow[r] == kNoShadow) return false;
  if (win.shadow[r] == kWholeFace) return true;
  const V2 w = win.w[r], u = win.u[r], d = w - win.s;
  const double side = cross(d, u - w);
  if (!(std::abs(side) > 1e-12 * norm(d) * norm(u - w))) return false;
  const double sgn = side > 0 ? 1.0 : -1.0, tol = 1e-12 * norm(p - w);
  return sgn * cross(d, p - w) >= -tol * norm(d) && sgn * cross(u - w, p - w) <= tol * norm(u - w);
}

// Whether the window's two rays bound a wedge of some width (collinear vertices can make them
// coincide; such a window sees nothing).
inline bool has_width(const Window& win) {
  return std::abs(ray_side(win)) > 1e-12 * norm(win.w[0] - win.s) * norm(win.w[1] - win.s);
}

// Windows with rays have width (step() makes no other), so the ray tests below are sound.
inline double value_at(const Window& win, V2 p) {
  if (win.rays) {
    // Inside the wedge (the usual case) without the tolerances' square roots: beyond_ray
    // needs a cross product of the wrong sign.
    const double o = ray_side(win);
    const V2 q = p - win.s;
    if (cross(win.w[0] - win.s, q) * o >= 0 && cross(win.w[1] - win.s, q) * o <= 0) return norm(q) + win.sigma;
    for (int r = 0; r < 2; ++r)
      if (beyond_ray(win, r, p, o))
        return in_shadow(win, r, p) ? norm(p - win.w[r]) + norm(win.w[r] - win.s) + win.sigma : kInf;
  }
  return norm(p - win.s) + win.sigma;
}

// Where the path value_at measures comes from in a straight line: S, or the ray's vertex W
// when p is in its shadow wedge; *rest is the length left there. False where the window gives
// p nothing.
inline bool origin_of(const Window& win, V2 p, V2* from, double* rest) {
  if (win.rays) {
    const double o = ray_side(win);
    for (int r = 0; r < 2; ++r)
      if (beyond_ray(win, r, p, o)) {
        if (!in_shadow(win, r, p)) return false;
        *from = win.w[r], *rest = norm(win.w[r] - win.s) + win.sigma;
        return true;
      }
  }
  *from = win.s, *rest = win.sigma;
  return true;
}

// The window `win` (in T's frame) through T's edge A B into T (P its third corner): the new
// windows, written to out; their count.
constexpr int kMaxStepOut = 6;
// shadow_sources: the part of AB in the shadow of a ray's vertex W also gets a window of its own
// from W (which can bend again further on); without, only the shadow wedge carried by the new
// window reaches it (one bend).
int step(const Window& win, V2 a, V2 b, V2 p, Window out[kMaxStepOut], bool shadow_sources, int depth = 0);

// Whether two windows have one source (S and sigma equal up to rounding).
bool same_source(const Window& x, const Window& y);

// The union of two windows of one source whose wedges touch or overlap: 1 (x already holds
// it), 2 (merged into *out), 0 (no union).
int merge(const Window& x, const Window& y, Window* out);

}  // namespace gsp::detail::windows
