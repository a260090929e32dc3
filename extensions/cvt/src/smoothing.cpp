#include "smoothing.hpp"
#include "triangle_geometry.hpp"

#include "boundary_curves.hpp"
#include "flips.hpp"

#include <gsp/connectivity.hpp>
#include <gsp/cvt/closest_point_index.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <unordered_map>
#include <vector>

namespace gsp::cvt::detail {

namespace {

constexpr double kPi = 3.14159265358979323846;

// Points hashed into cubes of side `cell`, for the points within a radius of a query.
class PointGrid {
 public:
  PointGrid(const std::vector<Vec3>& points, double cell) : points_(points), cell_(cell > 0 ? cell : 1.0) {
    for (Index i = 0; i < points.size(); ++i) cells_[cell_key(points[i])].push_back(i);
  }
  template <class Fn>
  void near(Vec3 p, double r, Fn&& fn) const {
    const long long x0 = coord(p.x - r), x1 = coord(p.x + r), y0 = coord(p.y - r), y1 = coord(p.y + r),
                    z0 = coord(p.z - r), z1 = coord(p.z + r);
    for (long long x = x0; x <= x1; ++x)
      for (long long y = y0; y <= y1; ++y)
        for (long long z = z0; z <= z1; ++z) {
          const auto it = cells_.find(pack(x, y, z));
          if (it == cells_.end()) continue;
          for (Index i : it->second)
            if (distance(points_[i], p) <= r) fn(i);
        }
  }

