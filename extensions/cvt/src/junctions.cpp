// Junctions of face-labelled regions and their dual triangles (see junctions.hpp).
#include "junctions.hpp"

#include <algorithm>
#include <map>
#include <set>

namespace gsp::cvt::detail {

namespace {

// Faces around v in the rotation order of the faces' own orientation (counter-clockwise for
// counter-clockwise faces). `closed` says whether the fan goes all the way round. Returns false
// for a vertex with several fans or on a non-manifold edge.
bool vertex_fan(const TriangleMesh& m, const Connectivity& conn, Index v, std::vector<Index>& fan, bool& closed) {
  fan.clear();
  const Index b = conn.vertex_corner_begin[v], e = conn.vertex_corner_begin[v + 1];
  if (b == e) return false;
  const Index c0 = conn.vertex_corners[b];
  // Across halfedge h (one of the two edges of its face at v): the neighbour face and the
  // other edge of that face at v, or kInvalidIndex at a boundary / non-manifold edge.
  auto cross = [&](Index h, Index& next_h) -> Index {
    const Index o = conn.radial_next[h];
    if (o == h || conn.radial_next[o] != h || conn.halfedge_edge[h] == kInvalidIndex) return kInvalidIndex;
    const Index g = face_of(o);
    for (Index j = 0; j < 3; ++j) {
      if (m.triangles[g][j] != v) continue;
      const Index out = 3 * g + j, in = prev_halfedge(out);
      if (o == out) return next_h = in, g;
      if (o == in) return next_h = out, g;
    }
    return kInvalidIndex;
  };
  const Index f0 = face_of(c0);
  const std::size_t cap = e - b + 1;
  fan.push_back(f0);
  closed = false;
  Index h = prev_halfedge(c0), next_h = 0;
  for (;;) {
    const Index g = cross(h, next_h);
    if (g == kInvalidIndex) break;
    if (g == f0) {
      closed = true;
      break;
    }
    fan.push_back(g);
    if (fan.size() > cap) return false;
    h = next_h;
  }
  if (!closed) {
    std::vector<Index> back;
    h = c0;
    for (;;) {
      const Index g = cross(h, next_h);
      if (g == kInvalidIndex || g == f0) break;
      back.push_back(g);
      if (back.size() > cap) return false;
      h = next_h;
    }
    fan.insert(fan.begin(), back.rbegin(), back.rend());
  }
  return fan.size() == e - b;
}

}  // namespace

DualTriangles dual_triangles(const TriangleMesh& m, const Connectivity& conn, const std::vector<Index>& label) {
  DualTriangles d;
  std::set<std::array<Index, 3>> seen;
  Index vertex = 0;
  auto emit = [&](Index a, Index b, Index c) {
    std::array<Index, 3> key{a, b, c};
    std::sort(key.begin(), key.end());
    if (!seen.insert(key).second) {
      d.stats.duplicate_triangles++;
      d.trouble_vertices.push_back(vertex);
      return;
    }
    d.triangles.push_back({a, b, c});
    d.junction_vertex.push_back(vertex);
  };
  std::vector<Index> fan, seq;
  for (Index v = 0; v < m.num_vertices(); ++v) {
    vertex = v;
    bool closed = false;
    const bool ok = vertex_fan(m, conn, v, fan, closed);
    seq.clear();
    for (Index f : fan)
      if (seq.empty() || seq.back() != label[f]) seq.push_back(label[f]);
    if (closed && seq.size() > 1 && seq.front() == seq.back()) seq.pop_back();
    std::vector<Index> distinct = seq;
    std::sort(distinct.begin(), distinct.end());
    distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
    if (distinct.size() < 3) continue;
    d.stats.junctions++;
    if (!ok || distinct.size() != seq.size() || distinct.back() == kInvalidIndex) {
      d.stats.skipped_junctions++;
      d.trouble_vertices.push_back(v);
      continue;
    }
    if (seq.size() > 3) d.stats.junctions_over_three++;
    if (closed) {
      // A polygon of k regions: fan from its smallest label, so that the same regions meeting
      // elsewhere get the same triangles.
      const std::size_t k = seq.size();
      const std::size_t s = std::size_t(std::min_element(seq.begin(), seq.end()) - seq.begin());
      for (std::size_t i = 1; i + 1 < k; ++i) emit(seq[s], seq[(s + i) % k], seq[(s + i + 1) % k]);
    } else {
      // Open fan: the outside closes the polygon between the last and the first region; the
      // triangles that would use it are left out.
      for (std::size_t i = 1; i + 1 < seq.size(); ++i) emit(seq[0], seq[i], seq[i + 1]);
    }
  }
  return d;
}

std::vector<Index> overused_edge_vertices(const DualTriangles& d) {
  std::map<std::pair<Index, Index>, int> uses;
  std::vector<Index> out;
  for (std::size_t t = 0; t < d.triangles.size(); ++t)
    for (int i = 0; i < 3; ++i) {
      Index a = d.triangles[t][i], b = d.triangles[t][(i + 1) % 3];
      if (a > b) std::swap(a, b);
      if (++uses[{a, b}] > 2) out.push_back(d.junction_vertex[t]);
    }
  return out;
}

}  // namespace gsp::cvt::detail
