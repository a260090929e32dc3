// Shortening a path in its sleeve (sleeve.hpp): building the sleeve of faces from the faces the
// path runs through, then the rounds of funnel and rerouting.
#include "sleeve.hpp"

#include "sleeve_shortener.hpp"

#include <algorithm>
#include <array>
#include <unordered_map>

namespace gsp::pathfinding::detail {

void Sleeve::remove_loops() {
  // The kept faces are distinct, so each has one place, found by a hash map instead of a scan
  // of all kept faces: the scan made this quadratic in the sleeve's length, and it runs after
  // every rerouting round (on a CAD part of needles, 11% of gsp-path's time).
  std::vector<Index> f2, e2, x2;
  std::unordered_map<Index, std::size_t> place;
  place.reserve(faces.size());
  for (std::size_t k = 0; k < faces.size(); ++k) {
    const auto found = place.find(faces[k]);
    if (found != place.end()) {   // back at f2[at]: drop what came after it, leave by this exit
      const std::size_t at = found->second;
      for (std::size_t m = at + 1; m < f2.size(); ++m) place.erase(f2[m]);
      f2.resize(at + 1), e2.resize(at + 1), x2.resize(at + 1);
      x2[at] = exit[k];
      continue;
    }
    place.emplace(faces[k], f2.size());
    f2.push_back(faces[k]), e2.push_back(entry[k]), x2.push_back(exit[k]);
  }
  faces.swap(f2), entry.swap(e2), exit.swap(x2);
}

namespace {

End end_of(const TriangleMesh& mesh, const PathPoint& p) {
  End e;
  std::array<double, 3> b = p.point.barycentric;
  for (double& x : b) x = std::max(0.0, x);
  const double sum = b[0] + b[1] + b[2];
  for (int i = 0; i < 3; ++i)
    if (b[i] > 1e-9 * sum) e.vertex[e.n] = mesh.triangles[p.point.element][i], e.weight[e.n++] = b[i] / sum;
  return e;
}

}  // namespace

bool Shortener::fan(Index v, Index to, Index first_exit, Sleeve& out, double* angle) const {
  Index h = first_exit;
  double sum = 0;
  for (std::size_t guard = 0; guard < 256; ++guard) {
    const Index g = conn_.radial_next[h];
    if (g == h || conn_.radial_next[g] != h) return false;   // boundary or non-manifold edge
    const Index next = face_of(g);
    if (!valid_face(next)) return false;
    out.faces.push_back(next), out.entry.push_back(g), out.exit.push_back(h);
    if (next == to) {
      if (angle) *angle = sum;
      return true;
    }
    sum += corner_angle(next, corner_at(next, v));
    // Leave `next` over its other edge through v.
    h = from_vertex(mesh_, g) == v ? prev_halfedge(g) : next_halfedge(g);
  }
  return false;
}

bool Shortener::build(const PathPoint& start, const PathPoint& end, const std::vector<Index>& segment_faces) {
  if (segment_faces.empty()) return false;
  start_ = end_of(mesh_, start);
  end_ = end_of(mesh_, end);
  Sleeve s;
  for (const Index f : segment_faces) {
    if (f >= mesh_.num_faces() || !valid_face(f)) return false;
    if (!s.faces.empty() && s.faces.back() == f) continue;
    if (s.faces.empty()) {
      s.faces.push_back(f), s.entry.push_back(kInvalidIndex);
      continue;
    }
    const Index a = s.faces.back();
    Index ha, hb;
    if (link(a, f, ha, hb)) {
      s.exit.push_back(ha), s.faces.push_back(f), s.entry.push_back(hb);
      continue;
    }
    Sleeve best;
    if (!fan_round_shared_vertex(a, f, best)) return false;
    s.append(best);
  }
  s.exit.push_back(kInvalidIndex);
  s.remove_loops();
  s_ = std::move(s);
  return cut_to_ends();
}

// The path runs through a vertex faces a and f share: go round it on the side with the
// smaller angle (the shortening moves it to the other side if that is shorter).
bool Shortener::fan_round_shared_vertex(Index a, Index f, Sleeve& best) const {
  Index v = kInvalidIndex;
  for (Index x : mesh_.triangles[a])
    if (corner_at(f, x) != kInvalidIndex) v = x;
  if (v == kInvalidIndex) return false;
  Sleeve side;
  double best_angle = 0, angle = 0;
  const Index ca = corner_at(a, v);
  for (Index h0 : {3 * a + ca, prev_halfedge(3 * a + ca)}) {
    side = Sleeve{};
    if (fan(v, f, h0, side, &angle) && (best.faces.empty() || angle < best_angle))
      best = side, best_angle = angle;
  }
  return !best.faces.empty();
}

// The sleeve starts at the last face holding the start and ends at the first one after it
// holding the end; false where it holds no such pair.
bool Shortener::cut_to_ends() {
  std::size_t first = s_.faces.size(), last = s_.faces.size();
  for (std::size_t k = 0; k < s_.faces.size(); ++k)
    if (contains(s_.faces[k], start_)) first = k;
  if (first == s_.faces.size()) return false;
  for (std::size_t k = first; k < s_.faces.size() && last == s_.faces.size(); ++k)
    if (contains(s_.faces[k], end_)) last = k;
  if (last == s_.faces.size()) return false;
  s_.keep(first, last);
  return true;
}

bool shorten_in_sleeve(const TriangleMesh& mesh, const Connectivity& conn, const PathPoint& start, const PathPoint& end,
                       const std::vector<Index>& segment_faces, std::vector<PathPoint>& out,
                       const SleeveOptions& options) {
  Shortener s(mesh, conn);
  if (!s.build(start, end, segment_faces)) return false;
  const std::size_t cap = options.max_reroutes ? options.max_reroutes : 4 * s.sleeve_size() + 256;
  for (std::size_t round = 0; round < cap && s.reroute_round(); ++round) {
  }
  s.emit(out);
  return true;
}

}  // namespace gsp::pathfinding::detail
