#include "refine.hpp"
#include "point_grid.hpp"
#include "triangle_geometry.hpp"

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

double triangle_distance(Vec3 z, Vec3 a, Vec3 b, Vec3 c) {
  const std::array<double, 3> w = closest_point_on_triangle(z, a, b, c);
  return distance(z, w[0] * a + w[1] * b + w[2] * c);
}

// The mesh with its directed edges and faces per vertex kept up to date through splits and
// flips, and a log to undo the edits of one tried insertion.
class EditableMesh {
 public:
  explicit EditableMesh(TriangleMesh& m) : m_(m), faces_of_(m.num_vertices()) {
    directed_.reserve(3 * m.num_faces());
    for (Index f = 0; f < m.num_faces(); ++f) link(f);
  }
  const TriangleMesh& mesh() const { return m_; }
  const std::vector<Index>& faces_of(Index v) const { return faces_of_[v]; }
  // The face with directed edge (a, b), or kInvalidIndex.
  Index face_with(Index a, Index b) const {
    const auto it = directed_.find(edge_key(a, b));
    return it == directed_.end() ? kInvalidIndex : it->second;
  }
  bool edge_exists(Index a, Index b) const { return face_with(a, b) != kInvalidIndex || face_with(b, a) != kInvalidIndex; }

  void begin() {
    old_.clear();
    faces0_ = m_.num_faces(), vertices0_ = m_.num_vertices();
  }
  Index add_vertex(Vec3 p) {
    m_.positions.push_back(p);
    faces_of_.emplace_back();
    return Index(m_.positions.size() - 1);
  }
  void set(Index f, const Triangle& t) {
    if (f < faces0_ && std::none_of(old_.begin(), old_.end(), [&](const auto& o) { return o.first == f; }))
      old_.push_back({f, m_.triangles[f]});
    unlink(f);
    m_.triangles[f] = t;
    link(f);
  }
  Index add(const Triangle& t) {
    m_.triangles.push_back(t);
    link(Index(m_.triangles.size() - 1));
    return Index(m_.triangles.size() - 1);
  }
  // The faces changed since begin(): edited ones and added ones.
  std::vector<Index> changed() const {
    std::vector<Index> c;
    for (const auto& o : old_) c.push_back(o.first);
    for (Index f = Index(faces0_); f < m_.num_faces(); ++f) c.push_back(f);
    return c;
  }
  // The triangles the changed ones replaced.
  std::vector<Triangle> replaced() const {
    std::vector<Triangle> r;
    for (const auto& o : old_) r.push_back(o.second);
    return r;
  }
  void rollback() {
    for (Index f = Index(faces0_); f < m_.num_faces(); ++f) unlink(f);
    for (const auto& o : old_) unlink(o.first);
    m_.triangles.resize(faces0_);
    for (const auto& o : old_) {
      m_.triangles[o.first] = o.second;
      link(o.first);
    }
    m_.positions.resize(vertices0_);
    faces_of_.resize(vertices0_);
    old_.clear();
  }

 private:
  void link(Index f) {
    const Triangle& t = m_.triangles[f];
    for (Index k = 0; k < 3; ++k) {
      directed_[edge_key(t[k], t[(k + 1) % 3])] = f;
      faces_of_[t[k]].push_back(f);
    }
  }
  void unlink(Index f) {
    const Triangle& t = m_.triangles[f];
    for (Index k = 0; k < 3; ++k) {
      const auto it = directed_.find(edge_key(t[k], t[(k + 1) % 3]));
      if (it != directed_.end() && it->second == f) directed_.erase(it);
      std::vector<Index>& fs = faces_of_[t[k]];
      const auto jt = std::find(fs.begin(), fs.end(), f);
      if (jt != fs.end()) fs.erase(jt);
    }
  }
  TriangleMesh& m_;
  std::unordered_map<std::uint64_t, Index> directed_;
  std::vector<std::vector<Index>> faces_of_;
  std::vector<std::pair<Index, Triangle>> old_;
  std::size_t faces0_ = 0, vertices0_ = 0;
};

}  // namespace

