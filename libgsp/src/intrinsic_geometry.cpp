#include "intrinsic_geometry.hpp"
#include "prefetch_corners.hpp"
#include "ring_links.hpp"

#include <gsp/intrinsic/coplanar_faces.hpp>
#include <gsp/intrinsic/edge_lengths.hpp>
#include <gsp/intrinsic/saddle_creases.hpp>

#include <gsp/errors.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace gsp::detail {
namespace {

// The angle between sides a and b of a triangle whose third side is c. atan2 of (4 area,
// a^2 + b^2 - c^2) with Kahan's ordering of Heron's product stays accurate for slivers, where
// acos of the cosine loses half the digits. A zero-length side gives 0, like the 3D formula.
double corner_angle(double a, double b, double c) {
  if (!(a > 0 && b > 0)) return 0;
  double s[3] = {a, b, c};
  std::sort(s, s + 3, [](double x, double y) { return x > y; });
  const double x = s[0], y = s[1], z = s[2];   // x >= y >= z
  const double p = (x + (y + z)) * (z - (x - y)) * (z + (x - y)) * (x + (y - z));
  const double four_area = std::sqrt(std::max(0.0, p));
  return std::atan2(four_area, (a * a + b * b) - c * c);
}

}  // namespace

bool needs_double_lengths(const std::vector<double>& length, const std::vector<bool>& skipped_face,
                          const std::vector<char>* only_faces) {
  for (std::size_t f = 0; f < skipped_face.size(); ++f) {
    if (skipped_face[f] || (only_faces && !(*only_faces)[f])) continue;
    // x >= y >= z without a sort call (this runs over every face, twice per solver).
    const double a = length[3 * f], b = length[3 * f + 1], c = length[3 * f + 2];
    const double hi = std::max(a, b), lo = std::min(a, b);
    const double x = std::max(hi, c), z = std::min(lo, c), y = std::max(lo, std::min(hi, c));
    if (!(x > 0)) continue;                       // all corners at one point: nothing to unfold
    // 16 area^2 by Heron's formula in Kahan's ordering (accurate for needles and caps).
    const double p = (x + (y + z)) * (z - (x - y)) * (z + (x - y)) * (x + (y - z));
    const double four_area = std::sqrt(std::max(0.0, p));
    const double height = four_area / (2 * x);    // over the longest edge
    if (!(height * kFloatAspectLimit > x)) return true;
  }
  return false;
}

void validate_halfedge_lengths(const TriangleMesh& mesh, const std::vector<double>& length) {
  if (length.size() != 3 * mesh.num_faces())
    throw InvalidInput("edge lengths: " + std::to_string(length.size()) + " values for " +
                       std::to_string(3 * mesh.num_faces()) + " halfedges (3 per face)");
  for (std::size_t f = 0; f < mesh.num_faces(); ++f) {
    const double* l = &length[3 * f];
    for (int i = 0; i < 3; ++i)
      if (!std::isfinite(l[i]) || l[i] < 0)
        throw InvalidInput("edge lengths: face " + std::to_string(f) + " halfedge " + std::to_string(i) +
                           " has length " + std::to_string(l[i]) + " (must be finite and >= 0)");
    const double longest = std::max({l[0], l[1], l[2]});
    // The longest edge against the other two: rounding of lengths computed from a metric
    // (and float-stored slivers) leaves degenerate faces a hair outside.
    if (longest > (l[0] + l[1] + l[2] - longest) + 1e-6 * longest)
      throw InvalidInput("edge lengths: face " + std::to_string(f) + " violates the triangle inequality (" +
                         std::to_string(l[0]) + ", " + std::to_string(l[1]) + ", " + std::to_string(l[2]) + ")");
  }
}

void canonical_corners(const std::vector<double>& length, Index f, double scale, double out[3][2]) {
  const double len[3] = {scale * length[3 * f], scale * length[3 * f + 1], scale * length[3 * f + 2]};
  out[0][0] = out[0][1] = 0;
  out[1][0] = len[0], out[1][1] = 0;
  intrinsic::canonical_corner2(len, out[2][0], out[2][1]);
}

}  // namespace gsp::detail

