// GSP on the neighbour graph. A point p holds a virtual source S_p in its tangent plane; the
// link p -> q is unfolded like a mesh edge: the tangent directions of the link in p's and in
// q's plane are identified (a rotation about the link), which carries S_p into q's plane.
// q takes the straight distance sigma_p + |S - q| if the line q -> S passes within rho of p,
// rho = min(|p - q| sin(alpha), tau |p - q|^2 / |S - q|) (an angle at q and an area of the
// hinge triangle S, p, q); else the path bends at the point x within rho of p nearest to that
// line, which becomes q's new virtual source (sigma_p + |S - x|). Links are unfolded with
// their arc length (curved_links), and steep and gap links (across gaps) are left out except
// to reach points nothing else reaches. docs/pointcloud.md.
#include "point_propagation.hpp"

#include <gsp/intrinsic/speed_limiter.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>

namespace gsp::pointcloud::detail {

void PointState::reset(std::size_t n) {
  const double inf = std::numeric_limits<double>::infinity();
  distance.assign(n, inf);
  sigma.assign(n, inf);
  sx.assign(n, 0.0);
  sy.assign(n, 0.0);
  label.assign(n, kInvalidIndex);
}

namespace {

struct Entry {
  Index point;
  double d;   // the point's distance when queued; stale once the point improved
};

// Vectors shorter than this fraction of the link are treated as zero (a link along the
// normal has no direction in the tangent plane).
constexpr double kTangentFraction = 1e-3;

// Arc over chord of a circular arc whose tangent turns by theta, cos(theta) = c:
// (theta/2) / sin(theta/2) = asin(x) / x with x = sin(theta/2), x^2 = (1 - c) / 2. The series
// in x^2 (error below 2e-4 at theta = 60 degrees, 1e-9 at 20) saves the acos and sin on
// every update step; wider turns take the exact form.
double arc_over_chord(double c) {
  const double x2 = 0.5 * (1 - std::clamp(c, -1.0, 1.0));
  if (x2 > 0.25) {
    const double x = std::sqrt(x2);
    return std::asin(x) / x;
  }
  return 1 + x2 * (1.0 / 6 + x2 * (3.0 / 40 + x2 * (5.0 / 112 + x2 * (35.0 / 1152))));
}

class Expander {
 public:
  Expander(const Domain& domain, const PointGeodesicOptions& options, PointState& state,
           PointPropagationStats& stats)
      : g_(domain.graph), pos_(domain.position), fr_(domain.frames), state_(state), stats_(stats),
        sin_max_(std::sin(std::min(90.0, options.visibility_angle_deg) * 3.14159265358979323846 / 180.0)),
        sin_elliptic_(std::max(sin_max_, std::sin(std::min(90.0, options.elliptic_visibility_angle_deg) *
                                                  3.14159265358979323846 / 180.0))),
        max_distance_(options.max_distance),
        mean_link_(domain.mean_link), tau_(options.hinge_area), eps_(1e-12 * (domain.mean_link > 0 ? domain.mean_link : 1.0)),
        slope_(options.steep_link_slope < 1 ? options.steep_link_slope : std::numeric_limits<double>::infinity()),
        gap_slope_(options.gap_link_slope < 1 ? options.gap_link_slope : std::numeric_limits<double>::infinity()),
        curved_(options.curved_links) {}

  // After the propagation ran dry: from reached point p over its steep and gap links into
  // points still unreached. Across a gap p's position in q's plane means nothing, so q becomes a
  // source of its own (sigma = d_p + |q - p|, at q).
  template <class Push>
  void reach_over_steep(Index p, Push&& push) {
    const double dp = state_.distance[p];
    if (!std::isfinite(dp) || dp > max_distance_) return;
    for (Index k = g_.begin[p]; k < g_.begin[p + 1]; ++k) {
      const Index q = g_.neighbour[k];
      if (std::isfinite(state_.distance[q])) continue;
      const double d = dp + g_.length[k];
      if (set(q, d, d, Vec3{0, 0, 0}, state_.label[p])) {
        ++stats_.updates;
        ++stats_.bends;
        ++stats_.steep_links_used;
        push(Entry{q, state_.distance[q]});
      }
    }
  }

