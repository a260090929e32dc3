#include "flips.hpp"
#include "locked_vertices.hpp"
#include "triangle_geometry.hpp"

#include <gsp/connectivity.hpp>


#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <unordered_map>
#include <unordered_set>

namespace gsp::cvt::detail {

DirectedEdges::DirectedEdges(const TriangleMesh& m) {
  map.reserve(3 * m.num_faces());
  for (Index f = 0; f < m.num_faces(); ++f)
    for (Index i = 0; i < 3; ++i) map[edge_key(m.triangles[f][i], m.triangles[f][(i + 1) % 3])] = 3 * f + i;
  unique = map.size() == 3 * m.num_faces();
}

bool DirectedEdges::exists(Index a, Index b) const { return map.count(edge_key(a, b)) || map.count(edge_key(b, a)); }

void DirectedEdges::flip(TriangleMesh& m, Index f, Index g, Index a, Index b, Index c, Index d) {
  for (Index k = 0; k < 3; ++k) {
    map.erase(edge_key(m.triangles[f][k], m.triangles[f][(k + 1) % 3]));
    map.erase(edge_key(m.triangles[g][k], m.triangles[g][(k + 1) % 3]));
  }
  m.triangles[f] = {a, d, c};
  m.triangles[g] = {d, b, c};
  for (Index k = 0; k < 3; ++k) {
    map[edge_key(m.triangles[f][k], m.triangles[f][(k + 1) % 3])] = 3 * f + k;
    map[edge_key(m.triangles[g][k], m.triangles[g][(k + 1) % 3])] = 3 * g + k;
  }
}

std::size_t improve_by_flips(TriangleMesh& m, double max_normal_angle_deg, int max_passes,
                             const std::vector<bool>* locked, const std::vector<bool>* touched, bool* converged,
                             DirectedEdges* edges) {
  const double cos_limit = std::cos(max_normal_angle_deg * 3.14159265358979323846 / 180.0);
  std::optional<DirectedEdges> own;
  DirectedEdges& directed = edges ? *edges : own.emplace(m);
  // With `touched`: per vertex, the last pass in which it moved (0: before the call) or was a
  // corner of a flip. An edge is examined in pass k when a corner of its quad has a mark of
  // k - 1 or later: a quad examined in pass k - 1 and not changed since would be refused
  // again. A flip of (a, b) marks a and b: every quad it changed holds one of them (the new
  // faces are (a, d, c) and (d, b, c)), and so does every quad whose flip the edge (a, b)
  // blocked.
  constexpr int kNever = -2;
  std::vector<int> mark;
  if (touched) {
    mark.assign(m.num_vertices(), kNever);
    for (Index v = 0; v < m.num_vertices() && v < touched->size(); ++v)
      if ((*touched)[v]) mark[v] = 0;
  }
  std::size_t flips = 0;
  if (converged) *converged = false;
  for (int pass = 0; pass < max_passes; ++pass) {
    std::size_t this_pass = 0;
    for (Index f = 0; f < m.num_faces(); ++f)
      for (Index i = 0; i < 3; ++i) {
        const Triangle t = m.triangles[f];
        const Index a = t[i], b = t[(i + 1) % 3], c = t[(i + 2) % 3];
        if (is_locked_edge(locked, a, b)) continue;
        const auto it = directed.map.find(edge_key(b, a));
        if (it == directed.map.end()) continue;   // boundary or inconsistently oriented
        const Index g = it->second / 3, j = it->second % 3;
        if (g == f) continue;
        const Index d = m.triangles[g][(j + 2) % 3];
        if (touched && std::max({mark[a], mark[b], mark[c], mark[d]}) < pass - 1) continue;
        if (d == c || directed.exists(c, d)) continue;
        const Vec3 pa = m.positions[a], pb = m.positions[b], pc = m.positions[c], pd = m.positions[d];
        if (angle_at(pc, pa, pb) + angle_at(pd, pb, pa) <= 3.14159265358979323846 + 1e-12) continue;
        const double before = std::min(min_angle(pa, pb, pc), min_angle(pb, pa, pd));
        const double after = std::min(min_angle(pa, pd, pc), min_angle(pd, pb, pc));
        if (after <= before) continue;
        // No fold: both new triangles face the way the old pair faces, and the old pair is
        // nearly flat (not a crease, where a flip would change the shape).
        const Vec3 n1 = normal(pa, pb, pc), n2 = normal(pb, pa, pd);
        const Vec3 m1 = normal(pa, pd, pc), m2 = normal(pd, pb, pc);
        if (dot(n1, n2) < cos_limit * norm(n1) * norm(n2)) continue;
        const Vec3 n = n1 + n2;
        if (dot(m1, n) <= 0 || dot(m2, n) <= 0) continue;
        directed.flip(m, f, g, a, b, c, d);
        if (touched) mark[a] = mark[b] = pass;
        ++this_pass;
      }
    flips += this_pass;
    if (this_pass == 0) {
      if (converged) *converged = true;
      break;
    }
  }
  return flips;
}

std::size_t delaunay_flips_in_planes(TriangleMesh& m, double max_height, std::size_t max_flips,
                                     std::vector<bool>& changed) {
  // Halfedge 3 f + k runs from corner k to k + 1; twin: the opposite halfedge of the one other
  // face on that edge (a radial ring of two, wound the other way), else kInvalidIndex. The
  // undirected edges as a set, for the one question a flip asks of the whole mesh: does the
  // new edge exist already; built at the first flip, so a curved mesh (a scan) skips it. (A
  // map of directed edges, updated with six erasures and six insertions a flip, took 1.3 s for
  // a CAD gear's 376,000 flips.)
  const std::size_t nh = 3 * m.num_faces();
  std::vector<Index> twin(nh, kInvalidIndex);
  const Connectivity conn = build_connectivity(m);
  for (Index h = 0; h < nh; ++h) {
    const Index o = conn.radial_next[h];
    if (o == h || conn.radial_next[o] != h || face_of(o) == face_of(h)) continue;
    if (m.triangles[face_of(h)][corner_of(h)] == m.triangles[face_of(o)][corner_of(next_halfedge(o))]) twin[h] = o;
  }
  std::unordered_set<std::uint64_t> edges;
  auto edge_exists = [&](Index c, Index d) {
    if (edges.empty()) {
      edges.reserve(conn.edge_halfedge.size());
      for (Index h : conn.edge_halfedge) {
        const Index a = m.triangles[face_of(h)][corner_of(h)], b = m.triangles[face_of(h)][corner_of(next_halfedge(h))];
        edges.insert(edge_key(std::min(a, b), std::max(a, b)));
      }
    }
    return edges.count(edge_key(std::min(c, d), std::max(c, d))) > 0;
  };
  auto link = [&](Index h, Index o) {
    twin[h] = o;
    if (o != kInvalidIndex) twin[o] = h;
  };
  std::vector<Index> stack(m.num_faces());
  for (Index f = 0; f < m.num_faces(); ++f) stack[f] = m.num_faces() - 1 - f;
  std::size_t flips = 0;
  while (!stack.empty() && flips < max_flips) {
    const Index f = stack.back();
    stack.pop_back();
    for (Index i = 0; i < 3; ++i) {
      const Index h = 3 * f + i, o = twin[h];
      if (o == kInvalidIndex) continue;
      const Index g = o / 3, j = o % 3;
      const Triangle t = m.triangles[f];
      const Index a = t[i], b = t[(i + 1) % 3], c = t[(i + 2) % 3], d = m.triangles[g][(j + 2) % 3];
      if (d == c) continue;
      const Vec3 pa = m.positions[a], pb = m.positions[b], pc = m.positions[c], pd = m.positions[d];
      // Not locally Delaunay: the cotangents of the angles at c and d sum below 0.
      const Vec3 xc = cross(pa - pc, pb - pc), xd = cross(pb - pd, pa - pd);
      const double sc = norm(xc), sd = norm(xd);
      if (!(sc > 0) || !(sd > 0)) continue;
      if (dot(pa - pc, pb - pc) / sc + dot(pb - pd, pa - pd) / sd >= -1e-9) continue;
      // One plane: d off (a, b, c)'s plane and c off (b, a, d)'s by at most max_height.
      if (std::abs(dot(pd - pa, xc)) > max_height * sc || std::abs(dot(pc - pa, xd)) > max_height * sd) continue;
      const Vec3 n = xc + xd;
      if (dot(normal(pa, pd, pc), n) <= 0 || dot(normal(pd, pb, pc), n) <= 0) continue;
      if (edge_exists(c, d)) continue;
      // f = (a, b, c), g = (b, a, d) become (a, d, c) and (d, b, c).
      const Index bc = twin[3 * f + (i + 1) % 3], ca = twin[3 * f + (i + 2) % 3];
      const Index ad = twin[3 * g + (j + 1) % 3], db = twin[3 * g + (j + 2) % 3];
      m.triangles[f] = {a, d, c};
      m.triangles[g] = {d, b, c};
      link(3 * f + 0, ad), link(3 * f + 1, 3 * g + 2), link(3 * f + 2, ca);
      link(3 * g + 0, db), link(3 * g + 1, bc);
      edges.erase(edge_key(std::min(a, b), std::max(a, b)));
      edges.insert(edge_key(std::min(c, d), std::max(c, d)));
      changed[f] = changed[g] = true;
      stack.push_back(g);
      stack.push_back(f);
      ++flips;
      break;   // f is (a, d, c) now: its edges are checked again when it is popped
    }
  }
  return flips;
}

std::size_t remove_caps(TriangleMesh& m, double cap_angle_deg,
                        const std::function<bool(Index, Index, Index, Index, Index, Index)>& keeps_surface,
                        const std::function<void(Index, Index, bool)>& flipped) {
  const double cap = cap_angle_deg * 3.14159265358979323846 / 180.0;
  DirectedEdges directed(m);
  std::size_t flips = 0;
  for (Index f = 0; f < m.num_faces(); ++f)
    for (Index i = 0; i < 3; ++i) {
      const Triangle t = m.triangles[f];
      const Index a = t[i], b = t[(i + 1) % 3], c = t[(i + 2) % 3];
      const Vec3 pa = m.positions[a], pb = m.positions[b], pc = m.positions[c];
      if (angle_at(pc, pa, pb) <= cap) continue;
      const auto it = directed.map.find(edge_key(b, a));
      if (it == directed.map.end()) continue;
      const Index g = it->second / 3, j = it->second % 3;
      if (g == f) continue;
      const Index d = m.triangles[g][(j + 2) % 3];
      if (d == c || directed.exists(c, d)) continue;
      const Vec3 pd = m.positions[d];
      const double before = std::min(min_angle(pa, pb, pc), min_angle(pb, pa, pd));
      const double after = std::min(min_angle(pa, pd, pc), min_angle(pd, pb, pc));
      if (after <= before) continue;
      const Vec3 n = normal(pa, pb, pc) + normal(pb, pa, pd);
      if (dot(normal(pa, pd, pc), n) <= 0 || dot(normal(pd, pb, pc), n) <= 0) continue;
      if (!keeps_surface(f, g, a, b, c, d)) continue;
      directed.flip(m, f, g, a, b, c, d);
      ++flips;
      flipped(f, g, directed.unique);
      break;
    }
  return flips;
}

}  // namespace gsp::cvt::detail