namespace gsp::intrinsic {

std::vector<bool> skipped_faces(const TriangleMesh& mesh) {
  std::vector<bool> skipped(mesh.num_faces());
  for (std::size_t f = 0; f < mesh.num_faces(); ++f) skipped[f] = repeats_vertex(mesh.triangles[f]);
  return skipped;
}

std::size_t skip_duplicate_faces(const TriangleMesh& mesh, const Connectivity& conn, std::vector<bool>& skipped) {
  std::size_t marked = 0;
  std::vector<std::pair<Index, Index>> ring;   // (third vertex, face) of one edge's faces
  for (Index e : conn.nonmanifold_edges) {
    ring.clear();
    const Index h0 = conn.edge_halfedge[e];
    Index h = h0;
    do {
      const Index f = face_of(h);
      // A copy names the edge's two ends and the same third vertex.
      if (!skipped[f]) ring.push_back({mesh.triangles[f][corner_of(prev_halfedge(h))], f});
      h = conn.radial_next[h];
    } while (h != h0);
    std::sort(ring.begin(), ring.end());
    for (std::size_t i = 1; i < ring.size(); ++i)
      if (ring[i].first == ring[i - 1].first && !skipped[ring[i].second]) skipped[ring[i].second] = true, ++marked;
  }
  return marked;
}

std::vector<bool> skipped_faces(const TriangleMesh& mesh, const Connectivity& conn) {
  std::vector<bool> skipped = skipped_faces(mesh);
  skip_duplicate_faces(mesh, conn, skipped);
  return skipped;
}

Index kept_copy(const std::vector<Triangle>& triangles, const std::vector<Index>& corner_begin,
                const std::vector<Index>& corners, const std::vector<bool>& skipped, Index f,
                std::array<double, 3>& bary) {
  const Triangle& t = triangles[f];
  if (!skipped[f] || repeats_vertex(t)) return f;
  for (Index k = corner_begin[t[0]]; k < corner_begin[t[0] + 1]; ++k) {
    const Index g = face_of(corners[k]);
    if (skipped[g]) continue;
    const Triangle& u = triangles[g];
    std::array<double, 3> b{};
    int found = 0;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        if (u[j] == t[i]) b[j] = bary[i], ++found;
    if (found == 3) {
      bary = b;
      return g;
    }
  }
  return f;
}

std::vector<double> halfedge_lengths(const TriangleMesh& mesh) {
  std::vector<double> length(3 * mesh.num_faces());
  for (std::size_t f = 0; f < mesh.num_faces(); ++f) {
    detail::prefetch_corners(mesh.triangles, mesh.positions, f);
    for (int i = 0; i < 3; ++i)
      length[3 * f + i] = distance(mesh.positions[mesh.triangles[f][i]], mesh.positions[mesh.triangles[f][(i + 1) % 3]]);
  }
  return length;
}

void snap_zero_lengths(std::vector<double>& length, const std::vector<char>* only_faces) {
  for (std::size_t f = 0; 3 * f < length.size(); ++f) {
    if (only_faces && !(*only_faces)[f]) continue;
    double* l = &length[3 * f];
    const double longest = std::max({l[0], l[1], l[2]});
    for (int i = 0; i < 3; ++i)
      if (l[i] <= kZeroEdge * longest) l[i] = 0;
  }
}

double mean_edge_length(const std::vector<double>& length, const std::vector<bool>& skipped_face) {
  double sum = 0;   // in double: millions of float lengths would lose digits
  std::size_t n = 0;
  for (std::size_t f = 0; f < skipped_face.size(); ++f) {
    if (skipped_face[f]) continue;
    for (int i = 0; i < 3; ++i) sum += length[3 * f + i];
    n += 3;
  }
  return (n > 0 && sum > 0) ? sum / double(n) : 1.0;
}

CornerAngleSums corner_angle_sums(const TriangleMesh& mesh, const std::vector<bool>& skipped_face,
                                  const std::vector<double>* length) {
  CornerAngleSums sums;
  sums.angle.assign(mesh.num_vertices(), 0.0);
  sums.used.assign(mesh.num_vertices(), 0);
  add_corner_angles(mesh, skipped_face, length, sums, 0, mesh.num_faces());
  return sums;
}

void add_corner_angles(const TriangleMesh& mesh, const std::vector<bool>& skipped_face,
                       const std::vector<double>* length, CornerAngleSums& sums, std::size_t begin, std::size_t end) {
  constexpr double kPi = 3.14159265358979323846;
  for (std::size_t f = begin; f < end; ++f) {
    detail::prefetch_corners(mesh.triangles, mesh.positions, f);
    detail::prefetch_corners(mesh.triangles, sums.angle, f);
    detail::prefetch_corners(mesh.triangles, sums.used, f);
    if (skipped_face[f]) continue;
    const Triangle& t = mesh.triangles[f];
    double a[3];
    if (length) {
      const double* l = &(*length)[3 * f];
      for (int i = 0; i < 3; ++i) a[i] = detail::corner_angle(l[i], l[(i + 2) % 3], l[(i + 1) % 3]);
    } else {
      // |cross| is twice the area at every corner: one cross product, and the third angle
      // from the other two (a degenerate face keeps its own atan2: its corners may sum to 0).
      const Vec3 p0 = mesh.positions[t[0]], p1 = mesh.positions[t[1]], p2 = mesh.positions[t[2]];
      const Vec3 e01 = p1 - p0, e02 = p2 - p0, e12 = p2 - p1;
      const Vec3 n = cross(e01, e02);
      const double twice_area = norm(n);
      if (!sums.normal.empty()) sums.normal[f] = unit_normal(n);
      a[0] = std::atan2(twice_area, dot(e01, e02));
      a[1] = std::atan2(twice_area, -dot(e01, e12));
      a[2] = twice_area > 0 ? kPi - a[0] - a[1] : std::atan2(0.0, dot(e02, e12));
    }
    for (int i = 0; i < 3; ++i) {
      sums.angle[t[i]] += a[i];
      sums.used[t[i]] = 1;
    }
  }
}

std::vector<std::uint8_t> vertex_kinds(const TriangleMesh& mesh, const std::vector<std::uint8_t>& boundary_halfedge,
                                       const std::vector<bool>& skipped_face,
                                       const std::vector<Index>& nonmanifold_vertices,
                                       const std::vector<double>* length) {
  return vertex_kinds(mesh, corner_angle_sums(mesh, skipped_face, length), boundary_halfedge, skipped_face,
                      nonmanifold_vertices);
}

std::vector<std::uint8_t> vertex_kinds(const TriangleMesh& mesh, const CornerAngleSums& sums,
                                       const std::vector<std::uint8_t>& boundary_halfedge,
                                       const std::vector<bool>& skipped_face,
                                       const std::vector<Index>& nonmanifold_vertices,
                                       const std::vector<Index>* crease_links) {
  constexpr double kPi = 3.14159265358979323846;
  const std::size_t nv = mesh.num_vertices();
  const std::vector<double>& angle = sums.angle;
  const std::vector<std::uint8_t>& used = sums.used;
  std::vector<std::uint8_t> boundary(nv, 0);
  for (std::size_t f = 0; f < mesh.num_faces(); ++f) {
    if (skipped_face[f]) continue;
    const Triangle& t = mesh.triangles[f];
    for (int i = 0; i < 3; ++i)
      if (boundary_halfedge[3 * f + i]) boundary[t[i]] = boundary[t[(i + 1) % 3]] = 1;
  }
  constexpr double tol = kFlatAngleTolerance;
  std::vector<std::uint8_t> kind(nv, kPlainVertex);
  for (std::size_t v = 0; v < nv; ++v) {
    if (!used[v]) continue;
    const bool flat = boundary[v] ? angle[v] <= kPi * (1 + tol) : std::abs(angle[v] - 2 * kPi) <= 2 * kPi * tol;
    const bool saddle = !boundary[v] && angle[v] > 2 * kPi * (1 + kSaddleExcess);
    const bool convex = !boundary[v] && angle[v] < 2 * kPi;
    kind[v] = flat ? kFlatVertex : saddle ? kSaddleVertex : convex ? kConvexVertex : kPlainVertex;
  }
  std::vector<std::uint8_t> joins_fans(nv, 0);
  for (Index v : nonmanifold_vertices) joins_fans[v] = 1;
  // What each vertex's neighbours are, in one pass over the faces: kSaddleNext where one is a
  // saddle, kCurvedNext where one is neither flat nor joining several fans, kTurnNext where
  // one is a saddle or plain (a vertex no rule calls flat or convex: a mildly saddle one, a
  // boundary corner), not joining several fans.
  constexpr std::uint8_t kSaddleNext = 1, kCurvedNext = 2, kTurnNext = 4;
  std::vector<std::uint8_t> next_to(nv, 0);
  for (std::size_t f = 0; f < mesh.num_faces(); ++f) {
    if (skipped_face[f]) continue;
    const Triangle& t = mesh.triangles[f];
    for (int i = 0; i < 3; ++i)
      for (int j = 1; j < 3; ++j) {
        const Index b = t[(i + j) % 3];
        const bool curved = kind[b] != kFlatVertex && !joins_fans[b];
        next_to[t[i]] |= std::uint8_t((kind[b] == kSaddleVertex ? kSaddleNext : 0) | (curved ? kCurvedNext : 0) |
                                      (curved && kind[b] != kConvexVertex ? kTurnNext : 0));
      }
  }
  // Flat vertices made plain below whose curved neighbours are all convex: convex themselves
  // where they are alone on a crease (apply_crease_rules).
  std::vector<Index> lone;
  for (std::size_t v = 0; v < nv; ++v) {
    // Barely saddle vertices go straight on like convex ones, unless a saddle is next to
    // them: in a cluster of negative curvature (a CAD part's concave fillet) the lines carried
    // past them go on to pass the saddles at the wrong side (docs/gsp-core.md, rule 6).
    if (kind[v] == kPlainVertex && used[v] && !boundary[v] && angle[v] <= 2 * kPi * (1 + kStraightExcess) &&
        !(next_to[v] & kSaddleNext))
      kind[v] = kConvexVertex;
    // A vertex joining several fans has no single angle sum.
    if (joins_fans[v]) kind[v] = kPlainVertex;
    // Flat only inside a flat region: a flat vertex with a curved neighbour (angle sum off
    // 2 pi, or a reflex boundary corner) stays plain, so no line is carried past it (rule 4
    // of docs/gsp-core.md: on midpoint-split meshes every new vertex is flat next to curved
    // old ones, and lines carried past them came out short). Vertices joining
    // several fans have no angle sum to judge by and do not count (the local triangles of
    // point clouds overlap at many of them, on planes too).
    if (kind[v] == kFlatVertex && (next_to[v] & kCurvedNext)) {
      kind[v] = kPlainVertex;
      if (!(next_to[v] & kTurnNext)) lone.push_back(Index(v));
    }
  }
  if (crease_links) {
    std::vector<std::uint8_t> interior(nv);   // the vertices with an angle sum of their own
    for (std::size_t v = 0; v < nv; ++v) interior[v] = used[v] && !boundary[v] && !joins_fans[v];
    apply_crease_rules(mesh, angle, interior, skipped_face, *crease_links, sums.normal, lone, kind);
  }
  return kind;
}

std::vector<std::uint8_t> boundary_halfedges(const Connectivity& conn, const std::vector<bool>& skipped_face,
                                             const std::vector<double>& length) {
  std::vector<std::uint8_t> boundary(conn.num_halfedges());
  for (Index h = 0; h < Index(boundary.size()); ++h) boundary[h] = next_crossed(conn, skipped_face, length, h) == h;
  return boundary;
}

std::vector<Index> nonmanifold_vertices(const TriangleMesh& mesh, const Connectivity& conn,
                                        const std::vector<Index>& bridge_vertices,
                                        const std::vector<Index>& coincident_vertices,
                                        const std::vector<bool>* skipped_face) {
  std::vector<Index> joins = bridge_vertices;
  joins.insert(joins.end(), coincident_vertices.begin(), coincident_vertices.end());
  for (Index e : conn.nonmanifold_edges) {
    const Index h0 = conn.edge_halfedge[e];
    std::size_t taking_part = 0;
    Index h = h0;
    do {
      taking_part += !skipped_face || !(*skipped_face)[face_of(h)];
      h = conn.radial_next[h];
    } while (h != h0);
    if (taking_part > 2) {
      joins.push_back(from_vertex(mesh, h0));
      joins.push_back(to_vertex(mesh, h0));
    }
  }
  return joins;
}

std::vector<std::uint8_t> vertex_kinds(const TriangleMesh& mesh, const Connectivity& conn,
                                       const std::vector<bool>& skipped_face,
                                       const std::vector<Index>& bridge_vertices,
                                       const std::vector<Index>& coincident_vertices,
                                       const std::vector<double>& length, bool angles_from_length) {
  const std::vector<std::uint8_t> boundary = boundary_halfedges(conn, skipped_face, length);
  const std::vector<Index> nonmanifold =
      nonmanifold_vertices(mesh, conn, bridge_vertices, coincident_vertices, &skipped_face);
  CornerAngleSums sums;
  sums.angle.assign(mesh.num_vertices(), 0.0);
  sums.used.assign(mesh.num_vertices(), 0);
  if (!angles_from_length) sums.normal.assign(mesh.num_faces(), {0, 0, 0});   // for the creases
  add_corner_angles(mesh, skipped_face, angles_from_length ? &length : nullptr, sums, 0, mesh.num_faces());
  // The crease limit for 3D angles (intrinsic lengths have no creases), as the core applies it:
  // its radial links' encoding (ring_links.hpp), pairs where an edge joins two faces that take part.
  if (angles_from_length) return vertex_kinds(mesh, sums, boundary, skipped_face, nonmanifold);
  if (conn.num_halfedges() > detail::kRingIndexMask) throw InvalidInput("mesh too large: more than 2^29 - 1 halfedges");
  auto runs_up = [&](Index h) { return from_vertex(mesh, h) < to_vertex(mesh, h); };
  std::vector<Index> links(conn.num_halfedges());
  for (Index h = 0; h < Index(links.size()); ++h) {
    const Index g = conn.radial_next[h];
    links[h] = detail::ring_link(h, g, g != h && conn.radial_next[g] == h && !skipped_face[face_of(g)], runs_up);
  }
  return vertex_kinds(mesh, sums, boundary, skipped_face, nonmanifold, &links);
}

}  // namespace gsp::intrinsic
