#include "prefetch_corners.hpp"

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
  c.halfedge_edge.resize(nh);

  // Vertex -> corners by counting sort (linear time, corners in face order), and the
  // halfedges grouped by their smaller endpoint (bucket = that vertex), then by the larger one
  // inside the bucket: buckets are small (vertex valence), so this is linear overall and
  // touches memory in vertex order. One pass over the faces counts both, one fills both.
  c.vertex_corner_begin.assign(nv + 1, 0);
  std::vector<Index> bucket_begin(nv + 1, 0);
  for (std::size_t f = 0; f < nf; ++f) {
    const Triangle& t = mesh.triangles[f];
    if (f + detail::kFacesAhead < nf) {   // counters of the corners ahead (prefetch_corners.hpp)
      const Triangle& q = mesh.triangles[f + detail::kFacesAhead];
      for (int i = 0; i < 3; ++i)
        if (q[i] < nv) {
          __builtin_prefetch(c.vertex_corner_begin.data() + q[i] + 1, 1);
          __builtin_prefetch(bucket_begin.data() + std::min(q[i], q[i == 2 ? 0 : i + 1]) + 1, 1);
        }
    }
    for (int i = 0; i < 3; ++i) {
      const Index a = t[i], b = t[i == 2 ? 0 : i + 1];
      if (a >= nv) throw InvalidInput("triangle index " + std::to_string(a) + " out of range");
      ++c.vertex_corner_begin[a + 1];
      if (a != b) ++bucket_begin[std::min(a, b) + 1];
    }
  }
  for (std::size_t v = 0; v < nv; ++v) {
    c.vertex_corner_begin[v + 1] += c.vertex_corner_begin[v];
    bucket_begin[v + 1] += bucket_begin[v];
  }
  c.vertex_corners.resize(nh);
  // Each entry is (other end << 32 | halfedge): sorting the plain integers orders a bucket by
  // the other end, then by halfedge index (a stable ring order that keeps results independent
  // of hashing), without looking the ends up again in the comparisons.
  std::vector<std::uint64_t> bucket(bucket_begin[nv]);
  {
    std::vector<Index> corner_fill(c.vertex_corner_begin.begin(), c.vertex_corner_begin.end() - 1);
    std::vector<Index> bucket_fill(bucket_begin.begin(), bucket_begin.end() - 1);
    for (Index f = 0; f < Index(nf); ++f) {
      const Triangle& t = mesh.triangles[f];
      detail::prefetch_corners(mesh.triangles, corner_fill, f);
      detail::prefetch_corners(mesh.triangles, bucket_fill, f);
      for (Index i = 0; i < 3; ++i) {
        const Index h = 3 * f + i, a = t[i], b = t[i == 2 ? 0 : i + 1];
        c.vertex_corners[corner_fill[a]++] = h;
        if (a == b) {
          c.radial_next[h] = h;
          c.halfedge_edge[h] = kInvalidIndex;
          continue;
        }
        bucket[bucket_fill[std::min(a, b)]++] = (std::uint64_t(std::max(a, b)) << 32) | h;
      }
    }
  }
  c.edge_halfedge.reserve(nh / 2 + 1);
  const std::uint64_t* const bucket_end = bucket.data() + bucket.size();
  auto halfedge = [](std::uint64_t e) { return Index(e & 0xffffffffu); };
  for (std::size_t v = 0; v < nv; ++v) {
    std::uint64_t* first = bucket.data() + bucket_begin[v];
    std::uint64_t* last = bucket.data() + bucket_begin[v + 1];
    // Most buckets hold a vertex's few edges: an insertion sort without std::sort's set-up;
    // a fan's centre (thousands of edges in CAD files) gets std::sort.
    if (last - first > 16) {
      std::sort(first, last);
    } else {
      for (std::uint64_t* i = first + (first != last); i < last; ++i) {
        const std::uint64_t x = *i;
        std::uint64_t* j = i;
        for (; j != first && *(j - 1) > x; --j) *j = *(j - 1);
        *j = x;
      }
    }
    for (std::uint64_t* it = first; it != last;) {
      std::uint64_t* end = it + 1;
      while (end != last && (*end >> 32) == (*it >> 32)) ++end;
      const Index edge = static_cast<Index>(c.edge_halfedge.size());
      c.edge_halfedge.push_back(halfedge(*it));
      if (end - it > 2) c.nonmanifold_edges.push_back(edge);
      for (std::uint64_t* k = it; k != end; ++k) {
        if (k + detail::kHalfedgesAhead < bucket_end) {   // the halfedges' slots ahead, written below
          const Index ahead = halfedge(*(k + detail::kHalfedgesAhead));
          __builtin_prefetch(c.radial_next.data() + ahead, 1);
          __builtin_prefetch(c.halfedge_edge.data() + ahead, 1);
        }
        c.radial_next[halfedge(*k)] = (k + 1 != end) ? halfedge(*(k + 1)) : halfedge(*it);
        c.halfedge_edge[halfedge(*k)] = edge;
      }
      it = end;
    }
  }
  return c;
}

}  // namespace gsp
