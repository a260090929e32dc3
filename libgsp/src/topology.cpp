#include "disjoint_sets.hpp"

#include <gsp/topology.hpp>

#include <algorithm>
#include <numeric>
#include <utility>

namespace gsp {
namespace {



// The zero-area threshold scales with the model: area <= 1e-12 * (bbox diagonal)^2, with the
// box over all positions (as the shared data set's figures are computed).
double zero_area_threshold(const TriangleMesh& mesh) {
  if (mesh.positions.empty()) return 0.0;
  const BoundingBox box = bounding_box(mesh);
  const Vec3 d = box.max - box.min;
  return 1e-12 * dot(d, d);
}

double triangle_area(const TriangleMesh& mesh, const Triangle& t) {
  const Vec3 a = mesh.positions[t[0]];
  return 0.5 * norm(cross(mesh.positions[t[1]] - a, mesh.positions[t[2]] - a));
}

// Number of fans the faces around v form: corners of v are joined when their faces share a
// manifold edge through v (or are the same face, for a face naming v twice). `scratch` is a
// local union-find over v's corners, reused across vertices to avoid allocation per vertex.
std::size_t count_fans(const TriangleMesh& mesh, const Connectivity& conn, Index v,
                       std::vector<Index>& scratch) {
  const Index begin = conn.vertex_corner_begin[v], end = conn.vertex_corner_begin[v + 1];
  const Index n = end - begin;
  if (n == 0) return 0;
  const auto corners_begin = conn.vertex_corners.begin() + begin;
  const auto corners_end = conn.vertex_corners.begin() + end;
  scratch.resize(n);
  std::iota(scratch.begin(), scratch.end(), Index{0});
  auto find = [&](Index x) {
    while (scratch[x] != x) x = scratch[x] = scratch[scratch[x]];
    return x;
  };
  auto unite = [&](Index a, Index b) {
    a = find(a), b = find(b);
    if (a != b) scratch[std::max(a, b)] = std::min(a, b);
  };
  // Corners of v are stored in increasing halfedge order, so a binary search finds the local
  // index of the corner of v in any face.
  auto local_corner_in_face = [&](Index f) -> Index {
    for (Index i = 0; i < 3; ++i)
      if (mesh.triangles[f][i] == v) {
        auto it = std::lower_bound(corners_begin, corners_end, 3 * f + i);
        return static_cast<Index>(it - corners_begin);
      }
    return kInvalidIndex;  // unreachable: the edge contains v
  };
  for (Index k = 0; k < n; ++k) {
    const Index h = conn.vertex_corners[begin + k];
    const Index f = face_of(h);
    // The two halfedges of f that touch v: out of v (h) and into v (prev of h).
    for (Index e : {h, prev_halfedge(h)}) {
      const Index g = conn.radial_next[e];
      if (g == e || conn.radial_next[g] != e) continue;  // boundary, loop or non-manifold edge
      const Index other = local_corner_in_face(face_of(g));
      if (other != kInvalidIndex) unite(k, other);
    }
    // Another corner of v in the same face (a face naming v twice) belongs to the same fan.
    for (Index i = 0; i < 3; ++i)
      if (3 * f + i != h && mesh.triangles[f][i] == v) {
        auto it = std::lower_bound(corners_begin, corners_end, 3 * f + i);
        unite(k, static_cast<Index>(it - corners_begin));
      }
  }
  std::size_t fans = 0;
  for (Index k = 0; k < n; ++k) fans += (find(k) == k);
  return fans;
}

}  // namespace

TopologyReport analyze_topology(const TriangleMesh& mesh, const Connectivity& conn) {
  const std::size_t nv = mesh.num_vertices();
  const std::size_t nf = mesh.num_faces();
  TopologyReport r;
  r.vertices = nv;
  r.faces = nf;
  r.edges = conn.num_edges();

  // Per-edge classification; vertices on non-manifold edges are non-manifold vertices.
  std::vector<bool> on_nonmanifold_edge(nv, false);
  detail::DisjointSets boundary_sets(nv);
  std::vector<bool> on_boundary(nv, false);
  for (Index h0 : conn.edge_halfedge) {
    const std::size_t ring = conn.ring_size(h0);
    const Index a = from_vertex(mesh, h0), b = to_vertex(mesh, h0);
    if (ring == 1) {
      ++r.boundary_edges;
      boundary_sets.unite(a, b);
      on_boundary[a] = on_boundary[b] = true;
    } else if (ring == 2) {
      if (from_vertex(mesh, conn.radial_next[h0]) == a) ++r.inconsistent_edges;
    } else {
      ++r.nonmanifold_edges;
      on_nonmanifold_edge[a] = on_nonmanifold_edge[b] = true;
    }
  }
  for (std::size_t v = 0; v < nv; ++v)
    if (on_boundary[v] && boundary_sets.find(static_cast<Index>(v)) == v) ++r.boundary_loops;

  // Components: faces joined through shared vertices.
  detail::DisjointSets vertex_sets(nv);
  for (const Triangle& t : mesh.triangles) {
    vertex_sets.unite(t[0], t[1]);
    vertex_sets.unite(t[1], t[2]);
  }
  std::size_t referenced = 0;
  std::vector<Index> scratch;
  for (std::size_t v = 0; v < nv; ++v) {
    const Index vi = static_cast<Index>(v);
    const bool used = conn.vertex_corner_begin[v + 1] > conn.vertex_corner_begin[v];
    if (!used) {
      ++r.isolated_vertices;
      continue;
    }
    ++referenced;
    if (vertex_sets.find(vi) == vi) ++r.components;
    if (on_nonmanifold_edge[v] || count_fans(mesh, conn, vi, scratch) > 1) ++r.nonmanifold_vertices;
  }

  // Degenerate faces.
  const double threshold = zero_area_threshold(mesh);
  for (const Triangle& t : mesh.triangles) {
    if (repeats_vertex(t)) ++r.repeated_index_faces;
    else if (triangle_area(mesh, t) <= threshold) ++r.zero_area_faces;
  }

  const std::vector<bool> duplicate = duplicate_faces(mesh);
  r.duplicate_faces = std::size_t(std::count(duplicate.begin(), duplicate.end(), true));

  r.euler_characteristic = static_cast<std::int64_t>(referenced) - static_cast<std::int64_t>(r.edges) +
                           static_cast<std::int64_t>(nf);
  return r;
}

std::vector<bool> duplicate_faces(const TriangleMesh& mesh) {
  // Faces sorted by their sorted vertex triple, then by index: a face equal to its predecessor
  // repeats an earlier one.
  std::vector<std::pair<Triangle, Index>> keys;
  keys.reserve(mesh.num_faces());
  for (std::size_t f = 0; f < mesh.num_faces(); ++f) {
    Triangle k = mesh.triangles[f];
    std::sort(k.begin(), k.end());
    keys.push_back({k, Index(f)});
  }
  std::sort(keys.begin(), keys.end());
  std::vector<bool> out(mesh.num_faces(), false);
  for (std::size_t i = 1; i < keys.size(); ++i)
    if (keys[i].first == keys[i - 1].first) out[keys[i].second] = true;
  return out;
}

std::vector<bool> degenerate_faces(const TriangleMesh& mesh) {
  const double threshold = zero_area_threshold(mesh);
  std::vector<bool> out(mesh.num_faces());
  for (std::size_t f = 0; f < mesh.num_faces(); ++f) {
    const Triangle& t = mesh.triangles[f];
    out[f] = repeats_vertex(t) || triangle_area(mesh, t) <= threshold;
  }
  return out;
}

}  // namespace gsp
