#include "move_checks.hpp"
#include "triangle_geometry.hpp"

#include <gsp/connectivity.hpp>
#include <gsp/cvt/closest_point_index.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace gsp::cvt::detail {

namespace {

constexpr double kPi = 3.14159265358979323846;

// The centroids of v's triangles and the midpoints of their edges at v, with v at x, each
// given to fn until it returns false: the points whose distance to the surface bounds how far
// the chords leave it. True if fn accepted every point.
template <class Fn>
bool all_chord_points(const SmoothingContext& c, Index v, Vec3 x, Fn&& fn) {
  for (Index h : c.rings.around(v)) {
    const Triangle& t = c.m.triangles[face_of(h)];
    const Index k = corner_of(h);
    const Vec3 b = c.m.positions[t[(k + 1) % 3]], d = c.m.positions[t[(k + 2) % 3]];
    for (Vec3 s : {(x + b + d) * (1.0 / 3), 0.5 * (x + b), 0.5 * (x + d)})
      if (!fn(s)) return false;
  }
  return true;
}

// The largest distance of those points to the surface: the figure a move may not exceed.
double deviation(const SmoothingContext& c, Index v, Vec3 x) {
  double worst = 0;
  Index near = kInvalidIndex;   // the last point's face: the next point lies a triangle away
  all_chord_points(c, v, x, [&](Vec3 s) {
    const ClosestPoint sp = c.index.closest(s, near);
    near = sp.point.element;
    worst = std::max(worst, sp.distance);
    return true;
  });
  return worst;
}

// Whether deviation(c, v, x) <= limit, without measuring each point's distance. hint[i]: the
// surface face that kept chord point i last time (the candidates of one search lie close
// together, so it mostly keeps it again and the BVH is not asked).
bool close_to_surface(const SmoothingContext& c, Index v, Vec3 x, double limit, std::vector<Index>& hint) {
  std::size_t i = 0;
  return all_chord_points(c, v, x, [&](Vec3 s) {
    if (i == hint.size()) hint.push_back(kInvalidIndex);
    return c.index.within(s, limit, hint[i++]);
  });
}

// The triangles around v's neighbours that are not v's, each once, with a sphere around each:
// they stay where they are when v moves, so a point within `limit` of one of them stays
// within `limit` of the mesh whatever v does. The sphere (centroid, farthest corner) rejects
// most triangles before the exact distance, which is at least |z - centre| - radius.
class RestTriangles {
 public:
  RestTriangles(const SmoothingContext& c, Index v) {
    std::vector<Index> faces;
    for (Index h : c.rings.around(v))
      for (Index u : c.m.triangles[face_of(h)]) {
        if (u == v) continue;
        for (Index k : c.rings.around(u)) {
          const Triangle& t = c.m.triangles[face_of(k)];
          if (t[0] != v && t[1] != v && t[2] != v) faces.push_back(face_of(k));
        }
      }
    std::sort(faces.begin(), faces.end());
    faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
    for (Index f : faces) {
      const Triangle& t = c.m.triangles[f];
      Entry e{{c.m.positions[t[0]], c.m.positions[t[1]], c.m.positions[t[2]]}, {}, 0};
      e.centre = (e.p[0] + e.p[1] + e.p[2]) * (1.0 / 3);
      for (const Vec3& q : e.p) e.radius = std::max(e.radius, distance(q, e.centre));
      entries_.push_back(e);
    }
  }

  // Whether z lies within `limit` of one of them.
  bool cover(Vec3 z, double limit) const {
    for (const Entry& e : entries_) {
      // (the relative slack covers the rounding of both sides: a hit is never rejected)
      if (distance(z, e.centre) > (limit + e.radius) * (1 + 1e-12)) continue;
      if (triangle_distance(z, e.p[0], e.p[1], e.p[2]) <= limit) return true;
    }
    return false;
  }

