#include "pulls.hpp"
#include "far_points.hpp"
#include "locked_vertices.hpp"
#include "move_checks.hpp"
#include "triangle_geometry.hpp"

#include <gsp/connectivity.hpp>
#include <gsp/cvt/closest_point_index.hpp>

#include <algorithm>
#include <unordered_map>
#include <vector>

namespace gsp::cvt::detail {

namespace {

constexpr double kPi = 3.14159265358979323846;

// Only the worst spots (the Hausdorff distance is a maximum; moving a neighbour's corner
// can help it too): within half the farthest distance, at most 2,000 points, the farthest
// first. A coarse remesh is far from the surface everywhere.
std::vector<FarPoint> worst_far_samples(const SmoothingContext& c, double pull_distance) {
  const ClosestPointIndex out(c.m);
  std::vector<FarPoint> far;
  for (Index w = 0; w < c.samples.num_vertices(); ++w) add_if_far(out, c.samples.positions, w, pull_distance, far);
  std::sort(far.begin(), far.end(), [](const FarPoint& a, const FarPoint& b) { return a.d > b.d; });
  std::size_t keep = 0;
  while (keep < far.size() && keep < 2000 && far[keep].d >= 0.5 * far.front().d) ++keep;
  far.resize(keep);
  return far;
}

// The best pull found for one far point: which vertex, to where, and the point's distance then.
struct Pull {
  Index v = kInvalidIndex;
  double d = 0;
  Vec3 y;
};

// The positions of v part of the way towards z, on the surface (the whole way mostly folds a
// triangle), that bring z closer than `best` does and pass the checks; `floor`: max(30
// degrees, the mesh's minimum angle).
void try_pulling(const SmoothingContext& c, Index v, Vec3 z, Vec3 z_normal, double floor, SurfaceGuard& guard,
                 Pull& best) {
  const Vec3 x0 = c.m.positions[v];
  if (dot(guard.normal(), z_normal) <= 0) return;   // another sheet
  const double q0 = signed_quality(c, v, x0, false, c.surf_n[v]);
  for (double t : {1.0, 0.75, 0.5, 0.35, 0.25}) {
    const ClosestPoint sp = c.index.closest(x0 + t * (z - x0));
    if (sp.point.element == kInvalidIndex) continue;
    const Vec3 y = sp.position;
    const double dz = ring_distance(c, v, z, y);
    if (dz >= 0.98 * best.d) continue;
    if (signed_quality(c, v, y, true, c.surface_normal(sp)) < std::min(q0, floor) ||
        plain_quality(c, v, y) < std::min(plain_quality(c, v, x0), floor))
      continue;
    if (guard.keeps(y)) best = {v, dz, y};
  }
}

// One round: each far point, the farthest first, pulls the best of its triangle's unlocked
// interior corners. A vertex is a corner of many far points' triangles (about ten tries per
// vertex on CAD parts), so its surface guard is kept until a move changes the triangles it
// reads: those around v's neighbours, i.e. until a vertex within two rings of v moves.
std::size_t pull_round(SmoothingContext& c, double pull_distance) {
  const double floor = std::max(mesh_min_angle(c.m), 30.0 * kPi / 180.0);
  std::vector<bool> locked(c.m.num_vertices(), false);
  std::unordered_map<Index, SurfaceGuard> guards;
  std::size_t pulled = 0;
  for (const FarPoint& f : worst_far_samples(c, pull_distance)) {
    const Vec3 z = c.samples.positions[f.w];
    Pull best;
    best.d = f.d;
    for (Index v : c.m.triangles[f.face]) {
      if (locked[v] || c.rings.on_boundary(v) || is_locked(c.locked, v)) continue;
      auto it = guards.find(v);
      if (it == guards.end()) it = guards.try_emplace(v, c, v, c.ring_normal(v), pull_distance).first;
      try_pulling(c, v, z, c.sample_normal[f.w], floor, it->second, best);
    }
    if (best.v == kInvalidIndex) continue;
    c.move(best.v, best.y);
    ++pulled;
    c.rings.mark_ring(c.m, best.v, locked);
    for (Index h : c.rings.around(best.v))
      for (Index u : c.m.triangles[face_of(h)])
        for (Index k : c.rings.around(u))
          for (Index w : c.m.triangles[face_of(k)]) guards.erase(w);
  }
  return pulled;
}

}  // namespace

std::size_t pull_towards_far_samples(SmoothingContext& c, double pull_distance) {
  std::size_t pulled = 0;
  for (int round = 0; round < 2; ++round) {
    const std::size_t n = pull_round(c, pull_distance);
    pulled += n;
    if (n == 0) break;
  }
  return pulled;
}

}  // namespace gsp::cvt::detail