RefineResult insert_at_far_points(TriangleMesh& m, const TriangleMesh& surface, const RefineParams& p) {
  RefineResult result;
  result.touched.assign(m.num_vertices(), false);
  if (!(p.bound > 0) || p.max_inserted == 0 || m.triangles.empty()) return result;
  const std::vector<Vec3>& points = surface.positions;
  std::vector<Vec3> point_normal(points.size());   // area-weighted
  for (const Triangle& t : surface.triangles) {
    const Vec3 n = normal(surface.positions[t[0]], surface.positions[t[1]], surface.positions[t[2]]);
    for (Index w : t) point_normal[w] = point_normal[w] + n;
  }
  double mean_edge = 0;
  for (const Triangle& t : m.triangles) mean_edge += distance(m.positions[t[0]], m.positions[t[1]]);
  mean_edge /= double(m.num_faces());
  const double floor_limit = p.floor_angle_deg * kPi / 180.0;
  const double fold_cos = std::cos(150.0 * kPi / 180.0);
  // Built when a first point is far: most remeshes have none.
  std::unique_ptr<ClosestPointIndex> own_index;
  const ClosestPointIndex* surface_index = p.surface_index;
  std::unique_ptr<PointGrid> grid;
  EditableMesh em(m);

  auto face_normal = [&](const Triangle& t) { return normal(m.positions[t[0]], m.positions[t[1]], m.positions[t[2]]); };
  auto face_min_angle = [&](const Triangle& t) { return min_angle(m.positions[t[0]], m.positions[t[1]], m.positions[t[2]]); };
  // Largest distance to the surface of a triangle's centroid and edge midpoints.
  auto deviation = [&](const Triangle& t) {
    const Vec3 a = m.positions[t[0]], b = m.positions[t[1]], c = m.positions[t[2]];
    double d = 0;
    for (Vec3 s : {(a + b + c) * (1.0 / 3), 0.5 * (a + b), 0.5 * (b + c), 0.5 * (c + a)})
      d = std::max(d, surface_index->closest(s).distance);
    return d;
  };

  // Flips the edges opposite the new vertex v where that raises the smaller of the pair's
  // smallest angles, the new pair faces the way the old one does, and the new edge's midpoint
  // stays within max(max_deviation, the old one's distance) of the surface.
  auto flip_around = [&](Index v) {
    std::size_t flips = 0;
    for (int sweep = 0; sweep < 8; ++sweep) {
      bool any = false;
      const std::vector<Index> ring = em.faces_of(v);
      for (Index f : ring) {
        Triangle t = m.triangles[f];
        while (t[2] != v) t = {t[1], t[2], t[0]};
        const Index a = t[0], b = t[1];
        const Index g = em.face_with(b, a);
        if (g == kInvalidIndex) continue;
        const Triangle& tg = m.triangles[g];
        Index d = kInvalidIndex;
        for (Index k = 0; k < 3; ++k)
          if (tg[k] != a && tg[k] != b) d = tg[k];
        if (d == kInvalidIndex || d == v || em.edge_exists(v, d)) continue;
        const Vec3 pa = m.positions[a], pb = m.positions[b], pv = m.positions[v], pd = m.positions[d];
        const double before = std::min(min_angle(pa, pb, pv), min_angle(pb, pa, pd));
        const double after = std::min(min_angle(pa, pd, pv), min_angle(pd, pb, pv));
        if (after <= before + 1e-9) continue;
        const Vec3 n = normal(pa, pb, pv) + normal(pb, pa, pd);
        if (dot(normal(pa, pd, pv), n) <= 0 || dot(normal(pd, pb, pv), n) <= 0) continue;
        if (surface_index->closest(0.5 * (pv + pd)).distance >
            std::max(p.max_deviation, surface_index->closest(0.5 * (pa + pb)).distance))
          continue;
        em.set(f, {a, d, v});
        em.set(g, {d, b, v});
        ++flips, any = true;
      }
      if (!any) break;
    }
    return flips;
  };

  // Checks the edits since em.begin() (new vertex at z, `reference`: the normal of the faces it
  // replaced); returns the smallest angle of the changed triangles, or -1 if they break a rule.
  auto judge = [&](Vec3 z, Vec3 reference, double floor_angle) {
    const std::vector<Index> changed = em.changed();
    const std::vector<Triangle> replaced = em.replaced();
    double worst = 10;
    for (Index f : changed) {
      const Triangle& t = m.triangles[f];
      // No fold: across each of its edges the triangle turns by at most 150 degrees. Whether it
      // faces the way the face it replaced did says nothing near a spike (the tent from a tip
      // that overhangs the face turns by 90 degrees and more, and is right to), nor does the
      // input's normal near a talon (it turns round within a fraction of an edge).
      const Vec3 n = face_normal(t);
      for (Index k = 0; k < 3; ++k) {
        const Index g = em.face_with(t[(k + 1) % 3], t[k]);
        if (g == kInvalidIndex) continue;
        const Vec3 ng = face_normal(m.triangles[g]);
        if (dot(n, ng) < fold_cos * norm(n) * norm(ng)) return -1.0;
      }
      worst = std::min(worst, face_min_angle(t));
    }
    if (worst < floor_angle) return -1.0;
    double dev0 = 0;
    for (const Triangle& t : replaced) dev0 = std::max(dev0, deviation(t));
    for (Index f : changed)
      if (deviation(m.triangles[f]) > std::max(p.max_deviation, dev0)) return -1.0;
    // The input near the change: no point of it (on this sheet) farther than max(bound, before)
    // from the changed triangles and the ones around them.
    std::vector<Index> ring;
    double reach = 0;
    for (Index f : changed)
      for (Index u : m.triangles[f]) {
        reach = std::max(reach, distance(z, m.positions[u]));
        for (Index h : em.faces_of(u))
          if (std::find(changed.begin(), changed.end(), h) == changed.end()) ring.push_back(h);
      }
    std::sort(ring.begin(), ring.end());
    ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
    bool ok = true;
    grid->near(z, reach + p.bound, [&](Index w) {
      if (!ok || dot(point_normal[w], reference) <= 0) return;
      const Vec3 q = points[w];
      double rest = 1e300;
      for (Index h : ring) {
        const Triangle& t = m.triangles[h];
        rest = std::min(rest, triangle_distance(q, m.positions[t[0]], m.positions[t[1]], m.positions[t[2]]));
      }
      if (rest <= p.bound) return;
      double before = rest, after = rest;
      for (const Triangle& t : replaced)
        before = std::min(before, triangle_distance(q, m.positions[t[0]], m.positions[t[1]], m.positions[t[2]]));
      for (Index f : changed) {
        const Triangle& t = m.triangles[f];
        after = std::min(after, triangle_distance(q, m.positions[t[0]], m.positions[t[1]], m.positions[t[2]]));
      }
      if (after > std::max(p.bound, before) + 1e-12 * p.bound) ok = false;
    });
    return ok ? worst : -1.0;
  };

  // The floor of the mesh as it came, less the slack the caller's moves are to win back.
  double mesh_min = 10;
  for (const Triangle& t : m.triangles) mesh_min = std::min(mesh_min, face_min_angle(t));
  result.floor = std::min(mesh_min, floor_limit);
  const double floor_angle = result.floor - p.slack_deg * kPi / 180.0;
  std::vector<int> stamp(m.num_faces(), -1);
  std::vector<Index> still_far;
  for (int round = 0; round < p.rounds && result.inserted < p.max_inserted; ++round) {
    const ClosestPointIndex out(m);
    struct Far {
      double d;
      Index w, face;
    };
    // The whole input the first time; after that only the points that were far (an insertion
    // never carries a point beyond max(bound, before)).
    std::vector<Far> far;
    auto look = [&](Index w) {
      const SurfacePoint sp = out.closest(points[w]);
      if (sp.face != kInvalidIndex && sp.distance > p.bound) far.push_back({sp.distance, w, sp.face});
    };
    if (round == 0)
      for (Index w = 0; w < points.size(); ++w) look(w);
    else
      for (Index w : still_far) look(w);
    still_far.clear();
    for (const Far& f : far) still_far.push_back(f.w);
    if (far.empty()) break;
    std::sort(far.begin(), far.end(), [](const Far& a, const Far& b) { return a.d > b.d || (a.d == b.d && a.w < b.w); });
    if (!surface_index) own_index = std::make_unique<ClosestPointIndex>(surface), surface_index = own_index.get();
    if (!grid) grid = std::make_unique<PointGrid>(points, mean_edge);
    std::vector<Vec3> placed;   // this round's new vertices: the index does not know them
    std::size_t inserted_here = 0;
    for (const Far& fp : far) {
      if (result.inserted >= p.max_inserted) break;
      const Vec3 z = points[fp.w];
      if (p.skip && (*p.skip)[fp.w]) continue;
      if (std::any_of(placed.begin(), placed.end(), [&](Vec3 q) { return distance(q, z) < 2 * mean_edge; })) continue;
      // Candidates: a face near z split at z (k = -1), or the interior edge of the nearest face
      // opposite its corner k when z lies near that edge. Not only the nearest face: a spike's
      // tip is nearest to the mesh beside the spike's base, and the tent from that face's corners
      // overhangs; the face around the base makes a tent that holds the spike.
      std::vector<Index> faces{fp.face};
      for (Index u : m.triangles[fp.face])
        for (Index h : em.faces_of(u))
          for (Index x : m.triangles[h])
            for (Index h2 : em.faces_of(x)) faces.push_back(h2);
      std::sort(faces.begin() + 1, faces.end());
      faces.erase(std::unique(faces.begin() + 1, faces.end()), faces.end());
      double best = -1;
      Index best_face = kInvalidIndex;
      int best_k = -2;
      std::size_t flips = 0;
      auto apply = [&](Index face, int k) -> Vec3 {   // returns the replaced faces' normal
        const Triangle t = m.triangles[face];
        const Vec3 nf = face_normal(t);
        em.begin();
        const Index v = em.add_vertex(z);
        if (k < 0) {
          em.set(face, {t[0], t[1], v});
          em.add({t[1], t[2], v});
          em.add({t[2], t[0], v});
          flips = flip_around(v);
          return nf;
        }
        const Index a = t[(k + 1) % 3], b = t[(k + 2) % 3], c = t[k];
        const Index g = em.face_with(b, a);
        const Triangle tg = m.triangles[g];
        Index d = kInvalidIndex;
        for (Index j = 0; j < 3; ++j)
          if (tg[j] != a && tg[j] != b) d = tg[j];
        const Vec3 ref = nf + face_normal(tg);
        em.set(face, {a, v, c});
        em.add({v, b, c});
        em.set(g, {b, v, d});
        em.add({v, a, d});
        flips = flip_around(v);
        return ref;
      };
      for (std::size_t i = 0; i < faces.size(); ++i) {
        const Index face = faces[i];
        if (i > 0 && face == fp.face) continue;
        const Triangle t = m.triangles[face];
        if (stamp[face] == round) continue;
        const Vec3 nf = face_normal(t);
        if (dot(nf, point_normal[fp.w]) <= 0) continue;   // on another sheet
        const std::array<double, 3> bary =
            closest_point_on_triangle(z, m.positions[t[0]], m.positions[t[1]], m.positions[t[2]]);
        if (triangle_distance(z, m.positions[t[0]], m.positions[t[1]], m.positions[t[2]]) > fp.d + mean_edge) continue;
        for (int k = -1; k < 3; ++k) {
          if (k >= 0) {
            if (i > 0 || bary[k] > 0.25) continue;
            const Index g = em.face_with(t[(k + 2) % 3], t[(k + 1) % 3]);
            if (g == kInvalidIndex || g == face || stamp[g] == round) continue;
          }
          const Vec3 ref = apply(face, k);
          const double score = judge(z, ref, floor_angle);
          em.rollback();
          if (score > best) best = score, best_face = face, best_k = k;
        }
      }
      if (best_k < -1) continue;
      apply(best_face, best_k);
      result.flips += flips;
      for (Index f : em.changed()) {
        if (f >= stamp.size()) stamp.resize(f + 1, -1);
        stamp[f] = round;
        for (Index u : m.triangles[f]) {
          if (u >= result.touched.size()) result.touched.resize(u + 1, false);
          result.touched[u] = true;
        }
      }
      em.begin();   // commit
      placed.push_back(z);
      result.points.push_back(fp.w);
      ++result.inserted, ++inserted_here;
    }
    if (inserted_here == 0) break;
  }
  result.touched.resize(m.num_vertices(), false);
  return result;
}

