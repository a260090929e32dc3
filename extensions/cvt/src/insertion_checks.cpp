#include "insertion_checks.hpp"
#include "triangle_geometry.hpp"

#include <gsp/cvt/closest_point_index.hpp>

#include <algorithm>
#include <cmath>

namespace gsp::cvt::detail {

namespace {

constexpr double kPi = 3.14159265358979323846;

}  // namespace

// No fold: across each of its edges a changed triangle turns by at most 150 degrees. Whether it
// faces the way the face it replaced did says nothing near a spike (the tent from a tip that
// overhangs the face turns by 90 degrees and more, and is right to), nor does the input's
// normal near a talon (it turns round within a fraction of an edge). -1 on a fold, else the
// smallest angle of the changed triangles.
double InsertionChecks::unfolded_min_angle(const std::vector<Index>& changed) const {
  const double fold_cos = std::cos(150.0 * kPi / 180.0);
  const TriangleMesh& m = em_.mesh();
  double worst = 10;
  for (Index f : changed) {
    const Triangle& t = m.triangles[f];
    const Vec3 n = normal(m.positions[t[0]], m.positions[t[1]], m.positions[t[2]]);
    for (Index k = 0; k < 3; ++k) {
      const Index g = em_.face_with(t[(k + 1) % 3], t[k]);
      if (g == kInvalidIndex) continue;
      const Triangle& tg = m.triangles[g];
      const Vec3 ng = normal(m.positions[tg[0]], m.positions[tg[1]], m.positions[tg[2]]);
      if (dot(n, ng) < fold_cos * norm(n) * norm(ng)) return -1.0;
    }
    worst = std::min(worst, min_angle(m.positions[t[0]], m.positions[t[1]], m.positions[t[2]]));
  }
  return worst;
}

// Largest distance to the surface of a triangle's centroid and edge midpoints: how far the
// triangle's chords leave the surface.
double InsertionChecks::deviation(const Triangle& t) const {
  const TriangleMesh& m = em_.mesh();
  const Vec3 a = m.positions[t[0]], b = m.positions[t[1]], c = m.positions[t[2]];
  double d = 0;
  for (Vec3 s : {(a + b + c) * (1.0 / 3), 0.5 * (a + b), 0.5 * (b + c), 0.5 * (c + a)})
    d = std::max(d, index_.closest(s).distance);
  return d;
}

// The changed triangles within max(max_deviation, before) of the surface.
bool InsertionChecks::keeps_deviation(const std::vector<Index>& changed, const std::vector<Triangle>& replaced) const {
  double dev0 = 0;
  for (const Triangle& t : replaced) dev0 = std::max(dev0, deviation(t));
  for (Index f : changed)
    if (deviation(em_.mesh().triangles[f]) > std::max(p_.max_deviation, dev0)) return false;
  return true;
}

// The input near the change: no point of it (on this sheet) farther than max(bound, before)
// from the changed triangles and the ones around them, or the insertion gives back elsewhere
// the distance it wins at z.
bool InsertionChecks::keeps_input_close(Vec3 z, Vec3 reference, const std::vector<Index>& changed,
                                        const std::vector<Triangle>& replaced) const {
  const TriangleMesh& m = em_.mesh();
  std::vector<Index> ring;
  double reach = 0;
  for (Index f : changed)
    for (Index u : m.triangles[f]) {
      reach = std::max(reach, distance(z, m.positions[u]));
      for (Index h : em_.faces_of(u))
        if (std::find(changed.begin(), changed.end(), h) == changed.end()) ring.push_back(h);
    }
  std::sort(ring.begin(), ring.end());
  ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
  bool ok = true;
  grid_.near(z, reach + p_.bound, [&](Index w) {
    if (!ok || dot(input_normal_[w], reference) <= 0) return;
    const Vec3 q = input_[w];
    double rest = 1e300;
    for (Index h : ring) rest = std::min(rest, triangle_distance(q, m, m.triangles[h]));
    if (rest <= p_.bound) return;
    double before = rest, after = rest;
    for (const Triangle& t : replaced) before = std::min(before, triangle_distance(q, m, t));
    for (Index f : changed) after = std::min(after, triangle_distance(q, m, m.triangles[f]));
    if (after > std::max(p_.bound, before) + 1e-12 * p_.bound) ok = false;
  });
  return ok;
}

double InsertionChecks::judge(Vec3 z, Vec3 reference, double floor_angle) const {
  const std::vector<Index> changed = em_.changed();
  const std::vector<Triangle> replaced = em_.replaced();
  const double worst = unfolded_min_angle(changed);
  if (worst < 0 || worst < floor_angle) return -1.0;
  if (!keeps_deviation(changed, replaced)) return -1.0;
  return keeps_input_close(z, reference, changed, replaced) ? worst : -1.0;
}

}  // namespace gsp::cvt::detail
