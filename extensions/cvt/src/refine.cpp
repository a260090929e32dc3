#include "refine.hpp"
#include "editable_mesh.hpp"
#include "far_points.hpp"
#include "insertion_checks.hpp"
#include "point_grid.hpp"
#include "locked_vertices.hpp"
#include "triangle_geometry.hpp"

#include <gsp/cvt/closest_point_index.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <vector>

namespace gsp::cvt::detail {

namespace {

constexpr double kPi = 3.14159265358979323846;

// A way to insert a point: `face` split at it (k = -1), or the edge of `face` opposite its
// corner k split there.
struct Split {
  Index face = kInvalidIndex;
  int k = -2;
};

// One insert_at_far_points call: the mesh under edit, the input it is to come close to, and what
// the rounds share (the floor, the faces changed in this round, the input points still far).
class FarPointInserter {
 public:
  FarPointInserter(TriangleMesh& m, const TriangleMesh& surface, const RefineParams& p, RefineResult& result);
  void run();

 private:
  std::vector<FarPoint> far_points(int round);
  void prepare_checks();
  bool insert_at(const FarPoint& fp, int round, std::vector<Vec3>& placed);
  std::vector<Index> candidate_faces(const FarPoint& fp) const;
  bool best_split(const FarPoint& fp, int round, Vec3 z, Split& best);
  Vec3 apply(Split s, Vec3 z);
  Vec3 split_face(Index face, Index v);
  Vec3 split_edge(Index face, int k, Index v);
  std::size_t flip_around(Index v);
  void commit(int round);