 private:
  long long coord(double v) const { return static_cast<long long>(std::floor(v / cell_)); }
  static std::uint64_t pack(long long x, long long y, long long z) {
    return (std::uint64_t(x & 0x1FFFFF) << 42) | (std::uint64_t(y & 0x1FFFFF) << 21) | std::uint64_t(z & 0x1FFFFF);
  }
  std::uint64_t cell_key(Vec3 p) const { return pack(coord(p.x), coord(p.y), coord(p.z)); }
  const std::vector<Vec3>& points_;
  double cell_;
  std::unordered_map<std::uint64_t, std::vector<Index>> cells_;
};

}  // namespace

SmoothCounts smooth_vertices(TriangleMesh& m, const TriangleMesh& surface, const TriangleMesh& samples,
                             const BoundaryCurves& curves,
                             const SmoothParams& p) {
  SmoothCounts counts;
  const ClosestPointIndex index(surface);
  double mean_edge = 0;
  for (const Triangle& t : m.triangles) mean_edge += distance(m.positions[t[0]], m.positions[t[1]]);
  mean_edge /= double(std::max<std::size_t>(1, m.num_faces()));
  const PointGrid grid(samples.positions, mean_edge);
  std::vector<Vec3> sample_normal(samples.num_vertices());   // area-weighted, not normalised
  for (const Triangle& t : samples.triangles) {
    const Vec3 n = cross(samples.positions[t[1]] - samples.positions[t[0]], samples.positions[t[2]] - samples.positions[t[0]]);
    for (Index w : t) sample_normal[w] = sample_normal[w] + n;
  }
  const double below = p.below_angle * kPi / 180.0;
  const double fold_cos = std::cos(40.0 * kPi / 180.0);
  const std::size_t V = m.num_vertices();

  // Boundary vertices of the dual on the surface's boundary curves: (loop, arc length).
  std::vector<std::size_t> loop_of(V, std::size_t(-1));
  std::vector<double> arc(V, 0);
  std::vector<Index> corner_begin, corners;
  std::vector<Index> next_b(V), prev_b(V);
  std::unordered_map<std::uint64_t, Index> directed;

  auto rebuild = [&] {
    corner_begin.assign(V + 1, 0);
    for (const Triangle& t : m.triangles)
      for (Index v : t) ++corner_begin[v + 1];
    for (std::size_t v = 0; v < V; ++v) corner_begin[v + 1] += corner_begin[v];
    corners.assign(corner_begin.back(), 0);
    std::vector<Index> fill(corner_begin.begin(), corner_begin.end() - 1);
    for (Index f = 0; f < m.num_faces(); ++f)
      for (Index i = 0; i < 3; ++i) corners[fill[m.triangles[f][i]]++] = 3 * f + i;
    directed.clear();
    for (Index f = 0; f < m.num_faces(); ++f)
      for (Index i = 0; i < 3; ++i) directed[edge_key(m.triangles[f][i], m.triangles[f][(i + 1) % 3])] = f;
    BoundaryLinks links = boundary_links(m, directed);
    next_b = std::move(links.next);
    prev_b = std::move(links.prev);
    const std::vector<int>& out_count = links.out_count;
    // A vertex where the boundary passes twice is left where it is.
    for (std::size_t v = 0; v < V; ++v)
      if (out_count[v] > 1) next_b[v] = prev_b[v] = kInvalidIndex;
  };
  rebuild();
  if (!curves.loops.empty()) {
    for (std::size_t v = 0; v < V; ++v) {
      if (next_b[v] == kInvalidIndex) continue;
      std::size_t l = 0;
      double s = 0, d = 0;
      if (curves.project(m.positions[v], l, s, d) && d <= 1e-3 * distance(m.positions[v], m.positions[next_b[v]]))
        loop_of[v] = l, arc[v] = s;
    }
  }

  // The worst angle of v's triangles with v at x, or -1 if one of them folds against its
  // normal before the move.
  auto quality = [&](Index v, Vec3 x, bool check_fold) {
    double worst = 10;
    for (Index c = corner_begin[v]; c < corner_begin[v + 1]; ++c) {
      const Triangle& t = m.triangles[face_of(corners[c])];
      Vec3 q[3] = {m.positions[t[0]], m.positions[t[1]], m.positions[t[2]]};
      const Vec3 before = cross(q[1] - q[0], q[2] - q[0]);
      q[corner_of(corners[c])] = x;
      const Vec3 after = cross(q[1] - q[0], q[2] - q[0]);
      if (check_fold && dot(before, after) <= fold_cos * norm(before) * norm(after)) return -1.0;
      worst = std::min(worst, min_angle(q[0], q[1], q[2]));
    }
    return worst;
  };
  // Largest distance to the surface of the centroids of v's triangles and the midpoints of
  // their edges at v, with v at x.
  auto deviation = [&](Index v, Vec3 x) {
    double worst = 0;
    for (Index c = corner_begin[v]; c < corner_begin[v + 1]; ++c) {
      const Triangle& t = m.triangles[face_of(corners[c])];
      const Index k = corner_of(corners[c]);
      const Vec3 b = m.positions[t[(k + 1) % 3]], d = m.positions[t[(k + 2) % 3]];
      for (Vec3 s : {(x + b + d) * (1.0 / 3), 0.5 * (x + b), 0.5 * (x + d)})
        worst = std::max(worst, index.closest(s).distance);
    }
    return worst;
  };

  // Distance from point z to v's triangles with v at y.
  auto ring_distance = [&](Index v, Vec3 z, Vec3 y) {
    double d = 1e300;
    for (Index c = corner_begin[v]; c < corner_begin[v + 1]; ++c) {
      const Triangle& t = m.triangles[face_of(corners[c])];
      const Index k = corner_of(corners[c]);
      const Vec3 b = m.positions[t[(k + 1) % 3]], e = m.positions[t[(k + 2) % 3]];
      const std::array<double, 3> w = closest_point_on_triangle(z, y, b, e);
      d = std::min(d, distance(z, w[0] * y + w[1] * b + w[2] * e));
    }
    return d;
  };
  // Points of the surface under v's triangles (v at x0; `normal`: theirs): x0, the surface
  // points nearest their edge midpoints at v and centroids, and the sample mesh's vertices
  // near v whose closest point on the triangles depends on v (not on the far edges, which
  // belong to the neighbours' triangles too): the input's tips and creases are among them.
  auto under_points = [&](Index v, Vec3 x0, Vec3 normal) {
    std::vector<Vec3> under{x0};
    double reach = 0;
    for (Index c = corner_begin[v]; c < corner_begin[v + 1]; ++c) {
      const Triangle& t = m.triangles[face_of(corners[c])];
      const Index k = corner_of(corners[c]);
      const Vec3 b = m.positions[t[(k + 1) % 3]], e = m.positions[t[(k + 2) % 3]];
      reach = std::max(reach, distance(x0, b));
      for (Vec3 z : {0.5 * (x0 + b), (x0 + b + e) * (1.0 / 3)}) {
        const SurfacePoint sp = index.closest(z);
        if (sp.face != kInvalidIndex) under.push_back(sp.position);
      }
    }
    grid.near(x0, reach, [&](Index w) {
      if (dot(sample_normal[w], normal) <= 0) return;   // another sheet (a slit, a thin wall)
      const Vec3 z = samples.positions[w];
      for (Index c = corner_begin[v]; c < corner_begin[v + 1]; ++c) {
        const Triangle& t = m.triangles[face_of(corners[c])];
        const Index k = corner_of(corners[c]);
        const std::array<double, 3> wt =
            closest_point_on_triangle(z, x0, m.positions[t[(k + 1) % 3]], m.positions[t[(k + 2) % 3]]);
        if (wt[0] > 1e-9) {
          under.push_back(z);
          return;
        }
      }
    });
    return under;
  };

  // A vertex is tried again only when its triangles changed since its last try (a neighbour
  // moved, a flip): the search is deterministic, it would find nothing new.
  std::vector<bool> dirty(V, true);
  if (p.flip_max_normal_angle >= 0) {
    const std::size_t caps = remove_caps(
        m, 120.0, p.max_deviation, [&](Vec3 x) { return index.closest(x).distance; },
        [&](Vec3 x) { return index.closest(x).position; });
    counts.flips += caps;
    if (caps) rebuild();
  }
  for (int pass = 0; pass < p.passes; ++pass) {
    std::size_t moved = 0;
    for (Index v = 0; v < V; ++v) {
      if (corner_begin[v] == corner_begin[v + 1] || !dirty[v]) continue;
      dirty[v] = false;
      const Vec3 x0 = m.positions[v];
      const double q0 = quality(v, x0, false);
      if (q0 >= below) continue;
      const bool on_boundary = next_b[v] != kInvalidIndex || prev_b[v] != kInvalidIndex;
      // Mean edge length and normal at v, a basis of the tangent plane.
      Vec3 mean, normal;
      double h = 0;
      std::size_t n = 0;
      for (Index c = corner_begin[v]; c < corner_begin[v + 1]; ++c) {
        const Triangle& t = m.triangles[face_of(corners[c])];
        const Vec3 nb = m.positions[t[(corner_of(corners[c]) + 1) % 3]];
        mean = mean + nb;
        h += distance(nb, x0);
        ++n;
        normal = normal + cross(m.positions[t[1]] - m.positions[t[0]], m.positions[t[2]] - m.positions[t[0]]);
      }
      const double nn = norm(normal);
      if (nn == 0 || h == 0) continue;
      normal = (1.0 / nn) * normal;
      mean = (1.0 / double(n)) * mean;
      h /= double(n);
      const std::size_t l = loop_of[v];
      // The surface must stay close: triangle deviation for interior moves, the boundary
      // chords' deviation from the boundary curve for boundary moves. Checked for every
      // improvement the search below finds, so it finds the best point that keeps the surface.
      // The reference figures of the checks below, computed when a first candidate needs them.
      double dev0 = 0;
      std::vector<Vec3> under;
      std::vector<double> under_before;
      bool prepared = false;
      auto prepare = [&] {
        dev0 = deviation(v, x0);
        under = under_points(v, x0, normal);
        for (Vec3 z : under) under_before.push_back(ring_distance(v, z, x0));
      };
      auto close_enough = [&](Vec3 y, double sy) {
        if (!prepared) prepare(), prepared = true;
        if (on_boundary) {
          const Index a = prev_b[v], b = next_b[v];
          const double sa = arc[a], sv = arc[v], sb = arc[b];
          const double before = std::max(curves.chord_deviation(l, sa, curves.wrap(l, sv - sa)),
                                         curves.chord_deviation(l, sv, curves.wrap(l, sb - sv)));
          const double after = std::max(curves.chord_deviation(l, sa, curves.wrap(l, sy - sa)),
                                        curves.chord_deviation(l, sy, curves.wrap(l, sb - sy)));
          if (after > std::max(before, p.max_deviation)) return false;
        }
        if (deviation(v, y) > std::max(dev0, p.max_deviation)) return false;
        // The other way round: points of the surface under the old triangles (the old
        // position, the surface points nearest the old edge midpoints and centroids) must not
        // end up farther from the moved triangles than max(before, max_deviation), or a tip or
        // a crease the vertex sat on would be cut off.
        for (std::size_t i = 0; i < under.size(); ++i)
          if (ring_distance(v, under[i], y) > std::max(under_before[i], p.max_deviation)) return false;
        return true;
      };
      // The best position so far (its arc length on the boundary) and its quality.
      Vec3 x = x0;
      double sx = arc[v], best = q0;
      if (on_boundary) {
        const Index a = prev_b[v], b = next_b[v];
        if (a == kInvalidIndex || b == kInvalidIndex || l == std::size_t(-1) || loop_of[a] != l || loop_of[b] != l) continue;
        const double L = curves.loops[l].length;
        const double back = curves.wrap(l, arc[v] - arc[a]), ahead = curves.wrap(l, arc[b] - arc[v]);
        if (back + ahead > 0.75 * L) continue;   // not in the curve's order: leave it
        // Never past a neighbour: the slide stays inside (arc[a], arc[b]).
        auto try_arc = [&](double offset) {
          if (offset <= -0.9 * back || offset >= 0.9 * ahead) return false;
          const double s = curves.wrap(l, arc[v] + offset);
          const Vec3 y = curves.at(l, s);
          const double q = quality(v, y, true);
          if (q <= best + 1e-9 || !close_enough(y, s)) return false;
          best = q, x = y, sx = s;
          return true;
        };
        const double shift = 0.5 * (ahead - back);
        for (double t : {1.0, 0.5, 0.25})
          if (try_arc(t * shift)) break;
        // Then a pattern search along the curve.
        double offset = curves.wrap(l, sx - arc[v]);
        if (offset > 0.5 * L) offset -= L;
        double step = 0.1 * h;
        for (int it = 0; it < 40 && step > 0.005 * h; ++it) {
          if (try_arc(offset + step)) offset += step;
          else if (try_arc(offset - step)) offset -= step;
          else step *= 0.5;
        }
      } else {
        // A point of the surface near `target`, on the same sheet as v.
        auto try_point = [&](Vec3 target) {
          const SurfacePoint sp = index.closest(target);
          if (sp.face == kInvalidIndex || sp.distance > 0.5 * h) return false;
          const Triangle& st = surface.triangles[sp.face];
          const Vec3 sn = cross(surface.positions[st[1]] - surface.positions[st[0]],
                                surface.positions[st[2]] - surface.positions[st[0]]);
          if (dot(sn, normal) <= 0.5 * norm(sn)) return false;   // another sheet
          const double q = quality(v, sp.position, true);
          if (q <= best + 1e-9 || !close_enough(sp.position, 0.0)) return false;
          best = q, x = sp.position;
          return true;
        };
        Vec3 lap = mean - x0;
        lap = lap - dot(lap, normal) * normal;
        for (double t : {1.0, 0.5, 0.25})
          if (try_point(x0 + t * lap)) break;
        // Then a pattern search in the tangent plane (8 directions, halving steps): the
        // smallest angle is not smooth in the position, the mean of the neighbours only
        // roughly raises it.
        Vec3 e1 = cross(normal, Vec3{1, 0, 0});
        if (norm(e1) < 0.5) e1 = cross(normal, Vec3{0, 1, 0});
        e1 = (1.0 / norm(e1)) * e1;
        const Vec3 e2 = cross(normal, e1);
        double step = 0.1 * h;
        for (int it = 0; it < 60 && step > 0.005 * h; ++it) {
          bool moved_here = false;
          for (int k = 0; k < 8 && !moved_here; ++k) {
            const double phi = k * kPi / 4;
            moved_here = try_point(x + step * (std::cos(phi) * e1 + std::sin(phi) * e2));
          }
          if (!moved_here) step *= 0.5;
        }
      }
      if (best <= q0 + 1e-9) continue;
      m.positions[v] = x;
      if (on_boundary) arc[v] = sx, ++counts.boundary_moves;
      ++moved;
      for (Index c = corner_begin[v]; c < corner_begin[v + 1]; ++c)
        for (Index w : m.triangles[face_of(corners[c])]) dirty[w] = true;
    }
    counts.moves += moved;
    const std::vector<Triangle> before_flips = m.triangles;
    const std::size_t flips = p.flip_max_normal_angle < 0 ? 0 : improve_by_flips(m, p.flip_max_normal_angle);
    for (std::size_t f = 0; f < m.num_faces(); ++f)
      if (m.triangles[f] != before_flips[f])
        for (Index w : m.triangles[f]) dirty[w] = true;
    counts.flips += flips;
    if (moved == 0 && flips == 0) break;
    if (flips) rebuild();
  }
  // Pull: a sample vertex of the surface farther than pull_distance from the mesh (the dual's
  // chords cut the surface there) pulls a corner of the triangle nearest to it part of the way
  // towards it (on the surface; the position that brings it closest), if the corner is
  // interior, nothing folds, no angle falls below min(before, max(30 degrees, the mesh's
  // minimum angle)) and
  // the surface checks above hold with pull_distance as the bound (nothing else ends up
  // farther than that unless it already was). Two rounds; moved vertices and their neighbours
  // are locked within a round.
  auto pull_round = [&]() -> std::size_t {
    const ClosestPointIndex out(m);
    double mesh_min = 10;
    for (const Triangle& t : m.triangles)
      mesh_min = std::min(mesh_min, min_angle(m.positions[t[0]], m.positions[t[1]], m.positions[t[2]]));
    struct Far {
      double d;
      Index w, face;
    };
    std::vector<Far> far;
    for (Index w = 0; w < samples.num_vertices(); ++w) {
      const SurfacePoint sp = out.closest(samples.positions[w]);
      if (sp.face != kInvalidIndex && sp.distance > p.pull_distance) far.push_back({sp.distance, w, sp.face});
    }
    std::sort(far.begin(), far.end(), [](const Far& a, const Far& b) { return a.d > b.d; });
    // Only the worst spots (the Hausdorff distance is a maximum; moving a neighbour's corner
    // can help it too): within half the farthest distance, at most 2,000 points. A coarse
    // remesh is far from the surface everywhere.
    std::size_t keep = 0;
    while (keep < far.size() && keep < 2000 && far[keep].d >= 0.5 * far.front().d) ++keep;
    far.resize(keep);
    std::vector<bool> locked(V, false);
    std::size_t pulled = 0;
    for (const Far& f : far) {
      const Vec3 z = samples.positions[f.w];
      Index best_v = kInvalidIndex;
      double best_d = f.d;
      Vec3 best_y;
      for (Index v : m.triangles[f.face]) {
        if (locked[v] || next_b[v] != kInvalidIndex || prev_b[v] != kInvalidIndex) continue;
        const Vec3 x0 = m.positions[v];
        Vec3 normal;
        for (Index c = corner_begin[v]; c < corner_begin[v + 1]; ++c) {
          const Triangle& t = m.triangles[face_of(corners[c])];
          normal = normal + cross(m.positions[t[1]] - m.positions[t[0]], m.positions[t[2]] - m.positions[t[0]]);
        }
        if (dot(normal, sample_normal[f.w]) <= 0) continue;   // another sheet
        const double q0 = quality(v, x0, false), dev0 = deviation(v, x0);
        std::vector<Vec3> under;
        std::vector<double> under_before;
        // Part of the way towards z, on the surface: the whole way mostly folds a triangle.
        for (double t : {1.0, 0.75, 0.5, 0.35, 0.25}) {
          const SurfacePoint sp = index.closest(x0 + t * (z - x0));
          if (sp.face == kInvalidIndex) continue;
          const Vec3 y = sp.position;
          const double dz = ring_distance(v, z, y);
          if (dz >= 0.98 * best_d) continue;
          // No new angle below 30 degrees nor below the mesh's minimum.
          if (quality(v, y, true) < std::min(q0, std::max(mesh_min, 30.0 * kPi / 180.0))) continue;
          if (deviation(v, y) > std::max(dev0, p.pull_distance)) continue;
          if (under.empty()) {
            under = under_points(v, x0, normal);
            for (Vec3 u : under) under_before.push_back(ring_distance(v, u, x0));
          }
          bool ok = true;
          for (std::size_t i = 0; i < under.size() && ok; ++i)
            ok = ring_distance(v, under[i], y) <= std::max(under_before[i], p.pull_distance);
          if (ok) best_v = v, best_d = dz, best_y = y;
        }
      }
      if (best_v == kInvalidIndex) continue;
      m.positions[best_v] = best_y;
      ++pulled;
      for (Index c = corner_begin[best_v]; c < corner_begin[best_v + 1]; ++c)
        for (Index w : m.triangles[face_of(corners[c])]) locked[w] = true;
    }
    return pulled;
  };
  if (p.pull_distance > 0)
    for (int round = 0; round < 2; ++round) {
      const std::size_t n = pull_round();
      counts.pulls += n;
      if (n == 0) break;
    }
  return counts;
}

}  // namespace gsp::cvt::detail
