// 1-to-4 midpoint split: the surface does not change (every new vertex is an edge midpoint),
// only the resolution at which Voronoi regions are resolved.
#include <gsp/connectivity.hpp>
#include <gsp/cvt/cvt.hpp>
#include <gsp/errors.hpp>

#include <algorithm>
#include <numeric>

namespace gsp::cvt {

namespace {

using Bary = std::array<double, 3>;

Bary mid(const Bary& a, const Bary& b) { return {0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1]), 0.5 * (a[2] + b[2])}; }

void split_once(WorkingMesh& w) {
  const TriangleMesh& m = w.mesh;
  const Connectivity conn = build_connectivity(m);
  TriangleMesh out;
  out.positions = m.positions;
  // One new vertex per undirected edge; halfedges whose ends coincide get their own.
  std::vector<Index> edge_vertex(conn.num_edges(), kInvalidIndex);
  std::vector<Index> halfedge_vertex(conn.num_halfedges());
  for (Index h = 0; h < conn.num_halfedges(); ++h) {
    const Index e = conn.halfedge_edge[h];
    Index* slot = e == kInvalidIndex ? nullptr : &edge_vertex[e];
    if (slot && *slot != kInvalidIndex) {
      halfedge_vertex[h] = *slot;
      continue;
    }
    const Index v = Index(out.positions.size());
    out.positions.push_back(0.5 * (m.positions[from_vertex(m, h)] + m.positions[to_vertex(m, h)]));
    if (slot) *slot = v;
    halfedge_vertex[h] = v;
  }
  std::vector<Index> parent;
  std::vector<std::array<Bary, 3>> corner_bary;
  out.triangles.reserve(4 * m.num_faces());
  parent.reserve(4 * m.num_faces());
  corner_bary.reserve(4 * m.num_faces());
  for (Index f = 0; f < m.num_faces(); ++f) {
    const Triangle& t = m.triangles[f];
    const Index a = halfedge_vertex[3 * f], b = halfedge_vertex[3 * f + 1], c = halfedge_vertex[3 * f + 2];
    const auto& cb = w.corner_bary[f];
    const Bary ma = mid(cb[0], cb[1]), mb = mid(cb[1], cb[2]), mc = mid(cb[2], cb[0]);
    // Children keep the parent's orientation.
    out.triangles.push_back({t[0], a, c});
    corner_bary.push_back({cb[0], ma, mc});
    out.triangles.push_back({a, t[1], b});
    corner_bary.push_back({ma, cb[1], mb});
    out.triangles.push_back({c, b, t[2]});
    corner_bary.push_back({mc, mb, cb[2]});
    out.triangles.push_back({a, b, c});
    corner_bary.push_back({ma, mb, mc});
    for (int k = 0; k < 4; ++k) parent.push_back(w.parent[f]);
  }
  w.mesh = std::move(out);
  w.parent = std::move(parent);
  w.corner_bary = std::move(corner_bary);
  ++w.levels;
}

// One pass of longest-edge bisection: edges longer than max_edge that are their faces' longest,
// longest first, as long as no face gets two split edges in this pass. Returns the number split.
std::size_t bisect_once(WorkingMesh& w, double max_edge) {
  TriangleMesh& m = w.mesh;
  const Connectivity conn = build_connectivity(m);
  auto length = [&](Index h) { return distance(m.positions[from_vertex(m, h)], m.positions[to_vertex(m, h)]); };
  std::vector<Index> candidates;
  for (Index f = 0; f < m.num_faces(); ++f) {
    Index longest = 3 * f;
    for (Index i = 1; i < 3; ++i)
      if (length(3 * f + i) > length(longest)) longest = 3 * f + i;
    if (length(longest) > max_edge && conn.halfedge_edge[longest] != kInvalidIndex) candidates.push_back(longest);
  }
  std::sort(candidates.begin(), candidates.end(), [&](Index a, Index b) { return length(a) > length(b); });
  std::vector<bool> face_taken(m.num_faces(), false);
  std::vector<Index> split_halfedge(m.num_faces(), kInvalidIndex);   // per face: its edge to split
  std::vector<Index> edge_vertex(conn.num_edges(), kInvalidIndex);
  std::size_t split = 0;
  for (Index h : candidates) {
    bool free = true;
    Index o = h;
    do {
      free = free && !face_taken[face_of(o)];
      o = conn.radial_next[o];
    } while (o != h);
    if (!free) continue;
    const Index e = conn.halfedge_edge[h];
    edge_vertex[e] = Index(m.positions.size());
    m.positions.push_back(0.5 * (m.positions[from_vertex(m, h)] + m.positions[to_vertex(m, h)]));
    o = h;
    do {
      face_taken[face_of(o)] = true;
      split_halfedge[face_of(o)] = o;
      o = conn.radial_next[o];
    } while (o != h);
    ++split;
  }
  const std::size_t nf = m.num_faces();
  for (Index f = 0; f < nf; ++f) {
    const Index h = split_halfedge[f];
    if (h == kInvalidIndex) continue;
    const Index i = corner_of(h);
    const Triangle t = m.triangles[f];
    const Index a = t[i], b = t[(i + 1) % 3], c = t[(i + 2) % 3];
    const Index mid_v = edge_vertex[conn.halfedge_edge[h]];
    const auto cb = w.corner_bary[f];
    const Bary ba = cb[i], bb = cb[(i + 1) % 3], bc = cb[(i + 2) % 3], bm = mid(ba, bb);
    // (a, b, c) -> (a, m, c) in place and (m, b, c) appended: the same turning direction.
    m.triangles[f] = {a, mid_v, c};
    w.corner_bary[f] = {ba, bm, bc};
    m.triangles.push_back({mid_v, b, c});
    w.corner_bary.push_back({bm, bb, bc});
    w.parent.push_back(w.parent[f]);
  }
  return split;
}

}  // namespace

std::size_t refine_long_edges(WorkingMesh& w, double max_edge, std::size_t max_faces) {
  if (!(max_edge > 0)) throw InvalidInput("cvt: the edge length bound must be > 0");
  std::size_t total = 0;
  // Each pass rebuilds the connectivity: a pass cap keeps the cost bounded too (12 passes
  // halve the longest edges at least 6 times over).
  for (int pass = 0; pass < 12 && w.mesh.num_faces() < max_faces; ++pass) {
    const std::size_t n = bisect_once(w, max_edge);
    if (n == 0) break;
    total += n;
  }
  return total;
}

WorkingMesh subdivide(const TriangleMesh& mesh, int levels) {
  if (levels < 0) throw InvalidInput("cvt: negative subdivision level");
  WorkingMesh w;
  w.mesh.positions = mesh.positions;
  w.mesh.triangles = mesh.triangles;
  w.parent.resize(mesh.num_faces());
  w.corner_bary.resize(mesh.num_faces());
  for (Index f = 0; f < mesh.num_faces(); ++f) {
    w.parent[f] = f;
    w.corner_bary[f] = {Bary{1, 0, 0}, Bary{0, 1, 0}, Bary{0, 0, 1}};
  }
  subdivide(w, levels);
  return w;
}

void subdivide(WorkingMesh& w, int levels) {
  if (levels < 0) throw InvalidInput("cvt: negative subdivision level");
  for (int i = 0; i < levels; ++i) split_once(w);
}

}  // namespace gsp::cvt