  bool set(Index q, double d, double sigma, Vec3 w, Index label) {
    if (!(d < state_.distance[q] - eps_)) return false;
    state_.distance[q] = d;
    state_.sigma[q] = sigma;
    state_.sx[q] = dot(w, fr_.t1[q]);
    state_.sy[q] = dot(w, fr_.t2[q]);
    state_.label[q] = label;
    return true;
  }

  // The speed limiter's view of an entry (gsp/intrinsic/speed_limiter.hpp).
  double key(const Entry& e) const { return e.d; }
  bool is_stale(const Entry& e) const { return e.d != state_.distance[e.point]; }
  void prefetch(const Entry&) const {}

  template <class Push>
  void expand(const Entry& e, Push&& push) {
    const Index p = e.point;
    if (e.d != state_.distance[p]) {
      ++stats_.stale_skipped;
      return;
    }
    if (e.d > max_distance_) return;
    const double dp = state_.distance[p];
    const double sig = state_.sigma[p];
    const Index label = state_.label[p];
    const Vec3 v = state_.sx[p] * fr_.t1[p] + state_.sy[p] * fr_.t2[p];   // S_p - p
    const Vec3 np0 = fr_.normal[p];
    for (Index k = g_.begin[p]; k < g_.begin[p + 1]; ++k) {
      const Index q = g_.neighbour[k];
      const double chord = g_.length[k];
      ++stats_.update_steps;
      double len = chord;
      const Vec3 nq = fr_.normal[q];
      double cand, cand_sigma;
      Vec3 w;   // S - q in q's tangent plane
      bool bent = false;
      if (chord <= eps_) {
        // Coincident points: the same source, its direction re-projected into q's plane.
        w = v - dot(v, nq) * nq;
        const double lw = norm(w), lv = norm(v);
        w = lw > 0 ? (lv / lw) * w : lv * fr_.t1[q];
        cand_sigma = sig;
        cand = sig + lv;
      } else {
        const Vec3 link = pos_[q] - pos_[p];
        // Steep links (steep at one end) and gap links (steep at both ends) are skipped here;
        // see reach_over_steep.
        const double off_p = std::abs(dot(link, np0)), off_q = std::abs(dot(link, nq));
        if (std::max(off_p, off_q) > slope_ * chord || std::min(off_p, off_q) > gap_slope_ * chord) continue;
        const Vec3 np = dot(np0, nq) < 0 ? -1.0 * np0 : np0;   // estimated normals are unoriented
        Vec3 ep = link - dot(link, np) * np;
        Vec3 eq = link - dot(link, nq) * nq;
        const double lp = norm(ep), lq = norm(eq);
        bool straight = false;
        if (lp > kTangentFraction * len && lq > kTangentFraction * len) {
          ep = (1.0 / lp) * ep;
          eq = (1.0 / lq) * eq;
          if (curved_) len = chord * arc_over_chord(dot(ep, eq));
          const double a = dot(v, ep);               // along the link, in p's plane
          const double b = dot(v, cross(np, ep));    // across it
          w = (a - len) * eq + b * cross(nq, eq);    // p unfolds to q - len * eq
          const double r = norm(w);
          // p unfolds to P = -len * eq. Visible: the line q -> S passes within rho of P, with
          // P's foot on the segment side of q (the source lies beyond p, not behind q).
          const double proj = len * (len - a);   // (P . w), i.e. |P| r cos(angle at q)
          if (r > 0 && proj > 0) {
            const double h = len * std::abs(b) / r;   // P's distance from the line q -> S
            // The flat unfolding errs by about curvature x area of the hinge triangle
            // (S, p, q) = r h / 2; bound that area (tau len^2 / 2) as well as the angle at q.
            // Where the surface is elliptic at both ends the flat unfolding does not cut
            // corners (positive curvature: geodesics converge), so the window is wider there.
            const double sin_vis = fr_.elliptic[p] && fr_.elliptic[q] ? sin_elliptic_ : sin_max_;
            const double rho = std::min(len * sin_vis, tau_ * len * len / r);
            if (h <= rho) {
              straight = true;
              cand_sigma = sig;
              cand = sig + r;
            } else {
              // Bend at the point x within rho of P nearest to the line: continuous with the
              // straight case, and shorter than bending at p itself (a Dijkstra step).
              const Vec3 P = (-len) * eq;
              const Vec3 foot = (proj / (r * r)) * w;
              const Vec3 x = P + (rho / h) * (foot - P);
              cand_sigma = sig + norm(w - x);
              cand = cand_sigma + norm(x);
              w = x;
              straight = true;
              bent = true;
            }
          }
        }
        if (!straight) {
          w = lq > kTangentFraction * len ? (-len / lq) * (link - dot(link, nq) * nq) : (-len) * fr_.t1[q];
          cand_sigma = dp;
          cand = dp + len;
          bent = true;
        }
      }
      if (set(q, cand, cand_sigma, w, label)) {
        ++stats_.updates;
        if (bent) ++stats_.bends;
        push(Entry{q, state_.distance[q]});
      }
    }
  }

