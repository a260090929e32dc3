#include "flip_replay.hpp"

#include <algorithm>

namespace gsp::detail {

FlipReplay::FlipReplay(std::vector<FlipRecord> log, std::size_t num_faces)
    : log_(std::move(log)), begin_(num_faces + 1, 0), flips_(2 * log_.size()) {
  for (const FlipRecord& r : log_) ++begin_[r.f1 + 1], ++begin_[r.f2 + 1];
  for (std::size_t f = 0; f < num_faces; ++f) begin_[f + 1] += begin_[f];
  std::vector<Index> fill(begin_.begin(), begin_.end() - 1);
  for (Index i = 0; i < Index(log_.size()); ++i) flips_[fill[log_[i].f1]++] = i, flips_[fill[log_[i].f2]++] = i;
}

std::size_t FlipReplay::bytes() const {
  return log_.size() * sizeof(FlipRecord) + (begin_.size() + flips_.size()) * sizeof(Index);
}

namespace {

struct P2 {
  double x, y;
};
double cross(P2 o, P2 p, P2 q) { return (p.x - o.x) * (q.y - o.y) - (p.y - o.y) * (q.x - o.x); }

// Weights of p in triangle (u, v, w); the least of them.
double weights_in(P2 p, P2 u, P2 v, P2 w, double out[3]) {
  const double area = cross(u, v, w);
  if (!(area != 0)) {
    out[0] = out[1] = out[2] = 1.0 / 3;
    return -1;
  }
  out[0] = cross(p, v, w) / area, out[1] = cross(p, w, u) / area, out[2] = cross(p, u, v) / area;
  return std::min({out[0], out[1], out[2]});
}

}  // namespace

std::pair<Index, std::array<double, 3>> FlipReplay::locate(Index face, const Triangle& corners, const double w[3],
                                                           const std::vector<Triangle>& flipped) const {
  // The point as weights on vertices (a face never names a vertex twice), so a face's winding
  // and corner order do not matter.
  Index vert[3] = {corners[0], corners[1], corners[2]};
  double weight[3] = {w[0], w[1], w[2]};
  Index after = 0;   // the next flip to consider is at least this one
  for (;;) {
    const auto first = flips_.begin() + begin_[face], last = flips_.begin() + begin_[face + 1];
    const auto it = std::lower_bound(first, last, after);
    if (it == last) break;
    const FlipRecord& r = log_[*it];
    after = *it + 1;
    const Index ids[4] = {r.a, r.b, r.c, r.d};
    const P2 at[4] = {{0, 0}, {r.lab, 0}, {r.cx, r.cy}, {r.dx, r.dy}};
    P2 p{0, 0};
    bool known = true;
    for (int k = 0; k < 3; ++k) {
      const Index* hit = std::find(ids, ids + 4, vert[k]);
      if (hit == ids + 4) {
        known = false;
        break;
      }
      p.x += weight[k] * at[hit - ids].x, p.y += weight[k] * at[hit - ids].y;
    }
    if (!known) break;   // not this face's vertices: cannot happen for a consistent log
    // The new faces (c, a, d) in f1 and (d, b, c) in f2: the one holding p.
    double w1[3], w2[3];
    const double m1 = weights_in(p, at[2], at[0], at[3], w1);
    const double m2 = weights_in(p, at[3], at[1], at[2], w2);
    if (m1 >= m2) {
      face = r.f1, vert[0] = r.c, vert[1] = r.a, vert[2] = r.d;
      std::copy(w1, w1 + 3, weight);
    } else {
      face = r.f2, vert[0] = r.d, vert[1] = r.b, vert[2] = r.c;
      std::copy(w2, w2 + 3, weight);
    }
  }
  // Clamped to the face (rounding) and put in the face's corner order.
  double sum = 0;
  for (double& x : weight) sum += (x = std::max(x, 0.0));
  std::array<double, 3> out{1.0 / 3, 1.0 / 3, 1.0 / 3};
  if (sum > 0) {
    const Triangle& t = flipped[face];
    for (int i = 0; i < 3; ++i)
      for (int k = 0; k < 3; ++k)
        if (t[i] == vert[k]) out[i] = weight[k] / sum;
  }
  return {face, out};
}

}  // namespace gsp::detail
