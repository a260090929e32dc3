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

Index FlipReplay::walk(Index face, Index vert[3], double (*weight)[3], int points) const {
  // Each point as weights on vertices (a face never names a vertex twice), so a face's winding
  // and corner order do not matter. Point 0 picks the face at each flip; the others follow it
  // with weights of any sign (the two faces of a flip lie in one plane, so a point outside the
  // face keeps its place in the plane unfolded along the way).
  Index after = 0;   // the next flip to consider is at least this one
  for (;;) {
    const auto first = flips_.begin() + begin_[face], last = flips_.begin() + begin_[face + 1];
    const auto it = std::lower_bound(first, last, after);
    if (it == last) break;
    const FlipRecord& r = log_[*it];
    after = *it + 1;
    const Index ids[4] = {r.a, r.b, r.c, r.d};
    const P2 at[4] = {{0, 0}, {r.lab, 0}, {r.cx, r.cy}, {r.dx, r.dy}};
    int slot[3];
    for (int k = 0; k < 3; ++k) {
      slot[k] = int(std::find(ids, ids + 4, vert[k]) - ids);
      if (slot[k] == 4) return face;   // not this face's vertices: cannot happen for a consistent log
    }
    P2 p[4];
    for (int i = 0; i < points; ++i) {
      p[i] = {0, 0};
      for (int k = 0; k < 3; ++k) p[i].x += weight[i][k] * at[slot[k]].x, p[i].y += weight[i][k] * at[slot[k]].y;
    }
    // The new faces (c, a, d) in f1 and (d, b, c) in f2: the one holding point 0.
    double w1[3], w2[3];
    const double m1 = weights_in(p[0], at[2], at[0], at[3], w1);
    const double m2 = weights_in(p[0], at[3], at[1], at[2], w2);
    const bool first_face = m1 >= m2;
    if (first_face)
      face = r.f1, vert[0] = r.c, vert[1] = r.a, vert[2] = r.d;
    else
      face = r.f2, vert[0] = r.d, vert[1] = r.b, vert[2] = r.c;
    std::copy(first_face ? w1 : w2, (first_face ? w1 : w2) + 3, weight[0]);
    for (int i = 1; i < points; ++i) {
      if (first_face)
        weights_in(p[i], at[2], at[0], at[3], weight[i]);
      else
        weights_in(p[i], at[3], at[1], at[2], weight[i]);
    }
  }
  return face;
}

std::pair<Index, std::array<double, 3>> FlipReplay::locate(Index face, const Triangle& corners, const double w[3],
                                                           const std::vector<Triangle>& flipped) const {
  Index vert[3] = {corners[0], corners[1], corners[2]};
  double weight[1][3] = {{w[0], w[1], w[2]}};
  face = walk(face, vert, weight, 1);
  // Clamped to the face (rounding) and put in the face's corner order.
  double sum = 0;
  for (double& x : weight[0]) sum += (x = std::max(x, 0.0));
  std::array<double, 3> out{1.0 / 3, 1.0 / 3, 1.0 / 3};
  if (sum > 0) {
    const Triangle& t = flipped[face];
    for (int i = 0; i < 3; ++i)
      for (int k = 0; k < 3; ++k)
        if (t[i] == vert[k]) out[i] = weight[0][k] / sum;
  }
  return {face, out};
}

FlipReplay::Frame FlipReplay::frame(Index face, const Triangle& corners, const double w[3],
                                    const std::vector<Triangle>& flipped) const {
  Index vert[3] = {corners[0], corners[1], corners[2]};
  double weight[4][3] = {{w[0], w[1], w[2]}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  Frame out;
  out.face = walk(face, vert, weight, 4);
  const Triangle& t = flipped[out.face];
  for (int c = 0; c < 3; ++c)
    for (int i = 0; i < 3; ++i) {
      out.corner[c][i] = 0;
      for (int k = 0; k < 3; ++k)
        if (t[i] == vert[k]) out.corner[c][i] = weight[c + 1][k];
    }
  return out;
}

}  // namespace gsp::detail
