#include "regions.hpp"

#include <algorithm>
#include <map>
#include <numeric>

namespace gsp::cvt::detail {

namespace {

Index find(std::vector<Index>& parent, Index x) {
  while (parent[x] != x) {
    parent[x] = parent[parent[x]];
    x = parent[x];
  }
  return x;
}

}  // namespace

Components find_components(const WorkingGeometry& g, const std::vector<Index>& label,
                           const std::vector<Index>& site_face, std::size_t sites) {
  const std::size_t nf = g.mesh.num_faces();
  std::vector<Index> parent(nf);
  std::iota(parent.begin(), parent.end(), Index(0));
  for (Index h = 0; h < g.conn.num_halfedges(); ++h) {
    const Index f = face_of(h);
    if (label[f] == kInvalidIndex || g.conn.halfedge_edge[h] == kInvalidIndex) continue;
    // Each pair of faces on the edge is joined once, from its lower halfedge.
    for (Index o = g.conn.radial_next[h]; o != h; o = g.conn.radial_next[o]) {
      const Index f2 = face_of(o);
      if (o < h || label[f2] != label[f]) continue;
      const Index a = find(parent, f), b = find(parent, f2);
      if (a != b) parent[std::max(a, b)] = std::min(a, b);
    }
  }
  Components c;
  c.of_face.assign(nf, kInvalidIndex);
  std::vector<Index> id(nf, kInvalidIndex);
  for (Index f = 0; f < nf; ++f) {
    if (label[f] == kInvalidIndex) continue;
    const Index r = find(parent, f);
    if (id[r] == kInvalidIndex) {
      id[r] = Index(c.label.size());
      c.label.push_back(label[f]);
      c.area.push_back(0);
      c.moment.push_back({});
    }
    const Index k = id[r];
    c.of_face[f] = k;
    c.area[k] += g.area[f];
    c.moment[k] = c.moment[k] + g.area[f] * g.centroid[f];
  }
  c.main.assign(sites, kInvalidIndex);
  for (Index s = 0; s < sites; ++s) {
    const Index f = site_face[s];
    if (f != kInvalidIndex && label[f] == s) c.main[s] = c.of_face[f];
  }
  for (Index k = 0; k < c.label.size(); ++k) {
    Index& m = c.main[c.label[k]];
    const Index s = c.label[k];
    const bool pinned = site_face[s] != kInvalidIndex && label[site_face[s]] == s;
    if (!pinned && (m == kInvalidIndex || c.area[k] > c.area[m])) m = k;
  }
  return c;
}

std::size_t absorb_small_components(const WorkingGeometry& g, std::vector<Index>& label,
                                     const Components& c, double min_area) {
  std::vector<Index> replacement(c.label.size(), kInvalidIndex);
  std::vector<std::map<Index, int>> votes(c.label.size());
  for (Index h = 0; h < g.conn.num_halfedges(); ++h) {
    const Index f = face_of(h);
    const Index k = c.of_face[f];
    if (k == kInvalidIndex || c.main[c.label[k]] == k || c.area[k] >= min_area) continue;
    if (g.conn.halfedge_edge[h] == kInvalidIndex) continue;
    for (Index o = g.conn.radial_next[h]; o != h; o = g.conn.radial_next[o]) {
      const Index l = label[face_of(o)];
      if (l != kInvalidIndex && l != label[f]) ++votes[k][l];
    }
  }
  for (Index k = 0; k < c.label.size(); ++k) {
    int best = 0;
    for (const auto& [l, n] : votes[k])
      if (n > best) best = n, replacement[k] = l;
  }
  std::size_t changed = 0;
  for (Index f = 0; f < label.size(); ++f) {
    const Index k = c.of_face[f];
    if (k != kInvalidIndex && replacement[k] != kInvalidIndex) {
      label[f] = replacement[k];
      ++changed;
    }
  }
  return changed;
}

std::vector<long> component_euler(const WorkingGeometry& g, const Components& c) {
  const TriangleMesh& m = g.mesh;
  std::vector<long> chi(c.label.size(), 0);
  // Faces and edges: a halfedge counts as a whole edge unless another halfedge of its edge
  // lies in the same component (then each counts half).
  std::vector<long> half_edges(c.label.size(), 0);
  for (Index f = 0; f < m.num_faces(); ++f) {
    const Index k = c.of_face[f];
    if (k == kInvalidIndex) continue;
    ++chi[k];
    for (Index i = 0; i < 3; ++i) {
      const Index h = 3 * f + i;
      if (g.conn.halfedge_edge[h] == kInvalidIndex) continue;
      bool shared = false;
      for (Index o = g.conn.radial_next[h]; o != h; o = g.conn.radial_next[o])
        shared = shared || c.of_face[face_of(o)] == k;
      half_edges[k] += shared ? 1 : 2;
    }
  }
  for (Index k = 0; k < chi.size(); ++k) chi[k] -= half_edges[k] / 2;
  // Vertices: each (vertex, component) pair once.
  for (Index v = 0; v < m.num_vertices(); ++v)
    for (Index i = g.conn.vertex_corner_begin[v]; i < g.conn.vertex_corner_begin[v + 1]; ++i) {
      const Index k = c.of_face[face_of(g.conn.vertex_corners[i])];
      if (k == kInvalidIndex) continue;
      // A vertex usually touches one or two components: a short scan of the corners seen.
      bool seen = false;
      for (Index j = g.conn.vertex_corner_begin[v]; j < i && !seen; ++j)
        seen = c.of_face[face_of(g.conn.vertex_corners[j])] == k;
      if (!seen) ++chi[k];
    }
  return chi;
}

Buckets bucket_faces(const std::vector<Index>& label, std::size_t sites) {
  Buckets b;
  b.begin.assign(sites + 1, 0);
  for (Index l : label)
    if (l != kInvalidIndex) ++b.begin[l + 1];
  for (std::size_t s = 0; s < sites; ++s) b.begin[s + 1] += b.begin[s];
  b.faces.resize(b.begin[sites]);
  std::vector<Index> fill(b.begin.begin(), b.begin.end() - 1);
  for (Index f = 0; f < label.size(); ++f)
    if (label[f] != kInvalidIndex) b.faces[fill[label[f]]++] = f;
  return b;
}

}  // namespace gsp::cvt::detail
