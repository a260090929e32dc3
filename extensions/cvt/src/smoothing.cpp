#include "smoothing.hpp"
#include "triangle_geometry.hpp"

#include "boundary_curves.hpp"
#include "flips.hpp"
#include "point_grid.hpp"

#include <gsp/connectivity.hpp>
#include <gsp/cvt/closest_point_index.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <unordered_map>
#include <vector>

namespace gsp::cvt::detail {

namespace {

constexpr double kPi = 3.14159265358979323846;

}  // namespace

SmoothCounts smooth_vertices(TriangleMesh& m, const TriangleMesh& surface, const TriangleMesh& samples,
                             const BoundaryCurves& curves,
                             const SmoothParams& p) {
  SmoothCounts counts;
  std::unique_ptr<ClosestPointIndex> own_index;
  if (!p.surface_index) own_index = std::make_unique<ClosestPointIndex>(surface);
  const ClosestPointIndex& index = p.surface_index ? *p.surface_index : *own_index;
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

  // The unit normal of the surface at a point of it (its face's), and at each vertex.
  auto surface_normal = [&](const SurfacePoint& sp) {
    if (sp.face == kInvalidIndex) return Vec3{};
    const Triangle& st = surface.triangles[sp.face];
    const Vec3 n = cross(surface.positions[st[1]] - surface.positions[st[0]], surface.positions[st[2]] - surface.positions[st[0]]);
    const double l = norm(n);
    return l > 0 ? (1.0 / l) * n : Vec3{};
  };
  std::vector<Vec3> surf_n(V);
  for (std::size_t v = 0; v < V; ++v) surf_n[v] = surface_normal(index.closest(m.positions[v]));

  // The worst angle of v's triangles with v at x (`nx`: the surface's normal there), signed:
  // negative for a triangle that faces against the surface (its normal against the sum of the
  // surface normals at its corners, where these agree: not across a slit or a thin wall; the
  // dual folds so where a site lies beyond the edge of its neighbours, and its angles say
  // nothing then). -10 if the move folds a triangle: turns its normal by more than 40
  // degrees, unless it then faces the surface at all three corners. A sliver's normal turns
  // that much under any move (on falconstatue's base at 2,000 sites a 171-degree cap across
  // the bottom rim could not open towards the bottom), and a folded triangle must turn over
  // to unfold.
  auto quality = [&](Index v, Vec3 x, bool check_fold, Vec3 nx) {
    double worst = 10;
    for (Index c = corner_begin[v]; c < corner_begin[v + 1]; ++c) {
      const Triangle& t = m.triangles[face_of(corners[c])];
      const Index k = corner_of(corners[c]);
      Vec3 q[3] = {m.positions[t[0]], m.positions[t[1]], m.positions[t[2]]};
      Vec3 s[3] = {surf_n[t[0]], surf_n[t[1]], surf_n[t[2]]};
      const Vec3 before = cross(q[1] - q[0], q[2] - q[0]);
      q[k] = x, s[k] = nx;
      const Vec3 after = cross(q[1] - q[0], q[2] - q[0]);
      if (check_fold && dot(before, after) <= fold_cos * norm(before) * norm(after) &&
          !(dot(after, s[0]) > 0 && dot(after, s[1]) > 0 && dot(after, s[2]) > 0))
        return -10.0;
      const double a = min_angle(q[0], q[1], q[2]);
      const Vec3 sum = s[0] + s[1] + s[2];
      worst = std::min(worst, norm(sum) >= 2.0 && dot(after, sum) < 0 ? -a : a);
    }
    return worst;
  };
  // The plain (unsigned) worst angle of v's triangles with v at x: what the quality figures
  // measure. A move never lowers it, whatever the signs.
  auto plain_quality = [&](Index v, Vec3 x) {
    double worst = 10;
    for (Index c = corner_begin[v]; c < corner_begin[v + 1]; ++c) {
      const Triangle& t = m.triangles[face_of(corners[c])];
      Vec3 q[3] = {m.positions[t[0]], m.positions[t[1]], m.positions[t[2]]};
      q[corner_of(corners[c])] = x;
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
  // Distance from z to the triangles around v's neighbours that are not v's: they stay where
  // they are when v moves, and an upper bound of the distance to the rest of the mesh.
  auto rest_distance = [&](Index v, Vec3 z) {
    double d = 1e300;
    for (Index c = corner_begin[v]; c < corner_begin[v + 1]; ++c)
      for (Index u : m.triangles[face_of(corners[c])]) {
        if (u == v) continue;
        for (Index k = corner_begin[u]; k < corner_begin[u + 1]; ++k) {
          const Triangle& t = m.triangles[face_of(corners[k])];
          if (t[0] == v || t[1] == v || t[2] == v) continue;
          const std::array<double, 3> w = closest_point_on_triangle(z, m.positions[t[0]], m.positions[t[1]], m.positions[t[2]]);
          d = std::min(d, distance(z, w[0] * m.positions[t[0]] + w[1] * m.positions[t[1]] + w[2] * m.positions[t[2]]));
        }
      }
    return d;
  };
  // The points under_points finds that a move of v could carry farther than max(bound, before)
  // from the mesh, and their distances to v's triangles before. A point the other triangles
  // around already keep within that bound stays within it whatever v does; checking it
  // against v's triangles alone blocked moves of vertices with long edges: on falconstatue's
  // base at 2,000 sites wall points 0.03-0.08 (6-17 times the bound) from a sliver's ring,
  // covered by their own triangles, grew by 1e-8 and refused every move.
  auto watched_points = [&](Index v, Vec3 x0, Vec3 normal, double bound, std::vector<Vec3>& kept,
                            std::vector<double>& before) {
    kept.clear(), before.clear();
    for (Vec3 z : under_points(v, x0, normal)) {
      const double d = ring_distance(v, z, x0);
      if (rest_distance(v, z) <= std::max(bound, d)) continue;
      kept.push_back(z), before.push_back(d);
    }
  };

  // A vertex is tried again only when its triangles changed since its last try (a neighbour
  // moved, a flip): the search is deterministic, it would find nothing new.
  std::vector<bool> dirty(V, true);
  if (p.only) dirty = *p.only, dirty.resize(V, false);
  if (p.flip_max_normal_angle >= 0 && p.cap_flips) {
    // The surface checks of a cap flip, both ways: the new edge's midpoint within
    // max(max_deviation, the old one's distance) of the input, and the input under the old pair
    // within max(max_deviation, before) of the new pair: the point nearest the old edge's
    // midpoint and every sample vertex near the pair whose nearest output triangle is one of the
    // two (an Embree index over the output, rebuilt after each flip). With the midpoint's point
    // alone a flip across camelhead's mouth slit at 2,000 sites uncovered the slit's far end: a
    // working vertex 0.7% of the diagonal from the old pair was 1.0% from the new one (the
    // two-sided Hausdorff distance 0.94% -> 1.00%).
    auto out = std::make_unique<ClosestPointIndex>(m);
    auto pair_distance = [](Vec3 z, Vec3 p0, Vec3 p1, Vec3 p2, Vec3 p3) {   // to (p0,p1,p2) and (p0,p1,p3)
      const std::array<double, 3> u = closest_point_on_triangle(z, p0, p1, p2), w = closest_point_on_triangle(z, p0, p1, p3);
      return std::min(distance(z, u[0] * p0 + u[1] * p1 + u[2] * p2), distance(z, w[0] * p0 + w[1] * p1 + w[2] * p3));
    };
    auto keeps_surface = [&](Index f, Index g, Index a, Index b, Index c, Index d) {
      const Vec3 pa = m.positions[a], pb = m.positions[b], pc = m.positions[c], pd = m.positions[d];
      const Vec3 old_mid = 0.5 * (pa + pb), new_mid = 0.5 * (pc + pd);
      if (index.closest(new_mid).distance > std::max(p.max_deviation, index.closest(old_mid).distance)) return false;
      // After the flip a point is as far as the nearer of the new pair and the other triangles
      // around the quad (those farther away cannot be nearer than before: the old pair was).
      auto after = [&](Vec3 z) {
        double r = pair_distance(z, pc, pd, pa, pb);
        for (Index v : {a, b, c, d})
          for (Index k = corner_begin[v]; k < corner_begin[v + 1]; ++k) {
            const Index h = face_of(corners[k]);
            if (h == f || h == g) continue;
            const Triangle& t = m.triangles[h];
            const std::array<double, 3> w = closest_point_on_triangle(z, m.positions[t[0]], m.positions[t[1]], m.positions[t[2]]);
            r = std::min(r, distance(z, w[0] * m.positions[t[0]] + w[1] * m.positions[t[1]] + w[2] * m.positions[t[2]]));
          }
        return r;
      };
      auto stays = [&](Vec3 z) { return after(z) <= std::max(p.max_deviation, pair_distance(z, pa, pb, pc, pd)); };
      if (!stays(index.closest(old_mid).position)) return false;
      const Vec3 centre = 0.25 * (pa + pb + pc + pd);
      double reach = 0;
      for (Vec3 q : {pa, pb, pc, pd}) reach = std::max(reach, distance(centre, q));
      bool ok = true;
      grid.near(centre, reach + p.max_deviation, [&](Index w) {
        if (!ok) return;
        const Vec3 z = samples.positions[w];
        const Index nearest_face = out->closest(z).face;
        if (nearest_face == f || nearest_face == g) ok = stays(z);
      });
      return ok;
    };
    const std::size_t caps = remove_caps(m, 120.0, keeps_surface, [&] {
      out = std::make_unique<ClosestPointIndex>(m);
      rebuild();
    });
    counts.flips += caps;
  }
  for (int pass = 0; pass < p.passes; ++pass) {
    std::size_t moved = 0;
    for (Index v = 0; v < V; ++v) {
      if (corner_begin[v] == corner_begin[v + 1] || !dirty[v]) continue;
      dirty[v] = false;
      const Vec3 x0 = m.positions[v];
      const double q0 = quality(v, x0, false, surf_n[v]);
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
        watched_points(v, x0, normal, p.max_deviation, under, under_before);
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
          const double q = quality(v, y, true, surface_normal(index.closest(y)));
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
          const double q = quality(v, sp.position, true, surface_normal(sp));
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
      if (best <= q0 + 1e-9 || plain_quality(v, x) < plain_quality(v, x0)) continue;
      m.positions[v] = x;
      surf_n[v] = surface_normal(index.closest(x));
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
        const double q0 = quality(v, x0, false, surf_n[v]), dev0 = deviation(v, x0);
        std::vector<Vec3> under;
        std::vector<double> under_before;
        bool watched = false;
        // Part of the way towards z, on the surface: the whole way mostly folds a triangle.
        for (double t : {1.0, 0.75, 0.5, 0.35, 0.25}) {
          const SurfacePoint sp = index.closest(x0 + t * (z - x0));
          if (sp.face == kInvalidIndex) continue;
          const Vec3 y = sp.position;
          const double dz = ring_distance(v, z, y);
          if (dz >= 0.98 * best_d) continue;
          // No new angle below 30 degrees nor below the mesh's minimum.
          if (quality(v, y, true, surface_normal(sp)) < std::min(q0, std::max(mesh_min, 30.0 * kPi / 180.0)) ||
              plain_quality(v, y) < std::min(plain_quality(v, x0), std::max(mesh_min, 30.0 * kPi / 180.0)))
            continue;
          if (deviation(v, y) > std::max(dev0, p.pull_distance)) continue;
          if (!watched) watched_points(v, x0, normal, p.pull_distance, under, under_before), watched = true;
          bool ok = true;
          for (std::size_t i = 0; i < under.size() && ok; ++i)
            ok = ring_distance(v, under[i], y) <= std::max(under_before[i], p.pull_distance);
          if (ok) best_v = v, best_d = dz, best_y = y;
        }
      }
      if (best_v == kInvalidIndex) continue;
      m.positions[best_v] = best_y;
      surf_n[best_v] = surface_normal(index.closest(best_y));
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
