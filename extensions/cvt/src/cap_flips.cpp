#include "cap_flips.hpp"
#include "flips.hpp"
#include "locked_vertices.hpp"
#include "triangle_geometry.hpp"

#include <gsp/connectivity.hpp>
#include <gsp/cvt/closest_point_index.hpp>

#include <algorithm>
#include <memory>
#include <vector>

namespace gsp::cvt::detail {

namespace {

// Distance from z to the pair (p0, p1, p2), (p0, p1, p3): what a flip of edge (p0, p1) changes.
double pair_distance(Vec3 z, Vec3 p0, Vec3 p1, Vec3 p2, Vec3 p3) {
  return std::min(triangle_distance(z, p0, p1, p2), triangle_distance(z, p0, p1, p3));
}

// The pair around the flipped edge: faces f = (a, b, c) and g = (b, a, d).
struct Quad {
  Index f, g, a, b, c, d;
  Vec3 pa, pb, pc, pd;
};

// Holds the index over the mesh that says which triangle a sample point is nearest, kept in
// step with the flips: rebuilding it after every flip was a fifth of a CAD part's post-pass
// (cgal_turbine at 5,000 vertices: hundreds of cap flips, each an Embree build over the whole
// mesh). The faces flipped since the last build are asked besides it, which gives the answer
// a new index would give (ClosestPointIndex::on_face); it is rebuilt once they are many.
class CapFlipCheck {
 public:
  CapFlipCheck(SmoothingContext& c, double max_deviation)
      : c_(c), bound_(max_deviation), out_(std::make_unique<ClosestPointIndex>(c.m)) {}

  bool keeps_surface(Index f, Index g, Index a, Index b, Index cc, Index d) const;
  // The rings go stale with each flip (the boundary links only where a directed edge is in
  // two faces: VertexRings::rebuild_rings), and so do faces f and g in the index.
  void flipped(Index f, Index g, bool unique) {
    unique ? c_.rings.rebuild_rings(c_.m) : c_.rings.rebuild(c_.m);
    stale_.push_back(f), stale_.push_back(g);
    if (stale_.size() >= kMaxStale) out_ = std::make_unique<ClosestPointIndex>(c_.m), stale_.clear();
  }

 private:
  static constexpr std::size_t kMaxStale = 32;

  double after(const Quad& q, Vec3 z) const;
  bool stays(const Quad& q, Vec3 z) const {
    return after(q, z) <= std::max(bound_, pair_distance(z, q.pa, q.pb, q.pc, q.pd));
  }
  // The mesh face nearest to z, ties to the lower face, as an index built now would say.
  Index nearest_face(Vec3 z) const {
    ClosestPoint best = out_->closest(z);
    for (Index h : stale_) {
      const ClosestPoint r = out_->on_face(h, z);
      if (r.distance < best.distance || (r.distance == best.distance && h < best.point.element)) best = r;
    }
    return best.point.element;
  }

  SmoothingContext& c_;
  const double bound_;
  std::unique_ptr<ClosestPointIndex> out_;
  std::vector<Index> stale_;   // faces flipped since out_ was built
};

// After the flip a point is as far as the nearer of the new pair and the other triangles
// around the quad (those farther away cannot be nearer than before: the old pair was).
double CapFlipCheck::after(const Quad& q, Vec3 z) const {
  double r = pair_distance(z, q.pc, q.pd, q.pa, q.pb);
  for (Index v : {q.a, q.b, q.c, q.d})
    for (Index k : c_.rings.around(v)) {
      const Index h = face_of(k);
      if (h == q.f || h == q.g) continue;
      r = std::min(r, triangle_distance(z, c_.m, c_.m.triangles[h]));
    }
  return r;
}

bool CapFlipCheck::keeps_surface(Index f, Index g, Index a, Index b, Index cc, Index d) const {
  const std::vector<Vec3>& x = c_.m.positions;
  const Quad q{f, g, a, b, cc, d, x[a], x[b], x[cc], x[d]};
  const Vec3 old_mid = 0.5 * (q.pa + q.pb), new_mid = 0.5 * (q.pc + q.pd);
  if (c_.index.closest(new_mid).distance > std::max(bound_, c_.index.closest(old_mid).distance)) return false;
  if (!stays(q, c_.index.closest(old_mid).position)) return false;
  const Vec3 centre = 0.25 * (q.pa + q.pb + q.pc + q.pd);
  double reach = 0;
  for (Vec3 p : {q.pa, q.pb, q.pc, q.pd}) reach = std::max(reach, distance(centre, p));
  bool ok = true;
  c_.grid.near(centre, reach + bound_, [&](Index w) {
    if (!ok) return;
    const Vec3 z = c_.samples.positions[w];
    const Index nearest_face = this->nearest_face(z);
    if (nearest_face == f || nearest_face == g) ok = stays(q, z);
  });
  return ok;
}

}  // namespace

std::size_t remove_caps_keeping_surface(SmoothingContext& c, double max_deviation) {
  CapFlipCheck check(c, max_deviation);
  auto keeps_surface = [&](Index f, Index g, Index a, Index b, Index cc, Index d) {
    return !is_locked_edge(c.locked, a, b) && check.keeps_surface(f, g, a, b, cc, d);
  };
  return remove_caps(c.m, 120.0, keeps_surface, [&](Index f, Index g, bool unique) { check.flipped(f, g, unique); });
}

}  // namespace gsp::cvt::detail