 private:
  const NeighbourGraph& g_;
  const std::vector<Vec3>& pos_;
  const TangentFrames& fr_;
  PointState& state_;
  PointPropagationStats& stats_;
  double sin_max_, sin_elliptic_, max_distance_, mean_link_;
  double tau_, eps_, slope_, gap_slope_;
  bool curved_;
};

std::vector<Entry> seed_state(const std::vector<Seed>& seeds, const TangentFrames& frames, PointState& state) {
  std::vector<Entry> queue;
  for (const Seed& s : seeds) {
    const double d = s.sigma + norm(s.offset);
    if (!(d < state.distance[s.point])) continue;
    state.distance[s.point] = d;
    state.sigma[s.point] = s.sigma;
    state.sx[s.point] = dot(s.offset, frames.t1[s.point]);
    state.sy[s.point] = dot(s.offset, frames.t2[s.point]);
    state.label[s.point] = s.label;
    queue.push_back({s.point, d});
  }
  return queue;
}

}  // namespace

void propagate_gsp(const Domain& domain, const std::vector<Seed>& seeds, const PointGeodesicOptions& options,
                   PointState& state, PointPropagationStats& stats) {
  std::vector<Entry> a = seed_state(seeds, domain.frames, state);
  Expander ex(domain, options, state, stats);
  // The core's speed limiter (paper 4.2, lean queue); the step is f mean link lengths.
  const double step = (options.f > 0 ? options.f : 1.0) * (domain.mean_link > 0 ? domain.mean_link : 1.0);
  for (;;) {
    intrinsic::SpeedLimiterCounters counters;
    intrinsic::run_speed_limiter(ex, a, step, counters);
    stats.iterations += counters.iterations;
    stats.enqueued += counters.enqueued;
    // Points only steep links lead to: reached over them, then the propagation goes on.
    if (!(options.steep_link_slope < 1) && !(options.gap_link_slope < 1)) break;
    for (Index p = 0; p < Index(state.distance.size()); ++p)
      ex.reach_over_steep(p, [&](const Entry& n) { ++stats.enqueued, a.push_back(n); });
    if (a.empty()) break;
  }
}

void propagate_dijkstra(const Domain& domain, const std::vector<Seed>& seeds, double max_distance,
                        PointState& state, PointPropagationStats& stats) {
  using Item = std::pair<double, Index>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> heap;
  for (const Entry& e : seed_state(seeds, domain.frames, state)) heap.push({e.d, e.point});
  const NeighbourGraph& g = domain.graph;
  while (!heap.empty()) {
    const auto [d, p] = heap.top();
    heap.pop();
    ++stats.iterations;
    if (d != state.distance[p]) {
      ++stats.stale_skipped;
      continue;
    }
    if (d > max_distance) continue;
    for (Index k = g.begin[p]; k < g.begin[p + 1]; ++k) {
      const Index q = g.neighbour[k];
      ++stats.update_steps;
      const double cand = d + g.length[k];
      if (cand < state.distance[q]) {
        // The path runs along links: the virtual source is the point itself.
        state.distance[q] = cand;
        state.sigma[q] = cand;
        state.sx[q] = state.sy[q] = 0;
        state.label[q] = state.label[p];
        ++stats.updates;
        ++stats.enqueued;
        heap.push({cand, q});
      }
    }
  }
}

}  // namespace gsp::pointcloud::detail