  TriangleMesh& m_;
  const TriangleMesh& surface_;
  const RefineParams& p_;
  RefineResult& result_;
  const std::vector<Vec3>& points_;
  const std::vector<Vec3> point_normal_;   // area-weighted
  const double mean_edge_;
  EditableMesh em_;
  double floor_angle_ = 0;
  std::unique_ptr<ClosestPointIndex> own_index_;
  const ClosestPointIndex* surface_index_;
  std::unique_ptr<PointGrid> grid_;
  std::unique_ptr<InsertionChecks> checks_;
  std::vector<int> stamp_;   // the round a face last changed in: a round changes a face once
  std::vector<Index> still_far_;
  std::size_t flips_ = 0;   // made by the last split applied
};

FarPointInserter::FarPointInserter(TriangleMesh& m, const TriangleMesh& surface, const RefineParams& p,
                                   RefineResult& result)
    : m_(m),
      surface_(surface),
      p_(p),
      result_(result),
      points_(surface.positions),
      point_normal_(vertex_normals(surface)),
      mean_edge_(mean_edge_estimate(m)),
      em_(m),
      surface_index_(p.surface_index),
      stamp_(m.num_faces(), -1) {
  // The floor of the mesh as it came, less the slack the caller's moves are to win back.
  result_.floor = std::min(mesh_min_angle(m), p.floor_angle_deg * kPi / 180.0);
  floor_angle_ = result_.floor - p.slack_deg * kPi / 180.0;
}

// Rounds until no point is far or none of the far ones can be inserted: an insertion moves
// the mesh nearer to other points, so each round looks again.
void FarPointInserter::run() {
  for (int round = 0; round < p_.rounds && result_.inserted < p_.max_inserted; ++round) {
    const std::vector<FarPoint> far = far_points(round);
    if (far.empty()) break;
    prepare_checks();
    std::vector<Vec3> placed;   // this round's new vertices: the index does not know them
    std::size_t inserted_here = 0;
    for (const FarPoint& fp : far) {
      if (result_.inserted >= p_.max_inserted) break;
      if (insert_at(fp, round, placed)) ++inserted_here;
    }
    if (inserted_here == 0) break;
  }
}

// The points farther than the bound, the worst first. The whole input the first time; after
// that only the points that were far (an insertion never carries a point beyond max(bound,
// before)).
std::vector<FarPoint> FarPointInserter::far_points(int round) {
  const ClosestPointIndex out(m_);
  std::vector<FarPoint> far;
  if (round == 0)
    for (Index w = 0; w < points_.size(); ++w) add_if_far(out, points_, w, p_.bound, far);
  else
    for (Index w : still_far_) add_if_far(out, points_, w, p_.bound, far);
  still_far_.clear();
  for (const FarPoint& f : far) still_far_.push_back(f.w);
  std::sort(far.begin(), far.end(),
            [](const FarPoint& a, const FarPoint& b) { return a.d > b.d || (a.d == b.d && a.w < b.w); });
  return far;
}

// Built when a first point is far: most remeshes have none, and the index takes a while.
void FarPointInserter::prepare_checks() {
  if (!surface_index_) own_index_ = std::make_unique<ClosestPointIndex>(surface_), surface_index_ = own_index_.get();
  if (!grid_) grid_ = std::make_unique<PointGrid>(points_, mean_edge_);
  if (!checks_) checks_ = std::make_unique<InsertionChecks>(em_, points_, point_normal_, *grid_, *surface_index_, p_);
}

// A point is left out when the caller said so, or near a vertex placed in this round (the far
// points there were measured before it came).
bool FarPointInserter::insert_at(const FarPoint& fp, int round, std::vector<Vec3>& placed) {
  const Vec3 z = points_[fp.w];
  if (p_.skip && (*p_.skip)[fp.w]) return false;
  if (std::any_of(placed.begin(), placed.end(), [&](Vec3 q) { return distance(q, z) < 2 * mean_edge_; })) return false;
  Split best;
  if (!best_split(fp, round, z, best)) return false;
  apply(best, z);
  result_.flips += flips_;
  commit(round);
  placed.push_back(z);
  result_.points.push_back(fp.w);
  ++result_.inserted;
  return true;
}

// Not only the nearest face: a spike's tip is nearest to the mesh beside the spike's base, and
// the tent from that face's corners overhangs; the face around the base makes a tent that holds
// the spike. The nearest face first, then the faces within two rings of it.
std::vector<Index> FarPointInserter::candidate_faces(const FarPoint& fp) const {
  std::vector<Index> faces{fp.face};
  for (Index u : m_.triangles[fp.face])
    for (Index h : em_.faces_of(u))
      for (Index x : m_.triangles[h])
        for (Index h2 : em_.faces_of(x)) faces.push_back(h2);
  std::sort(faces.begin() + 1, faces.end());
  faces.erase(std::unique(faces.begin() + 1, faces.end()), faces.end());
  return faces;
}

// Tries each candidate split (a face near z split at z, or the interior edge of the nearest face
// opposite its corner k when z lies near that edge) and keeps the one whose changed triangles
// have the largest smallest angle; false if every one breaks a rule.
bool FarPointInserter::best_split(const FarPoint& fp, int round, Vec3 z, Split& best) {
  const std::vector<Index> faces = candidate_faces(fp);
  double best_score = -1;
  for (std::size_t i = 0; i < faces.size(); ++i) {
    const Index face = faces[i];
    if (i > 0 && face == fp.face) continue;
    const Triangle t = m_.triangles[face];
    if (stamp_[face] == round) continue;
    const Vec3 nf = normal(m_.positions[t[0]], m_.positions[t[1]], m_.positions[t[2]]);
    if (dot(nf, point_normal_[fp.w]) <= 0) continue;   // on another sheet
    const std::array<double, 3> bary =
        closest_point_on_triangle(z, m_.positions[t[0]], m_.positions[t[1]], m_.positions[t[2]]);
    if (triangle_distance(z, m_, t) > fp.d + mean_edge_) continue;
    for (int k = -1; k < 3; ++k) {
      if (k >= 0) {
        if (i > 0 || bary[k] > 0.25) continue;
        if (is_locked_edge(p_.locked, t[(k + 1) % 3], t[(k + 2) % 3])) continue;
        const Index g = em_.face_with(t[(k + 2) % 3], t[(k + 1) % 3]);
        if (g == kInvalidIndex || g == face || stamp_[g] == round) continue;
      }
      const Vec3 ref = apply({face, k}, z);
      const double score = checks_->judge(z, ref, floor_angle_);
      em_.rollback();
      if (score > best_score) best_score = score, best = {face, k};
    }
  }
  return best.k >= -1;
}

// Starts a new edit log, so that the split can be judged and rolled back or committed; returns
// the normal of the faces it replaced, the side the input points it may serve lie on.
Vec3 FarPointInserter::apply(Split s, Vec3 z) {
  em_.begin();
  const Index v = em_.add_vertex(z);
  const Vec3 ref = s.k < 0 ? split_face(s.face, v) : split_edge(s.face, s.k, v);
  flips_ = flip_around(v);
  return ref;
}

// Three triangles round the new vertex, where it lies over the face's inside.
Vec3 FarPointInserter::split_face(Index face, Index v) {
  const Triangle t = m_.triangles[face];
  const Vec3 nf = normal(m_.positions[t[0]], m_.positions[t[1]], m_.positions[t[2]]);
  em_.set(face, {t[0], t[1], v});
  em_.add({t[1], t[2], v});
  em_.add({t[2], t[0], v});
  return nf;
}

// Four triangles round the new vertex, where it lies near the edge: a face split would make a
// sliver along it.
Vec3 FarPointInserter::split_edge(Index face, int k, Index v) {
  const Triangle t = m_.triangles[face];
  const Index a = t[(k + 1) % 3], b = t[(k + 2) % 3], c = t[k];
  const Index g = em_.face_with(b, a);
  const Triangle tg = m_.triangles[g];
  Index d = kInvalidIndex;
  for (Index j = 0; j < 3; ++j)
    if (tg[j] != a && tg[j] != b) d = tg[j];
  const Vec3 ref = normal(m_.positions[t[0]], m_.positions[t[1]], m_.positions[t[2]]) +
                   normal(m_.positions[tg[0]], m_.positions[tg[1]], m_.positions[tg[2]]);
  em_.set(face, {a, v, c});
  em_.add({v, b, c});
  em_.set(g, {b, v, d});
  em_.add({v, a, d});
  return ref;
}

// Flips the edges opposite the new vertex v where that raises the smaller of the pair's
// smallest angles, the new pair faces the way the old one does, and the new edge's midpoint
// stays within max(max_deviation, the old one's distance) of the surface: a split alone
// leaves the thin triangles a far point's tent makes.
std::size_t FarPointInserter::flip_around(Index v) {
  std::size_t flips = 0;
  for (int sweep = 0; sweep < 8; ++sweep) {
    bool any = false;
    const std::vector<Index> ring = em_.faces_of(v);
    for (Index f : ring) {
      Triangle t = m_.triangles[f];
      while (t[2] != v) t = {t[1], t[2], t[0]};
      const Index a = t[0], b = t[1];
      if (is_locked_edge(p_.locked, a, b)) continue;
      const Index g = em_.face_with(b, a);
      if (g == kInvalidIndex) continue;
      const Triangle& tg = m_.triangles[g];
      Index d = kInvalidIndex;
      for (Index k = 0; k < 3; ++k)
        if (tg[k] != a && tg[k] != b) d = tg[k];
      if (d == kInvalidIndex || d == v || em_.edge_exists(v, d)) continue;
      const Vec3 pa = m_.positions[a], pb = m_.positions[b], pv = m_.positions[v], pd = m_.positions[d];
      const double before = std::min(min_angle(pa, pb, pv), min_angle(pb, pa, pd));
      const double after = std::min(min_angle(pa, pd, pv), min_angle(pd, pb, pv));
      if (after <= before + 1e-9) continue;
      const Vec3 n = normal(pa, pb, pv) + normal(pb, pa, pd);
      if (dot(normal(pa, pd, pv), n) <= 0 || dot(normal(pd, pb, pv), n) <= 0) continue;
      if (surface_index_->closest(0.5 * (pv + pd)).distance >
          std::max(p_.max_deviation, surface_index_->closest(0.5 * (pa + pb)).distance))
        continue;
      em_.set(f, {a, d, v});
      em_.set(g, {d, b, v});
      ++flips, any = true;
    }
    if (!any) break;
  }
  return flips;
}

// Keeps the split for good: its faces are not changed again in this round, and its corners are
// the ones the caller's moves try.
void FarPointInserter::commit(int round) {
  for (Index f : em_.changed()) {
    if (f >= stamp_.size()) stamp_.resize(f + 1, -1);
    stamp_[f] = round;
    for (Index u : m_.triangles[f]) {
      if (u >= result_.touched.size()) result_.touched.resize(u + 1, false);
      result_.touched[u] = true;
    }
  }
  em_.begin();
}

// The vertices within `rings` rings of the flagged ones (flagged included).
std::vector<bool> grow_by_rings(const TriangleMesh& m, std::vector<bool> flag, int rings) {
  flag.resize(m.num_vertices(), false);
  for (int k = 0; k < rings; ++k) {
    std::vector<bool> grown = flag;
    for (const Triangle& t : m.triangles)
      if (flag[t[0]] || flag[t[1]] || flag[t[2]])
        for (Index v : t) grown[v] = true;
    flag.swap(grown);
  }
  return flag;
}

// An attempt's moves reach this many rings around the insertions: the floor is checked within
// one ring of the new vertices. Unbounded, they spread over the whole component in every
// attempt (up to three per component: half of gsp-cvt's time on CAD parts), where one pass
// over the mesh after the last attempt does the same work once (docs/cvt.md, "Settling the
// insertions").
constexpr int kSettleRings = 2;

}  // namespace

RefineResult insert_at_far_points(TriangleMesh& m, const TriangleMesh& surface, const RefineParams& p) {
  RefineResult result;
  result.touched.assign(m.num_vertices(), false);
  if (!(p.bound > 0) || p.max_inserted == 0 || m.triangles.empty()) return result;
  FarPointInserter(m, surface, p, result).run();
  result.touched.resize(m.num_vertices(), false);
  return result;
}

SettledRefinement refine_and_settle(TriangleMesh& mesh, const TriangleMesh& surface, const BoundaryCurves& curves,
                                    const SmoothParams& smooth, RefineParams params) {
  SettledRefinement out;
  std::vector<bool> skip(surface.num_vertices(), false);
  params.skip = &skip;
  const TriangleMesh before = mesh;
  SmoothParams settle = smooth;   // the moves, without the cap flips and the pulls
  settle.cap_flips = false;
  settle.pull_distance = 0;
  for (int attempt = 0; attempt < 3; ++attempt) {
    params.slack_deg = attempt < 2 ? 10.0 : 0.0;
    const RefineResult added = insert_at_far_points(mesh, surface, params);
    if (added.inserted == 0) break;
    ++out.attempts;
    SmoothParams again = settle;
    again.only = &added.touched;
    const std::vector<bool> movable = grow_by_rings(mesh, added.touched, kSettleRings);
    again.movable = &movable;
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
  // Then one pass of moves over the whole mesh: the pulls before the insertions left vertices
  // that the moves can raise again, which the moves of every attempt used to reach by
  // spreading out from the insertions (docs/cvt.md, "Settling the insertions").
  if (out.inserted > 0) {
    const SmoothCounts c = smooth_vertices(mesh, surface, surface, curves, settle);
    out.flips += c.flips;
    out.moves += c.moves;
    out.boundary_moves += c.boundary_moves;
  }
  return out;
}

}  // namespace gsp::cvt::detail
