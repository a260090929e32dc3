// Junctions of face-labelled regions and their dual triangles (see junctions.hpp).
#include "junctions.hpp"

#include <algorithm>
#include <cmath>
#include <array>
#include <cstdint>

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

// Smallest angle (as its cosine's complement: larger is better) of triangle (a, b, c).
double min_angle(Vec3 a, Vec3 b, Vec3 c) {
  auto angle = [](Vec3 p, Vec3 q, Vec3 r) { return std::atan2(norm(cross(q - p, r - p)), dot(q - p, r - p)); };
  return std::min({angle(a, b, c), angle(b, c, a), angle(c, a, b)});
}

// The worst angle of the fan from seq[s] over the triangles (s, s+i, s+i+1), i = 1..count.
double fan_quality(const std::vector<Index>& seq, std::size_t s, std::size_t count, const std::vector<Vec3>& p) {
  const std::size_t k = seq.size();
  double worst = 10;
  for (std::size_t i = 1; i <= count; ++i)
    worst = std::min(worst, min_angle(p[seq[s]], p[seq[(s + i) % k]], p[seq[(s + i + 1) % k]]));
  return worst;
}

// A triangle on the same three sites as an earlier one (in the order they were made) is
// dropped, counted, and its vertex marked as trouble.
void drop_repeated_triangles(DualTriangles& d) {
  std::vector<std::pair<std::array<Index, 3>, Index>> keys(d.triangles.size());
  for (std::size_t t = 0; t < keys.size(); ++t) {
    keys[t] = {d.triangles[t], Index(t)};
    std::sort(keys[t].first.begin(), keys[t].first.end());
  }
  std::sort(keys.begin(), keys.end());
  std::vector<bool> repeated(keys.size(), false);
  for (std::size_t i = 1; i < keys.size(); ++i)
    if (keys[i].first == keys[i - 1].first) repeated[keys[i].second] = true;
  std::size_t kept = 0;
  for (std::size_t t = 0; t < d.triangles.size(); ++t) {
    if (repeated[t]) {
      d.stats.duplicate_triangles++;
      d.trouble_vertices.push_back(d.junction_vertex[t]);
      continue;
    }
    d.triangles[kept] = d.triangles[t];
    d.junction_vertex[kept] = d.junction_vertex[t];
    ++kept;
  }
  d.triangles.resize(kept);
  d.junction_vertex.resize(kept);
}

}  // namespace

DualTriangles dual_triangles(const TriangleMesh& m, const Connectivity& conn, const std::vector<Index>& label,
                             const std::vector<Vec3>& sites) {
  DualTriangles d;
  Index vertex = 0;
  // Every triangle is kept here; one that repeats an earlier one's three sites is dropped
  // after the scan (below), by sorting, not by a tree of the triangles seen.
  auto emit = [&](Index a, Index b, Index c) {
    d.triangles.push_back({a, b, c});
    d.junction_vertex.push_back(vertex);
  };
  std::vector<Index> fan, seq;
  // Fewer than three labels among all the faces at v (a region's inside, a border between two:
  // nearly every vertex): its fan, a subset of them, has fewer too, and v makes no triangle.
  // Read off the vertex's corners without walking the fan.
  auto fewer_than_three = [&](Index v) {
    Index first = 0, second = 0;
    int labels_seen = 0;
    for (Index i = conn.vertex_corner_begin[v]; i < conn.vertex_corner_begin[v + 1]; ++i) {
      const Index l = label[face_of(conn.vertex_corners[i])];
      if ((labels_seen > 0 && l == first) || (labels_seen > 1 && l == second)) continue;
      if (labels_seen == 2) return false;
      (labels_seen == 0 ? first : second) = l;
      ++labels_seen;
    }
    return true;
  };
  for (Index v = 0; v < m.num_vertices(); ++v) {
    if (fewer_than_three(v)) continue;
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
    const std::size_t k = seq.size();
    if (closed) {
      // A polygon of k regions: fanned from the corner whose fan has the largest smallest angle
      // (for four regions: the better diagonal of the quad).
      std::size_t best = 0;
      if (k > 3) {
        double q = -1;
        for (std::size_t s = 0; s < k; ++s) {
          const double qs = fan_quality(seq, s, k - 2, sites);
          if (qs > q) q = qs, best = s;
        }
      }
      for (std::size_t i = 1; i + 1 < k; ++i) emit(seq[best], seq[(best + i) % k], seq[(best + i + 1) % k]);
    } else {
      // Open fan: the outside closes the polygon between the last and the first region; the
      // triangles that would use it are left out. Fanning from the first or the last region
      // keeps the edge between them (the dual's boundary edge here); the better one is taken.
      const bool from_last = k > 3 && fan_quality(seq, k - 1, k - 2, sites) > fan_quality(seq, 0, k - 2, sites);
      for (std::size_t i = 1; i + 1 < k; ++i) {
        if (from_last) emit(seq[k - 1], seq[(k - 1 + i) % k], seq[(k - 1 + i + 1) % k]);
        else emit(seq[0], seq[i], seq[i + 1]);
      }
    }
  }
  drop_repeated_triangles(d);
  return d;
}

std::vector<Index> overused_edge_vertices(const DualTriangles& d) {
  // (edge, triangle) pairs sorted by edge, then triangle: the third and later triangles of an
  // edge, in the order they were made, are the ones past its two.
  std::vector<std::pair<std::uint64_t, Index>> uses;
  uses.reserve(3 * d.triangles.size());
  for (std::size_t t = 0; t < d.triangles.size(); ++t)
    for (int i = 0; i < 3; ++i) {
      Index a = d.triangles[t][i], b = d.triangles[t][(i + 1) % 3];
      if (a > b) std::swap(a, b);
      uses.push_back({(std::uint64_t(a) << 32) | b, Index(t)});
    }
  std::sort(uses.begin(), uses.end());
  std::vector<Index> out;
  for (std::size_t i = 2; i < uses.size(); ++i)
    if (uses[i].first == uses[i - 2].first) out.push_back(d.junction_vertex[uses[i].second]);
  return out;
}

}  // namespace gsp::cvt::detail
