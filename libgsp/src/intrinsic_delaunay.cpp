#include "intrinsic_delaunay.hpp"

#include "disjoint_sets.hpp"
#include "prefetch_corners.hpp"
#include "side_by_side.hpp"

#include <gsp/connectivity.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace gsp::detail {
namespace {

// Angle opposite side c in a triangle with sides a, b, c (clamped: slivers round past +-1).
double opposite_angle(double a, double b, double c) {
  if (!(a > 0 && b > 0)) return 0;
  const double cosine = (a * a + b * b - c * c) / (2 * a * b);
  return std::acos(std::clamp(cosine, -1.0, 1.0));
}

// The twin of h when its edge is flippable, else kInvalidIndex. The twin may run the edge
// either way (a soup's inconsistently wound neighbour): a flip needs lengths only.
Index flippable_twin(const IntrinsicTriangulation& t, Index h) {
  const Index g = t.ring[h];
  if (g == h || t.ring[g] != h) return kInvalidIndex;   // boundary or non-manifold
  const Index f1 = face_of(h), f2 = face_of(g);
  if (f1 == f2 || t.skipped[f1] || t.skipped[f2]) return kInvalidIndex;
  const Triangle& a = t.triangles[f1];
  const Triangle& b = t.triangles[f2];
  if (a[corner_of(prev_halfedge(h))] == b[corner_of(prev_halfedge(g))]) return kInvalidIndex;
  return g;
}

// A pass over the halfedges in order reads each one's twin: its link, its face's corners and
// lengths, a cache miss each where the twin's face is far in face order. Asks for those of the
// halfedge kHalfedgesAhead further on (only loads: nothing changes; prefetch_corners.hpp).
[[gnu::always_inline]] inline void prefetch_twin(const IntrinsicTriangulation& t, Index h) {
  const Index ahead = h + kHalfedgesAhead;
  if (ahead >= t.ring.size()) return;
  const Index g = t.ring[ahead];
  __builtin_prefetch(t.ring.data() + g);
  __builtin_prefetch(t.triangles.data() + face_of(g));
  __builtin_prefetch(t.length.data() + 3 * face_of(g));
}

// Whether the twin g runs its edge the same way as h (the two faces are wound inconsistently).
bool same_direction(const IntrinsicTriangulation& t, Index h, Index g) {
  return t.triangles[face_of(h)][corner_of(h)] == t.triangles[face_of(g)][corner_of(g)];
}

bool is_delaunay(const IntrinsicTriangulation& t, Index h, Index g) {
  const double lab = t.length[h];
  // Both opposite angles at most 90 degrees (cosines >= 0): their sum is at most pi, and most
  // edges of a mesh end here without an acos (the same answer as the angles below).
  const double c1 = t.length[next_halfedge(h)], a1 = t.length[prev_halfedge(h)];
  const double c2 = t.length[next_halfedge(g)], a2 = t.length[prev_halfedge(g)];
  if (c1 > 0 && a1 > 0 && c2 > 0 && a2 > 0 && c1 * c1 + a1 * a1 - lab * lab >= 0 &&
      c2 * c2 + a2 * a2 - t.length[g] * t.length[g] >= 0)
    return true;
  const double ac = opposite_angle(t.length[next_halfedge(h)], t.length[prev_halfedge(h)], lab);
  const double ad = opposite_angle(t.length[next_halfedge(g)], t.length[prev_halfedge(g)], t.length[g]);
  return ac + ad <= 3.14159265358979323846 * (1 + 1e-9);
}

// The rule for a patch's winding (see the header), from what is measured of it as wound like
// its first face: 6 x its signed volume about the origin (used when it is closed and not 0),
// about its centroid with the sum of its tetrahedra's absolute values, and how many of its
// faces are reversed against the first. True: wind it the other way round.
bool wound_inwards(bool closed, double origin_volume, double centroid_volume, double tetrahedra,
                   std::size_t reversed, std::size_t faces) {
  if (closed && origin_volume != 0) return origin_volume < 0;
  // Open: about the centroid, a surface with a few holes still encloses most of its volume
  // one way; a sheet (|volume| small against its tetrahedra) leaves it to the majority.
  if (std::abs(centroid_volume) >= 0.25 * tetrahedra && centroid_volume != 0) return centroid_volume < 0;
  if (2 * reversed != faces) return 2 * reversed > faces;
  return centroid_volume < 0;
}

// Whether a patch (faces with their winding relative to its first face) is to be wound the
// other way round from its first face.
bool invert_patch(const IntrinsicTriangulation& t, const std::vector<Index>& patch,
                  const std::vector<std::int8_t>& reverse, std::size_t reversed, bool closed) {
  if (!t.positions) return 2 * reversed > patch.size();   // majority; a tie keeps the first face's
  auto volume = [&](Vec3 origin, double* unsigned_sum) {
    double v = 0;
    for (Index f : patch) {
      const Triangle& c = t.triangles[f];
      const Vec3 a = (*t.positions)[c[0]] - origin, b = (*t.positions)[c[1]] - origin, d = (*t.positions)[c[2]] - origin;
      const double x = dot(a, cross(b, d));
      v += reverse[f] ? -x : x;
      if (unsigned_sum) *unsigned_sum += std::abs(x);
    }
    return v;
  };
  const double origin_volume = closed ? volume(Vec3{0, 0, 0}, nullptr) : 0.0;
  if (closed && origin_volume != 0) return wound_inwards(true, origin_volume, 0, 0, reversed, patch.size());
  Vec3 centre{0, 0, 0};
  for (Index f : patch)
    for (Index x : t.triangles[f]) centre = centre + (1.0 / (3.0 * double(patch.size()))) * (*t.positions)[x];
  double tetrahedra = 0;
  const double v = volume(centre, &tetrahedra);
  return wound_inwards(closed, origin_volume, v, tetrahedra, reversed, patch.size());
}

// Reverses the marked faces: (a, b, c) -> (a, c, b), halfedge slots 0 and 2 trade places,
// slot 1 keeps its edge.
void reverse_faces(IntrinsicTriangulation& t, const std::vector<bool>& flip_face, std::size_t count) {
  t.reoriented = count;
  if (count == 0) return;
  const Index nf = Index(t.triangles.size()), nh = Index(t.length.size());
  auto moved = [&](Index h) {
    if (!flip_face[face_of(h)] || corner_of(h) == 1) return h;
    return corner_of(h) == 0 ? h + 2 : h - 2;
  };
  std::vector<double> length(nh);
  std::vector<Index> ring(nh);
  for (Index h = 0; h < nh; ++h) {
    length[moved(h)] = t.length[h];
    ring[moved(h)] = moved(t.ring[h]);
  }
  t.length = std::move(length);
  t.ring = std::move(ring);
  for (Index f = 0; f < nf; ++f)
    if (flip_face[f]) std::swap(t.triangles[f][1], t.triangles[f][2]);
}

// Any winding: each patch grown face by face from its first face (the first visit decides a
// face's winding relative to it), then wound as invert_patch says.
std::size_t orient_patches(IntrinsicTriangulation& t) {
  const Index nf = Index(t.triangles.size());
  // Per face: reverse relative to its patch's first face; patches grown across two-face edges.
  std::vector<std::int8_t> reverse(nf, -1);
  std::vector<Index> patch, stack;
  std::vector<bool> flip_face(nf, false);
  std::size_t count = 0;
  for (Index root = 0; root < nf; ++root) {
    if (reverse[root] >= 0 || t.skipped[root]) continue;
    patch.clear();
    reverse[root] = 0;
    stack.push_back(root);
    std::size_t reversed = 0;
    bool closed = true;   // every edge of the patch has exactly two faces, none skipped
    while (!stack.empty()) {
      const Index f = stack.back();
      stack.pop_back();
      patch.push_back(f);
      reversed += std::size_t(reverse[f]);
      for (Index i = 0; i < 3; ++i) {
        const Index h = 3 * f + i, g = t.ring[h];
        if (g == h || t.ring[g] != h) {   // boundary or non-manifold: not a patch link
          closed = false;
          continue;
        }
        const Index n = face_of(g);
        closed = closed && !t.skipped[n];
        if (n == f || t.skipped[n] || reverse[n] >= 0) continue;   // first visit decides (a Moebius
        reverse[n] = std::int8_t(reverse[f] ^ int(same_direction(t, h, g)));   // strip keeps one seam)
        stack.push_back(n);
      }
    }
    const bool invert = invert_patch(t, patch, reverse, reversed, closed);
    for (Index f : patch)
      if (bool(reverse[f]) != invert) flip_face[f] = true, ++count;
  }
  reverse_faces(t, flip_face, count);
  return count;
}

// The patches of a triangulation already consistent across every two-face edge (how most
// meshes come): the components over those edges, numbered in face order, with each one's face
// count and whether it is open (a boundary, non-manifold or skipped-neighbour edge).
struct WindingPatches {
  std::vector<Index> patch;   // per face
  std::vector<Index> faces;   // per patch
  std::vector<char> open;     // per patch
};

// The patches as above, from a pass in face order (the face-by-face growth of orient_patches
// reads the mesh in a random order: 0.4 s of a 2.2M-vertex preparation). False where some edge
// is wound inconsistently.
bool consistent_patches(const IntrinsicTriangulation& t, WindingPatches& out) {
  const Index nf = Index(t.triangles.size());
  DisjointSets sets(nf);   // over faces; a patch's root is its first face
  std::vector<char> open_face(nf, 0);   // a boundary, non-manifold or skipped-neighbour edge
  for (Index f = 0; f < nf; ++f) {
    for (Index i = 0; i < 3; ++i) {   // the twins ahead, and their faces' sets (a miss each otherwise)
      prefetch_twin(t, 3 * f + i);
      const Index ahead = 3 * f + i + kHalfedgesAhead;
      if (ahead < t.ring.size()) __builtin_prefetch(sets.parent.data() + face_of(t.ring[ahead]));
    }
    if (t.skipped[f]) continue;
    for (Index i = 0; i < 3; ++i) {
      const Index h = 3 * f + i, g = t.ring[h];
      if (g == h || t.ring[g] != h) {
        open_face[f] = 1;
        continue;
      }
      const Index n = face_of(g);
      if (t.skipped[n]) {
        open_face[f] = 1;
        continue;
      }
      if (n == f || h > g) continue;
      if (same_direction(t, h, g)) return false;
      sets.unite(f, n);
    }
  }
  // Roots, then patch numbers in face order (a root precedes the other faces of its patch),
  // with each patch's face count and whether it is open.
  for (Index f = 0; f < nf; ++f) sets.parent[f] = sets.find(f);
  out.patch = std::move(sets.parent);   // each face's root, then its patch number
  std::vector<Index>& patch = out.patch;
  out.faces.clear(), out.open.clear();
  for (Index f = 0; f < nf; ++f) {
    if (patch[f] == f) {
      patch[f] = Index(out.faces.size());
      out.faces.push_back(0), out.open.push_back(0);
    } else {
      patch[f] = patch[patch[f]];
    }
    if (t.skipped[f]) continue;
    ++out.faces[patch[f]];
    out.open[patch[f]] |= open_face[f];
  }
  return true;
}

// Which faces to reverse so that each patch is wound as wound_inwards says for a patch with
// no reversed face: every face of a patch to be turned (none without positions: the majority
// rule keeps a patch with no reversed face as it is). Reads only `triangles` (the patches'
// faces as numbered), `skipped` and `positions`, so it may run beside flips of a copy.
std::vector<bool> faces_to_reverse(const std::vector<Triangle>& triangles, const std::vector<bool>& skipped,
                                   const std::vector<Vec3>* positions, const WindingPatches& patches,
                                   std::size_t& count) {
  count = 0;
  if (!positions) return {};
  const Index nf = Index(triangles.size());
  const std::vector<Index>& patch = patches.patch;
  const std::vector<Index>& faces = patches.faces;
  const std::vector<char>& open = patches.open;
  const std::size_t n = faces.size();
  const std::vector<Vec3>& p = *positions;
  // What wound_inwards reads of each patch (none reversed): the volume about the origin of a
  // closed one; the centroid, the volume about it and the tetrahedra of the others (open, or
  // closed with a zero volume).
  std::vector<double> origin_volume(n, 0.0), volume(n, 0.0), tetrahedra(n, 0.0);
  std::vector<Vec3> centre(n, Vec3{0, 0, 0});
  for (Index f = 0; f < nf; ++f)
    if (!skipped[f] && !open[patch[f]]) {
      prefetch_corners(triangles, p, f);
      const Triangle& c = triangles[f];
      origin_volume[patch[f]] += dot(p[c[0]], cross(p[c[1]], p[c[2]]));
    }
  std::vector<char> about_centre(n, 0);
  bool any = false;
  for (std::size_t k = 0; k < n; ++k) any |= about_centre[k] = char(open[k] || origin_volume[k] == 0);
  for (Index f = 0; any && f < nf; ++f)
    if (!skipped[f] && about_centre[patch[f]]) {
      prefetch_corners(triangles, p, f);
      for (Index x : triangles[f]) centre[patch[f]] = centre[patch[f]] + (1.0 / (3.0 * double(faces[patch[f]]))) * p[x];
    }
  for (Index f = 0; any && f < nf; ++f) {
    if (skipped[f] || !about_centre[patch[f]]) continue;
    prefetch_corners(triangles, p, f);
    const Index k = patch[f];
    const Triangle& c = triangles[f];
    const Vec3 a = p[c[0]] - centre[k], b = p[c[1]] - centre[k], d = p[c[2]] - centre[k];
    const double x = dot(a, cross(b, d));
    volume[k] += x;
    tetrahedra[k] += std::abs(x);
  }
  std::vector<char> invert(n, 0);
  bool any_invert = false;
  for (std::size_t k = 0; k < n; ++k) {
    invert[k] = char(faces[k] > 0 && wound_inwards(!open[k], origin_volume[k], volume[k], tetrahedra[k], 0, faces[k]));
    any_invert = any_invert || invert[k];
  }
  if (!any_invert) return {};
  std::vector<bool> flip_face(nf, false);
  for (Index f = 0; f < nf; ++f)
    if (!skipped[f] && invert[patch[f]]) flip_face[f] = true, ++count;
  return flip_face;
}

// The winding of consistent patches: the same answer as orient_patches, from passes in face
// order. False, changing nothing, when some edge is inconsistent.
bool orient_consistent_patches(IntrinsicTriangulation& t) {
  WindingPatches patches;
  if (!consistent_patches(t, patches)) return false;
  std::size_t count = 0;
  const std::vector<bool> flip_face = faces_to_reverse(t.triangles, t.skipped, t.positions, patches, count);
  reverse_faces(t, flip_face, count);
  return true;
}

}  // namespace