SettledRefinement refine_and_settle(TriangleMesh& mesh, const TriangleMesh& surface, const BoundaryCurves& curves,
                                    const SmoothParams& smooth, RefineParams params) {
  SettledRefinement out;
  std::vector<bool> skip(surface.num_vertices(), false);
  params.skip = &skip;
  const TriangleMesh before = mesh;
  for (int attempt = 0; attempt < 3; ++attempt) {
    params.slack_deg = attempt < 2 ? 10.0 : 0.0;
    const RefineResult added = insert_at_far_points(mesh, surface, params);
    if (added.inserted == 0) break;
    SmoothParams again = smooth;
    again.cap_flips = false;
    again.pull_distance = 0;
    again.only = &added.touched;
    const SmoothCounts c = smooth_vertices(mesh, surface, surface, curves, again);
    // New vertices with a triangle below the floor within one ring.
    const std::size_t first = before.num_vertices();
    std::vector<bool> bad(mesh.num_vertices(), false), near_bad(mesh.num_vertices(), false);
    for (const Triangle& t : mesh.triangles)
      if (min_angle(mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]]) < added.floor)
        for (Index v : t) bad[v] = true;
    for (const Triangle& t : mesh.triangles)
      if (bad[t[0]] || bad[t[1]] || bad[t[2]])
        for (Index v : t) near_bad[v] = true;
    bool failed = false;
    for (std::size_t i = 0; i < added.points.size(); ++i)
      if (near_bad[first + i]) skip[added.points[i]] = true, failed = true;
    if (failed && attempt < 2) {
      mesh = before;
      continue;
    }
    out.inserted = added.inserted;
    out.flips = added.flips + c.flips;
    out.moves = c.moves;
    out.boundary_moves = c.boundary_moves;
    break;
  }
  return out;
}

}  // namespace gsp::cvt::detail
