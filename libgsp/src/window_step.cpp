#include "window_step.hpp"

#include <algorithm>
#include <cmath>

namespace gsp::detail::windows {

namespace {

// The shadow wedge at ray r's vertex for the next face, whose entry edge has its shadowed part
// from the end X to the ray's crossing (which lies on the wedge's other side, the ray's
// continuation).
std::pair<std::uint8_t, V2> clip_shadow(const Window& win, int r, V2 x) {
  if (win.shadow[r] == kNoShadow) return {kNoShadow, {}};
  if (win.shadow[r] == kWholeFace) return {kBounded, x};
  const V2 w = win.w[r], u = win.u[r], d = w - win.s;
  const double side = cross(d, u - w);
  if (!(std::abs(side) > 1e-12 * norm(d) * norm(u - w))) return {kNoShadow, {}};   // no width
  const double sgn = side > 0 ? 1.0 : -1.0;
  if (sgn * cross(u - w, x - w) <= 0) return {kBounded, x};   // X inside: bounded by W -> X now
  return {kBounded, u};
}

// The window whose source is ray r's vertex W, seeing what the shadow wedge there holds.
Window shadow_source(const Window& win, int r) {
  const V2 w = win.w[r];
  Window sw;
  sw.s = w, sw.sigma = win.sigma + norm(w - win.s), sw.label = win.label, sw.mid = w;
  if (win.shadow[r] == kBounded) {
    sw.rays = true;
    sw.w[0] = w + (w - win.s), sw.w[1] = win.u[r];   // the ray's continuation, W -> U
  }
  return sw;
}

}  // namespace

int step(const Window& win, V2 a, V2 b, V2 p, Window out[kMaxStepOut], bool shadow_sources, int depth) {
  const V2 ab = b - a;
  const double inside = cross(ab, p - a);
  int n = 0;
  auto corners = [&] {
    for (V2 x : {a, b}) {
      const double v = value_at(win, x);
      if (v < kInf) out[n] = corner_window(x, v), out[n++].label = win.label;
    }
    return n;
  };
  if (!(cross(ab, win.s - a) * inside < 0)) return corners();   // S on T's side: bend at A or B
  double lo = 0, hi = 1;
  V2 anchor[2] = {a, b};
  int from_ray[2] = {-1, -1}, hidden_by = -1;
  if (win.rays) {
    const double o = ray_side(win);
    for (int r = 0; r < 2; ++r) {
      const double sgn = r == 0 ? 1 : -1;
      const V2 wv = win.w[r];
      const double ca = sgn * cross(wv - win.s, a - win.s) * o, cb = sgn * cross(wv - win.s, b - win.s) * o;
      if (ca >= 0 && cb >= 0) continue;
      if (ca < 0 && cb < 0) {
        lo = 1, hi = 0, hidden_by = r;
        break;
      }
      const double t = ca / (ca - cb);
      if (ca < 0) {
        if (t > lo) lo = t, anchor[0] = wv, from_ray[0] = r;
      } else if (t < hi) {
        hi = t, anchor[1] = wv, from_ray[1] = r;
      }
    }
  }
  if (!(hi - lo > 1e-9)) {
    // S sees nothing of AB. Behind the ray that hides it, its vertex W is the source, seen
    // through its shadow wedge (W a corner of the sending face sees all of AB); without a
    // wedge there, the bends at A and B.
    if (hidden_by < 0 || win.shadow[hidden_by] == kNoShadow || depth > 0) return corners();
    const int m = step(shadow_source(win, hidden_by), a, b, p, out, shadow_sources, depth + 1);
    return m > 0 ? m : corners();
  }
  Window nw;
  nw.s = win.s, nw.sigma = win.sigma, nw.rays = true, nw.label = win.label;
  nw.w[0] = anchor[0], nw.w[1] = anchor[1];
  nw.mid = a + (0.5 * (lo + hi)) * ab;
  const V2 ends[2] = {a, b};
  bool moved[2] = {false, false};
  for (int e = 0; e < 2; ++e) {
    if (from_ray[e] < 0) {
      nw.shadow[e] = kWholeFace;
    } else {
      const auto [kind, u] = clip_shadow(win, from_ray[e], ends[e]);
      nw.shadow[e] = kind, nw.u[e] = u;
      // The part of AB in the shadow of the ray's vertex W gets a window of its own from W,
      // which can bend again further on (round a chain of reflex corners along a boundary);
      // the shadow wedge would end at the next one.
      const bool part = e == 0 ? lo > 1e-9 : hi < 1 - 1e-9;
      moved[e] = shadow_sources && depth == 0 && kind != kNoShadow && part && win.shadow[from_ray[e]] != kNoShadow;
    }
  }
  if (has_width(nw)) out[n++] = nw;   // a window of no width sees nothing
  for (int e = 0; e < 2; ++e)
    if (moved[e]) n += step(shadow_source(win, from_ray[e]), a, b, p, out + n, shadow_sources, depth + 1);
  return n;
}

bool same_source(const Window& x, const Window& y) {
  return std::abs(x.sigma - y.sigma) <= 1e-9 * (1 + y.sigma) &&
         norm(x.s - y.s) <= 1e-9 * (1 + std::max(std::abs(y.s.x), std::abs(y.s.y)));
}

int merge(const Window& x, const Window& y, Window* out) {
  if (!same_source(x, y)) return 0;
  if (!x.rays) return 1;
  if (!y.rays) return *out = y, 2;
  const V2 s = y.s;
  V2 ref = 0.5 * (x.w[0] + x.w[1]) - s;
  const double len = norm(ref);
  if (len > 0) ref = (1 / len) * ref;
  auto angle = [&](V2 v) { return std::atan2(cross(ref, v - s), dot(ref, v - s)); };
  struct End {
    double angle;
    const Window* win;
    int ray;
  };
  auto ends = [&](const Window& w) {
    End e0{angle(w.w[0]), &w, 0}, e1{angle(w.w[1]), &w, 1};
    return e0.angle <= e1.angle ? std::pair{e0, e1} : std::pair{e1, e0};
  };
  const auto [lx, hx] = ends(x);
  const auto [ly, hy] = ends(y);
  constexpr double tol = 1e-9;
  if (ly.angle > hx.angle + tol || lx.angle > hy.angle + tol) return 0;
  const End lo = lx.angle <= ly.angle ? lx : ly, hi = hx.angle >= hy.angle ? hx : hy;
  if (hi.angle - lo.angle >= M_PI - 1e-6) return 0;
  Window m;
  m.s = s, m.sigma = y.sigma, m.rays = true, m.label = y.label, m.mid = y.mid;
  for (int slot = 0; slot < 2; ++slot) {
    const End& e = slot == 0 ? lo : hi;
    m.w[slot] = e.win->w[e.ray], m.u[slot] = e.win->u[e.ray], m.shadow[slot] = e.win->shadow[e.ray];
  }
  *out = m;
  return 2;
}

}  // namespace gsp::detail::windows