std::size_t orient_consistently(IntrinsicTriangulation& t) {
  if (!orient_consistent_patches(t)) orient_patches(t);
  return t.reoriented;
}

namespace {

// The flips of make_intrinsic_delaunay, on faces wound already.
std::size_t flip_to_delaunay(IntrinsicTriangulation& t, std::size_t max_flips) {
  const Index nh = Index(t.length.size());
  // The flips run as from one stack that begins with every flippable edge (once, by its smaller
  // halfedge slot, in slot order) and gets the outer edges of each flip pushed on top: LIFO, so
  // the order (and with near-cocircular ties, the triangulation) is that stack's. The initial
  // part is walked by a cursor from the top slot down instead of being stored (an entry per
  // edge), and an edge found Delaunay in the first pass is passed over when the cursor reaches
  // it unless a flip has changed one of its faces since (nothing it depends on can change
  // otherwise): one test per edge instead of two.
  constexpr char kPending = 1, kPendingDelaunay = 2;   // in the stack; the latter Delaunay as first seen
  std::vector<char> queued(nh, 0);
  for (Index h = 0; h < nh; ++h) {
    prefetch_twin(t, h);
    if (!(h < t.ring[h])) continue;   // each edge once, by its smaller slot (and no boundary)
    const Index g = flippable_twin(t, h);
    if (g != kInvalidIndex) queued[h] = is_delaunay(t, h, g) ? kPendingDelaunay : kPending;
  }
  std::vector<char> changed(t.triangles.size(), 0);   // faces a flip has rewritten
  std::vector<Index> stack;                            // pushed by flips, above the initial part
  Index cursor = nh;                                   // the initial part: slots below it
  std::size_t flips = 0;
  while (flips < max_flips) {
    Index h;
    if (!stack.empty()) {
      h = stack.back();
      stack.pop_back();
    } else {
      while (cursor > 0 && !queued[cursor - 1]) --cursor;
      if (cursor == 0) break;
      h = --cursor;
      if (queued[h] == kPendingDelaunay && !changed[face_of(h)] && !changed[face_of(t.ring[h])]) {
        queued[h] = 0;
        continue;
      }
    }
    queued[h] = 0;
    const Index g = flippable_twin(t, h);
    if (g == kInvalidIndex || is_delaunay(t, h, g)) continue;
    const Index f1 = face_of(h), f2 = face_of(g);
    const Index hn = next_halfedge(h), hp = prev_halfedge(h), gn = next_halfedge(g), gp = prev_halfedge(g);
    const Index a = t.triangles[f1][corner_of(h)], b = t.triangles[f1][corner_of(hn)];
    const Index c = t.triangles[f1][corner_of(hp)], d = t.triangles[f2][corner_of(gp)];
    // f2 wound like f1: g = b->a, gn = a->d, gp = d->b; wound the other way: g = a->b,
    // gn = b->d, gp = d->a.
    const bool reversed = same_direction(t, h, g);
    const Index ad = reversed ? gp : gn, db = reversed ? gn : gp;
    const double lab = t.length[h], lbc = t.length[hn], lca = t.length[hp];
    const double lad = t.length[ad], ldb = t.length[db];
    // Unfold: a = (0, 0), b = (lab, 0), c above, d below; the new diagonal is |cd|.
    const double cx = (lab * lab + lca * lca - lbc * lbc) / (2 * lab);
    const double cy = std::sqrt(std::max(0.0, lca * lca - cx * cx));
    const double dx = (lab * lab + lad * lad - ldb * ldb) / (2 * lab);
    const double dy = -std::sqrt(std::max(0.0, lad * lad - dx * dx));
    const double lcd = std::hypot(cx - dx, cy - dy);
    if (!(lcd > 0) || !std::isfinite(lcd)) continue;
    // Outer halfedges and where they go: f1' = (c, a, d), f2' = (d, b, c), both wound like f1.
    const Index outer_old[4] = {hp, ad, db, hn};   // edges c-a, a-d, d-b, b-c
    const Index base1 = 3 * f1, base2 = 3 * f2;
    const Index outer_new[4] = {base1 + 0, base1 + 1, base2 + 0, base2 + 1};
    const double outer_len[4] = {lca, lad, ldb, lbc};
    Index outer_ring[4];
    for (int k = 0; k < 4; ++k) outer_ring[k] = t.ring[outer_old[k]];
    auto remap = [&](Index x) {
      for (int k = 0; k < 4; ++k)
        if (x == outer_old[k]) return outer_new[k];
      return x;
    };
    t.triangles[f1] = {c, a, d};
    t.triangles[f2] = {d, b, c};
    for (int k = 0; k < 4; ++k) {
      t.length[outer_new[k]] = outer_len[k];
      // Its ring partner (if any) must now point at the new index; a ring of one points at itself.
      const Index partner = outer_ring[k] == outer_old[k] ? outer_new[k] : remap(outer_ring[k]);
      t.ring[outer_new[k]] = partner;
    }
    // Every other halfedge whose ring link pointed at a moved halfedge.
    for (int k = 0; k < 4; ++k) {
      if (outer_ring[k] == outer_old[k]) continue;
      // Walk the partner's ring to the link that points to the old index.
      Index x = outer_ring[k];
      for (Index guard = 0; guard < nh; ++guard) {
        const Index nx = t.ring[x];
        if (nx == outer_old[k]) {
          t.ring[x] = outer_new[k];
          break;
        }
        if (nx == outer_new[k]) break;   // already relinked (the partner moved too)
        x = nx;
      }
    }
    t.length[base1 + 2] = t.length[base2 + 2] = lcd;   // d->c and c->d
    t.ring[base1 + 2] = base2 + 2;
    t.ring[base2 + 2] = base1 + 2;
    ++flips;
    if (t.log) t.log->push_back({f1, f2, a, b, c, d, lab, cx, cy, dx, dy});
    changed[f1] = changed[f2] = 1;
    for (Index x : {base1 + 0, base1 + 1, base2 + 0, base2 + 1})
      if (!queued[x] && flippable_twin(t, x) != kInvalidIndex) stack.push_back(x), queued[x] = kPending;
  }
  t.flipped = std::move(changed);
  return flips;
}

}  // namespace

std::size_t make_intrinsic_delaunay(IntrinsicTriangulation& t, std::size_t max_flips) {
  orient_consistently(t);
  return flip_to_delaunay(t, max_flips);
}

std::size_t make_intrinsic_delaunay_beside(IntrinsicTriangulation& t, std::size_t max_flips,
                                           const std::vector<Triangle>& wound,
                                           const std::function<IntrinsicTriangulation()>& again) {
  if (!t.positions) return make_intrinsic_delaunay(t, max_flips);
  WindingPatches patches;
  if (!consistent_patches(t, patches)) {   // inconsistent: grown face by face (no second union pass)
    orient_patches(t);
    return flip_to_delaunay(t, max_flips);
  }
  std::vector<bool> flip_face;
  std::size_t count = 0, flips = 0;
  side_by_side([&] { flip_face = faces_to_reverse(wound, t.skipped, t.positions, patches, count); },
               [&] { flips = flip_to_delaunay(t, max_flips); });
  if (count == 0) return flips;   // wound as it came: what make_intrinsic_delaunay flips
  t = again();
  reverse_faces(t, flip_face, count);
  return flip_to_delaunay(t, max_flips);
}

}  // namespace gsp::detail
