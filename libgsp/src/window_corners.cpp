#include "window_corners.hpp"

#include "ring_links.hpp"
#include "window_bounds.hpp"

#include <gsp/intrinsic/coplanar_faces.hpp>
#include <gsp/intrinsic/vertex_kinds.hpp>

#include <cmath>

namespace gsp::detail {

namespace {

constexpr double kPi = 3.14159265358979323846;

using intrinsic::coplanar_across;
using intrinsic::face_normal;

}  // namespace

std::vector<std::uint8_t> window_candidates(const TriangleMesh& mesh, const std::vector<std::uint8_t>& vertex_kind,
                                            const std::vector<double>& angle,
                                            const std::vector<std::uint8_t>& boundary_halfedge,
                                            const std::vector<bool>& skipped_face,
                                            const std::vector<Index>& nonmanifold) {
  std::vector<std::uint8_t> candidate(vertex_kind.size(), 0);
  for (std::size_t v = 0; v < vertex_kind.size(); ++v) candidate[v] = vertex_kind[v] == intrinsic::kSaddleVertex;
  for (Index h = 0; h < Index(boundary_halfedge.size()); ++h) {
    if (!boundary_halfedge[h] || skipped_face[face_of(h)]) continue;
    const Triangle& t = mesh.triangles[face_of(h)];
    for (Index v : {t[corner_of(h)], t[corner_of(next_halfedge(h))]})
      if (angle[v] > kPi * (1 + intrinsic::kSaddleExcess)) candidate[v] = 1;
  }
  for (Index v : nonmanifold) candidate[v] = 0;
  return candidate;
}

std::vector<std::uint8_t> window_corners(const TriangleMesh& mesh, const std::vector<Index>& ring,
                                         const std::vector<std::uint8_t>& candidate,
                                         const std::vector<bool>& skipped_face) {
  const std::vector<Triangle>& tris = mesh.triangles;
  const std::vector<Vec3>& pos = mesh.positions;
  std::vector<std::uint8_t> corner;
  for (Index f = 0; f < Index(tris.size()); ++f) {
    if (skipped_face[f]) continue;
    const Triangle& t = tris[f];
    bool cand[3];
    for (int i = 0; i < 3; ++i) cand[i] = candidate[t[i]] != 0;
    if (!cand[0] && !cand[1] && !cand[2]) continue;   // no edge of f has a candidate end
    const Vec3 n = face_normal(tris, pos, f);
    for (Index i = 0; i < 3; ++i) {
      const Index h = 3 * f + i, link = ring[h], g = link & kRingIndexMask;
      // Each edge of two faces once (the pair's lower halfedge); boundaries and fans of more
      // faces have no plane to share.
      if (!(link & kRingPair) || g < h || skipped_face[face_of(g)]) continue;
      const Index a = t[i], b = t[i == 2 ? 0 : i + 1];
      const bool sa = cand[i], sb = cand[i == 2 ? 0 : i + 1];
      if (!sa && !sb) continue;
      if (!corner.empty() && (!sa || corner[a]) && (!sb || corner[b])) continue;   // nothing new to mark
      if (!coplanar_across(tris, pos, n, h, g)) continue;
      if (corner.empty()) corner.assign(mesh.num_vertices(), 0);
      if (sa) corner[a] = 1;
      if (sb) corner[b] = 1;
    }
  }
  return corner;
}

std::vector<std::uint8_t> window_face_flags(const std::vector<Triangle>& triangles, const std::vector<Index>& ring,
                                            const std::vector<Index>& corner_begin, const std::vector<Index>& corners,
                                            const std::vector<Vec3>& positions,
                                            const std::vector<std::uint8_t>& window_corner,
                                            const std::vector<bool>& skipped_face) {
  constexpr std::uint8_t kSeen = 0x80;   // queued; cleared at the end
  std::vector<std::uint8_t> flags(triangles.size(), 0);
  std::vector<Index> queue;
  for (Index v = 0; v < Index(window_corner.size()); ++v) {
    if (!window_corner[v]) continue;
    for (Index k = corner_begin[v]; k < corner_begin[v + 1]; ++k) {
      const Index c = corners[k], f = face_of(c);
      if (skipped_face[f]) continue;
      flags[f] |= std::uint8_t(kWindowCorner0 << corner_of(c));
      if (!(flags[f] & kSeen)) flags[f] |= kSeen, queue.push_back(f);
    }
  }
  // The planar regions round them, one face at a time over the coplanar edges.
  for (std::size_t next = 0; next < queue.size(); ++next) {
    const Index f = queue[next];
    const Vec3 n = face_normal(triangles, positions, f);
    for (Index i = 0; i < 3; ++i) {
      const Index h = 3 * f + i, link = ring[h], g = link & kRingIndexMask, fg = face_of(g);
      if (!(link & kRingPair) || (flags[f] & (kWindowEdge0 << i)) || skipped_face[fg]) continue;
      if (!coplanar_across(triangles, positions, n, h, g)) continue;
      flags[f] |= std::uint8_t(kWindowEdge0 << i);
      flags[fg] |= std::uint8_t(kWindowEdge0 << corner_of(g));
      if (!(flags[fg] & kSeen)) flags[fg] |= kSeen, queue.push_back(fg);
    }
  }
  for (Index f : queue) flags[f] &= std::uint8_t(~kSeen);
  return flags;
}

}  // namespace gsp::detail
