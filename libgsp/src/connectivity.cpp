#include <gsp/connectivity.hpp>
#include <gsp/errors.hpp>

#include <algorithm>
#include <cstdint>
#include <string>

namespace gsp {

std::size_t Connectivity::ring_size(Index h) const {
  std::size_t n = 1;
  for (Index g = radial_next[h]; g != h; g = radial_next[g]) ++n;
  return n;
}

Connectivity build_connectivity(const TriangleMesh& mesh) {
  const std::size_t nv = mesh.num_vertices();
  const std::size_t nf = mesh.num_faces();
  if (3 * nf >= kInvalidIndex) throw InvalidInput("mesh has too many faces for 32-bit halfedge indices");
  const Index nh = static_cast<Index>(3 * nf);

  Connectivity c;
  c.radial_next.resize(nh);
  c.halfedge_edge.assign(nh, kInvalidIndex);

  // Vertex -> corners by counting sort: linear time, and corners come out in face order.
  c.vertex_corner_begin.assign(nv + 1, 0);
  for (const Triangle& t : mesh.triangles)
    for (Index v : t) {
      if (v >= nv) throw InvalidInput("triangle index " + std::to_string(v) + " out of range");
      ++c.vertex_corner_begin[v + 1];
    }
  for (std::size_t v = 0; v < nv; ++v) c.vertex_corner_begin[v + 1] += c.vertex_corner_begin[v];
  c.vertex_corners.resize(nh);
  {
    std::vector<Index> fill(c.vertex_corner_begin.begin(), c.vertex_corner_begin.end() - 1);
    for (Index h = 0; h < nh; ++h) c.vertex_corners[fill[from_vertex(mesh, h)]++] = h;
  }

  // Group halfedges by their smaller endpoint (bucket = that vertex's corners, reused as
  // scratch), then by the larger one inside the bucket: buckets are small (vertex valence),
  // so this is linear overall and touches memory in vertex order.
  std::vector<Index> bucket_begin(nv + 1, 0);
  for (Index h = 0; h < nh; ++h) {
    const Index a = from_vertex(mesh, h), b = to_vertex(mesh, h);
    if (a != b) ++bucket_begin[std::min(a, b) + 1];
  }
  for (std::size_t v = 0; v < nv; ++v) bucket_begin[v + 1] += bucket_begin[v];
  // Each entry is (other end << 32 | halfedge): sorting the plain integers orders a bucket by
  // the other end, then by halfedge index (a stable ring order that keeps results independent
  // of hashing), without looking the ends up again in the comparisons.
  std::vector<std::uint64_t> bucket(bucket_begin[nv]);
  {
    std::vector<Index> fill(bucket_begin.begin(), bucket_begin.end() - 1);
    for (Index h = 0; h < nh; ++h) {
      const Index a = from_vertex(mesh, h), b = to_vertex(mesh, h);
      if (a == b) { c.radial_next[h] = h; continue; }
      bucket[fill[std::min(a, b)]++] = (std::uint64_t(std::max(a, b)) << 32) | h;
    }
  }
  c.edge_halfedge.reserve(nh / 2 + 1);
  auto halfedge = [](std::uint64_t e) { return Index(e & 0xffffffffu); };
  for (std::size_t v = 0; v < nv; ++v) {
    auto first = bucket.begin() + bucket_begin[v], last = bucket.begin() + bucket_begin[v + 1];
    std::sort(first, last);
    for (auto it = first; it != last;) {
      auto end = it + 1;
      while (end != last && (*end >> 32) == (*it >> 32)) ++end;
      const Index edge = static_cast<Index>(c.edge_halfedge.size());
      c.edge_halfedge.push_back(halfedge(*it));
      for (auto k = it; k != end; ++k) {
        c.radial_next[halfedge(*k)] = (k + 1 != end) ? halfedge(*(k + 1)) : halfedge(*it);
        c.halfedge_edge[halfedge(*k)] = edge;
      }
      it = end;
    }
  }
  return c;
}

}  // namespace gsp