 private:
  struct Entry {
    Vec3 p[3];
    Vec3 centre;
    double radius;
  };
  std::vector<Entry> entries_;
};

// The points of the surface under v's triangles (v at x0; `normal`: theirs) that a move of v
// could carry farther than max(bound, before) from the mesh, and their distances to v's
// triangles before. The points under them: x0, the surface points nearest their edge
// midpoints at v and centroids, and the sample mesh's vertices near v whose closest point on
// the triangles depends on v (not on the far edges, which belong to the neighbours' triangles
// too): the input's tips and creases are among them. A point the other triangles around
// already keep within that bound stays within it whatever v does; checking it against v's
// triangles alone blocked moves of vertices with long edges: on falconstatue's base at 2,000
// sites wall points 0.03-0.08 (6-17 times the bound) from a sliver's ring, covered by their
// own triangles, grew by 1e-8 and refused every move.
void watched_points(const SmoothingContext& c, Index v, Vec3 x0, Vec3 normal, double bound, std::vector<Vec3>& kept,
                    std::vector<double>& before) {
  kept.clear(), before.clear();
  std::vector<std::array<Vec3, 2>> ring;   // the far edge of each of v's triangles
  std::vector<Vec3> under{x0};
  double reach = 0;
  Index near = kInvalidIndex;   // the last point's face (as in deviation())
  for (Index h : c.rings.around(v)) {
    const Triangle& t = c.m.triangles[face_of(h)];
    const Index k = corner_of(h);
    const Vec3 b = c.m.positions[t[(k + 1) % 3]], e = c.m.positions[t[(k + 2) % 3]];
    ring.push_back({b, e});
    reach = std::max(reach, distance(x0, b));
    for (Vec3 z : {0.5 * (x0 + b), (x0 + b + e) * (1.0 / 3)}) {
      const ClosestPoint sp = c.index.closest(z, near);
      near = sp.point.element;
      if (sp.point.element != kInvalidIndex) under.push_back(sp.position);
    }
  }
  const RestTriangles rest(c, v);
  // z's distance to v's triangles, and whether its closest point on one of them depends on v.
  auto measure = [&](Vec3 z, bool& on_v) {
    double d = 1e300;
    on_v = false;
    for (const auto& [b, e] : ring) {
      const std::array<double, 3> w = closest_point_on_triangle(z, x0, b, e);
      on_v = on_v || w[0] > 1e-9;
      d = std::min(d, distance(z, w[0] * x0 + w[1] * b + w[2] * e));
    }
    return d;
  };
  auto watch = [&](Vec3 z, double d) {
    if (rest.cover(z, std::max(bound, d))) return;
    kept.push_back(z), before.push_back(d);
  };
  bool on_v = false;
  for (Vec3 z : under) watch(z, measure(z, on_v));
  c.grid.near(x0, reach, [&](Index w) {
    if (dot(c.sample_normal[w], normal) <= 0) return;   // another sheet (a slit, a thin wall)
    const Vec3 z = c.samples.positions[w];
    const double d = measure(z, on_v);
    if (on_v) watch(z, d);
  });
}

}  // namespace

double signed_quality(const SmoothingContext& c, Index v, Vec3 x, bool check_fold, Vec3 nx) {
  const double fold_cos = std::cos(40.0 * kPi / 180.0);
  double worst = 10;
  for (Index h : c.rings.around(v)) {
    const Triangle& t = c.m.triangles[face_of(h)];
    const Index k = corner_of(h);
    Vec3 q[3] = {c.m.positions[t[0]], c.m.positions[t[1]], c.m.positions[t[2]]};
    Vec3 s[3] = {c.surf_n[t[0]], c.surf_n[t[1]], c.surf_n[t[2]]};
    const Vec3 before = normal(q[0], q[1], q[2]);
    q[k] = x, s[k] = nx;
    const Vec3 after = normal(q[0], q[1], q[2]);
    if (check_fold && dot(before, after) <= fold_cos * norm(before) * norm(after) &&
        !(dot(after, s[0]) > 0 && dot(after, s[1]) > 0 && dot(after, s[2]) > 0))
      return -10.0;
    const double a = min_angle(q[0], q[1], q[2]);
    const Vec3 sum = s[0] + s[1] + s[2];
    worst = std::min(worst, norm(sum) >= 2.0 && dot(after, sum) < 0 ? -a : a);
  }
  return worst;
}

double plain_quality(const SmoothingContext& c, Index v, Vec3 x) {
  double worst = 10;
  for (Index h : c.rings.around(v)) {
    const Triangle& t = c.m.triangles[face_of(h)];
    Vec3 q[3] = {c.m.positions[t[0]], c.m.positions[t[1]], c.m.positions[t[2]]};
    q[corner_of(h)] = x;
    worst = std::min(worst, min_angle(q[0], q[1], q[2]));
  }
  return worst;
}

// Whether z lies within `limit` of v's triangles with v at y: ring_distance(c, v, z, y) <= limit,
// stopping at the first triangle within reach, tried from `hint` (a slot of v's ring; updated
// to the slot that answered, the likeliest first next time).
bool ring_within(const SmoothingContext& c, Index v, Vec3 z, Vec3 y, double limit, Index& hint) {
  const auto ring = c.rings.around(v);
  const std::size_t n = std::size_t(ring.end() - ring.begin());
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t slot = (hint + i) % n;
    const Index h = ring.begin()[slot];
    const Triangle& t = c.m.triangles[face_of(h)];
    const Index k = corner_of(h);
    if (triangle_distance(z, y, c.m.positions[t[(k + 1) % 3]], c.m.positions[t[(k + 2) % 3]]) <= limit) {
      hint = Index(slot);
      return true;
    }
  }
  return false;
}

double ring_distance(const SmoothingContext& c, Index v, Vec3 z, Vec3 y) {
  double d = 1e300;
  for (Index h : c.rings.around(v)) {
    const Triangle& t = c.m.triangles[face_of(h)];
    const Index k = corner_of(h);
    d = std::min(d, triangle_distance(z, y, c.m.positions[t[(k + 1) % 3]], c.m.positions[t[(k + 2) % 3]]));
  }
  return d;
}

bool SurfaceGuard::keeps(Vec3 y) {
  if (!has_deviation_) deviation0_ = deviation(c_, v_, x0_), has_deviation_ = true;
  if (!close_to_surface(c_, v_, y, std::max(deviation0_, bound_), chord_hint_)) return false;
  if (!has_watched_) {
    watched_points(c_, v_, x0_, normal_, bound_, watched_, watched_before_);
    hint_.assign(watched_.size(), 0);
    has_watched_ = true;
  }
  for (std::size_t i = 0; i < watched_.size(); ++i)
    if (!ring_within(c_, v_, watched_[i], y, std::max(watched_before_[i], bound_), hint_[i])) return false;
  return true;
}

}  // namespace gsp::cvt::detail
