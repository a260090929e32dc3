#include "edge_remesh.hpp"

#include "sizing_field.hpp"
#include "triangle_geometry.hpp"

#include <gsp/cvt/features.hpp>

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include <algorithm>
#include <cmath>
#include <queue>
#include <utility>
#include <vector>

namespace gsp::cvt::detail {

namespace {

struct Traits : OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
};
using Mesh = OpenMesh::TriMesh_ArrayKernelT<Traits>;
using P = Mesh::Point;

// Crease curves shorter than this many spacings are not kept as feature lines.
constexpr double kMinCurve = 2.0;

P normal_of(const P& a, const P& b, const P& c) { return OpenMesh::cross(b - a, c - a); }

// The (unnormalised) normal of an input triangle.
P input_normal(const Vec3& a, const Vec3& b, const Vec3& c) {
  return normal_of(P(a.x, a.y, a.z), P(b.x, b.y, b.z), P(c.x, c.y, c.z));
}

// Whether the unnormalised normals point the same way with an angle below 90 degrees, and the
// new one is not degenerate (a triangle of no area has no direction to compare).
bool same_side(const P& before, const P& after) {
  const double nb = before.norm(), na = after.norm();
  return na > 1e-12 * nb && OpenMesh::dot(before, after) > 0;
}

class Remesher {
 public:
  Remesher(Mesh& m, const TriangleMesh& input, const ClosestPointIndex& surface, double length, double feature_angle_deg,
           std::size_t max_vertices, EdgeRemeshStats& stats)
      : m_(m), input_(input), surface_(surface), length_(length),
        feature_cos_(std::cos(feature_angle_deg * M_PI / 180)), max_vertices_(max_vertices), stats_(stats) {
    m_.add_property(hint);
    m_.add_property(feature_);
    m_.add_property(share_);
  }

  // The feature lines: boundary edges, and the input's crease curves (detect_features: edges
  // whose faces' normals differ by more than the feature angle, from corner to corner) at least
  // kMinCurve spacings long. A scan's noise makes creases too, short ones: on a pizza scan 15,675
  // crease edges at 40 degrees, 600 of them on curves of two spacings or more; on a CAD part
  // 1,802 of 1,827. Called once the input's faces are in (the vertex handles are the input's
  // indices).
  void mark_features(const TriangleMesh& input, double feature_angle_deg, double spacing) {
    for (Mesh::EdgeHandle e : m_.edges()) m_.property(feature_, e) = m_.is_boundary(e);
    FeatureOptions fo;
    fo.angle = feature_angle_deg;
    fo.boundary = false;
    const Features features = detect_features(input, fo);
    for (const std::vector<Index>& c : features.curves) {
      double length = 0;
      for (std::size_t i = 1; i < c.size(); ++i) length += distance(input.positions[c[i - 1]], input.positions[c[i]]);
      if (length < kMinCurve * spacing) continue;
      for (std::size_t i = 1; i < c.size(); ++i) {
        const Mesh::HalfedgeHandle h = m_.find_halfedge(m_.vertex_handle(c[i - 1]), m_.vertex_handle(c[i]));
        if (h.is_valid() && !m_.property(feature_, m_.edge_handle(h))) {
          m_.property(feature_, m_.edge_handle(h)) = true;
          ++stats_.feature_edges;
        }
      }
    }
  }

  // The spacing for the next rounds.
  void set_length(double length) { length_ = length; }

  // The input's edges on feature lines (as input vertex indices: called before any operation).
  std::vector<std::pair<Index, Index>> feature_edges() const {
    std::vector<std::pair<Index, Index>> out;
    for (Mesh::EdgeHandle e : m_.edges())
      if (m_.property(feature_, e)) {
        const Mesh::HalfedgeHandle h = m_.halfedge_handle(e, 0);
        out.emplace_back(Index(m_.from_vertex_handle(h).idx()), Index(m_.to_vertex_handle(h).idx()));
      }
    return out;
  }

  // Each input vertex's share of the spacing (curvature_sizing); empty: every share is 1.
  void set_sizing(std::vector<double> input_share) {
    input_share_ = std::move(input_share);
    for (Mesh::VertexHandle v : m_.vertices())
      m_.property(share_, v) = input_share_.empty() ? 1.0 : input_share_[std::size_t(v.idx())];
  }

  // One round; false where the splits reached the vertex cap.
  bool round() {
    if (!split_long_edges()) return false;
    collapse_short_edges();
    equalize_valences();
    smooth_tangentially();
    project();
    return true;
  }

  // What the rounds leave below 20 degrees (a short edge the link condition keeps, at handles
  // thinner than the spacing; a crease cut across): the edge opposite the largest angle
  // flipped where that raises the two triangles' smallest angle (between faces less than 30
  // degrees apart), else the triangle's shortest edge collapsed where the surface allows it,
  // without the length limit. A few passes, until nothing changes.
  void clean_small_angles(int passes) {
    const double limit = 20 * M_PI / 180;
    for (int pass = 0; pass < passes; ++pass) {
      bool any = false;
      for (std::size_t i = 0; i < m_.n_faces(); ++i) {
        const Mesh::FaceHandle f = m_.face_handle(unsigned(i));
        if (m_.status(f).deleted()) continue;
        Mesh::HalfedgeHandle h[3];
        int k = 0;
        for (Mesh::HalfedgeHandle x : m_.fh_range(f))
          if (k < 3) h[k++] = x;
        if (k != 3) continue;
        double angle[3];   // at the corner opposite h[j]
        for (int j = 0; j < 3; ++j) angle[j] = corner_angle(h[j]);
        const int small = int(std::min_element(angle, angle + 3) - angle);
        if (!(angle[small] < limit)) continue;
        const int large = int(std::max_element(angle, angle + 3) - angle);
        if (try_flip(m_.edge_handle(h[large]))) {
          any = true;
          continue;
        }
        const Mesh::HalfedgeHandle shortest = h[small];
        for (Mesh::HalfedgeHandle c : {shortest, m_.opposite_halfedge_handle(shortest)})
          if (collapse_ok(c, false)) {
            collapse(c);
            ++stats_.collapses;
            any = true;
            break;
          }
      }
      if (!any) break;
      m_.garbage_collection();
    }
  }

  OpenMesh::VPropHandleT<Index> hint;   // per vertex: the input face it was last projected onto

 private:
  double length(Mesh::EdgeHandle e) const { return m_.calc_edge_length(e); }

  // The spacing between a and b: L times the mean of their shares.
  double spacing(Mesh::VertexHandle a, Mesh::VertexHandle b) const {
    return length_ * (0.5 * (m_.property(share_, a) + m_.property(share_, b)));
  }
  double high(Mesh::VertexHandle a, Mesh::VertexHandle b) const { return 4.0 / 3.0 * spacing(a, b); }
  double low(Mesh::VertexHandle a, Mesh::VertexHandle b) const { return 4.0 / 5.0 * spacing(a, b); }
  // An edge's length over its upper limit: above 1 it is split.
  double excess(Mesh::EdgeHandle e) const {
    const Mesh::HalfedgeHandle h = m_.halfedge_handle(e, 0);
    return length(e) / high(m_.from_vertex_handle(h), m_.to_vertex_handle(h));
  }

  // Every edge longer than 4/3 L split at its middle, the longest first (as in Rivara's
  // bisection: a sliver is cut across, not fanned from its far corner, which in file order
  // made millions of vertices out of a CAD part's fans of needles). False where the vertex
  // cap was reached.
  bool split_long_edges() {
    std::priority_queue<std::pair<double, unsigned>> heap;
    for (Mesh::EdgeHandle e : m_.edges())
      if (const double x = excess(e); x > 1) heap.emplace(x, unsigned(e.idx()));
    while (!heap.empty()) {
      const auto [x, i] = heap.top();
      heap.pop();
      const Mesh::EdgeHandle e = m_.edge_handle(i);
      if (m_.status(e).deleted() || excess(e) != x) continue;   // split since (its pieces are queued)
      if (m_.n_vertices() >= max_vertices_) return false;
      const Mesh::HalfedgeHandle h = m_.halfedge_handle(e, 0);
      const Mesh::VertexHandle a = m_.from_vertex_handle(h), b = m_.to_vertex_handle(h);
      const bool feature = m_.property(feature_, e);
      const double share = 0.5 * (m_.property(share_, a) + m_.property(share_, b));
      const Mesh::VertexHandle v = m_.split(e, 0.5 * (m_.point(a) + m_.point(b)));
      m_.property(hint, v) = m_.property(hint, a);
      m_.property(share_, v) = share;
      for (Mesh::HalfedgeHandle o : m_.voh_range(v)) {   // the two halves of a feature edge stay feature
        const Mesh::VertexHandle w = m_.to_vertex_handle(o);
        m_.property(feature_, m_.edge_handle(o)) = feature && (w == a || w == b);
      }
      ++stats_.splits;
      for (Mesh::EdgeHandle f : m_.ve_range(v))
        if (const double xf = excess(f); xf > 1) heap.emplace(xf, unsigned(f.idx()));
    }
    return true;
  }

  // Whether collapsing h (its from-vertex into its to-vertex) keeps the surface: never a
  // corner, a vertex of a feature line only along the line; OpenMesh's link condition; no edge
  // of the merged vertex longer than 4/3 L; no face around the removed vertex turned over or
  // flattened.
  bool collapse_ok(Mesh::HalfedgeHandle h, bool limit_length = true) {
    const Mesh::VertexHandle from = m_.from_vertex_handle(h), to = m_.to_vertex_handle(h);
    const int degree = feature_degree(from);
    if (degree != 0 && (corner(from) || !m_.property(feature_, m_.edge_handle(h)))) return false;
    const P target = m_.point(to);
    // The length limit first: it refuses most collapses, and OpenMesh's link condition (half
    // of the remesh's time on demosthenes when asked first) is dearer.
    for (Mesh::VertexHandle w : m_.vv_range(from))
      if (limit_length && w != to && (m_.point(w) - target).norm() > high(to, w)) return false;
    if (!m_.is_collapse_ok(h)) return false;
    for (Mesh::FaceHandle f : m_.vf_range(from)) {
      Mesh::VertexHandle x[3];
      int k = 0;
      for (Mesh::VertexHandle v : m_.fv_range(f))
        if (k < 3) x[k++] = v;
      if (k != 3 || x[0] == to || x[1] == to || x[2] == to) continue;   // removed with the edge
      const P c[3] = {m_.point(x[0]), m_.point(x[1]), m_.point(x[2])};
      P moved[3] = {c[0], c[1], c[2]};
      for (int j = 0; j < 3; ++j)
        if (x[j] == from) moved[j] = target;
      if (!same_side(normal_of(c[0], c[1], c[2]), normal_of(moved[0], moved[1], moved[2]))) return false;
    }
    return true;
  }

  // Collapses h: an edge of the removed vertex's faces on h that was a feature leaves its flag
  // to the edge it merges with.
  void collapse(Mesh::HalfedgeHandle h) {
    const Mesh::VertexHandle from = m_.from_vertex_handle(h), to = m_.to_vertex_handle(h);
    for (Mesh::HalfedgeHandle side : {h, m_.opposite_halfedge_handle(h)}) {
      if (m_.is_boundary(side)) continue;
      const Mesh::VertexHandle x = m_.to_vertex_handle(m_.next_halfedge_handle(side));
      const Mesh::HalfedgeHandle gone = m_.find_halfedge(from, x), kept = m_.find_halfedge(to, x);
      if (gone.is_valid() && kept.is_valid() && m_.property(feature_, m_.edge_handle(gone)))
        m_.property(feature_, m_.edge_handle(kept)) = true;
    }
    m_.collapse(h);
  }

  void collapse_short_edges() {
    bool any = false;
    for (std::size_t i = 0; i < m_.n_edges(); ++i) {
      const Mesh::EdgeHandle e = m_.edge_handle(static_cast<unsigned>(i));
      if (m_.status(e).deleted()) continue;
      const Mesh::HalfedgeHandle h0 = m_.halfedge_handle(e, 0), h1 = m_.halfedge_handle(e, 1);
      if (!(length(e) < low(m_.from_vertex_handle(h0), m_.to_vertex_handle(h0)))) continue;
      // The end on fewer feature edges goes (an interior vertex to a feature line, not the
      // line's vertex inward).
      const bool first = feature_degree(m_.from_vertex_handle(h0)) <= feature_degree(m_.from_vertex_handle(h1));
      Mesh::HalfedgeHandle pick;
      for (Mesh::HalfedgeHandle h : {first ? h0 : h1, first ? h1 : h0})
        if (collapse_ok(h)) {
          pick = h;
          break;
        }
      if (!pick.is_valid()) continue;
      collapse(pick);
      ++stats_.collapses;
      any = true;
    }
    if (any) m_.garbage_collection();
  }

  int feature_degree(Mesh::VertexHandle v) const {
    int n = 0;
    for (Mesh::EdgeHandle e : m_.ve_range(v)) n += m_.property(feature_, e);
    return n;
  }

  // A vertex where feature lines meet or end, or where one turns by more than the feature
  // angle: it never moves and is never collapsed.
  bool corner(Mesh::VertexHandle v) const {
    P d[2];
    int n = 0;
    for (Mesh::HalfedgeHandle o : m_.voh_range(v))
      if (m_.property(feature_, m_.edge_handle(o))) {
        if (n < 2) d[n] = m_.point(m_.to_vertex_handle(o)) - m_.point(v);
        ++n;
      }
    if (n == 0) return false;
    if (n != 2) return true;
    // Straight on: the two directions about opposite.
    return !(OpenMesh::dot(d[0], d[1]) < -feature_cos_ * d[0].norm() * d[1].norm());
  }

  // The angle of h's face at the corner opposite h.
  double corner_angle(Mesh::HalfedgeHandle h) const {
    const Mesh::VertexHandle o = m_.to_vertex_handle(m_.next_halfedge_handle(h));
    return angle_at(at(o), at(m_.from_vertex_handle(h)), at(m_.to_vertex_handle(h)));
  }

  Vec3 at(Mesh::VertexHandle v) const {
    const P& p = m_.point(v);
    return {p[0], p[1], p[2]};
  }

  // Interior edge e's two faces (a, b, c) and (b, a, d), and the same quad flipped, (d, b, c)
  // and (c, a, d).
  struct Quad {
    Vec3 a, b, c, d;
  };
  Quad quad_of(Mesh::EdgeHandle e) const {
    const Mesh::HalfedgeHandle h0 = m_.halfedge_handle(e, 0), h1 = m_.halfedge_handle(e, 1);
    return {at(m_.from_vertex_handle(h0)), at(m_.to_vertex_handle(h0)), at(m_.to_vertex_handle(m_.next_halfedge_handle(h0))),
            at(m_.to_vertex_handle(m_.next_halfedge_handle(h1)))};
  }

  // Whether flipping interior edge e keeps the surface: not a feature edge, its faces' normals
  // less than acos(min_cos) apart, neither new face turned over.
  bool flip_keeps_surface(Mesh::EdgeHandle e, const Quad& q, double min_cos) const {
    if (m_.is_boundary(e) || m_.property(feature_, e) || !m_.is_flip_ok(e)) return false;
    const Vec3 n1 = normal(q.a, q.b, q.c), n2 = normal(q.b, q.a, q.d);
    if (!(dot(n1, n2) > min_cos * norm(n1) * norm(n2))) return false;
    const Vec3 sum = (1 / norm(n1)) * n1 + (1 / norm(n2)) * n2;
    auto same_side = [&](const Vec3& after) { return norm(after) > 1e-12 * norm(sum) && dot(sum, after) > 0; };
    return same_side(normal(q.d, q.b, q.c)) && same_side(normal(q.c, q.a, q.d));
  }

  // Flips interior edge e where the two faces are less than 30 degrees apart, no new face turns
  // over and the smallest angle of the two rises.
  bool try_flip(Mesh::EdgeHandle e) {
    const Quad q = quad_of(e);
    if (!flip_keeps_surface(e, q, std::cos(30 * M_PI / 180))) return false;
    const double before = std::min(min_angle(q.a, q.b, q.c), min_angle(q.b, q.a, q.d));
    const double after = std::min(min_angle(q.d, q.b, q.c), min_angle(q.c, q.a, q.d));
    if (!(after > before)) return false;
    m_.flip(e);
    ++stats_.flips;
    return true;
  }

  int target_valence(Mesh::VertexHandle v) const { return m_.is_boundary(v) ? 4 : 6; }

  // Flips an interior edge where that brings its four vertices' valences nearer 6 (4 on the
  // boundary), unless it is a feature edge, its two faces meet at a crease all the same
  // (normals more than 60 degrees apart) or a new face would turn over. The valences are
  // counted once and kept through the flips (OpenMesh counts a ring each time it is asked:
  // 5% of a demosthenes remesh's instructions, asked eight times an edge).
  void equalize_valences() {
    std::vector<int> valence(m_.n_vertices());
    for (Mesh::VertexHandle v : m_.vertices()) valence[std::size_t(v.idx())] = int(m_.valence(v));
    for (Mesh::EdgeHandle e : m_.edges()) {
      if (m_.status(e).deleted() || m_.is_boundary(e)) continue;
      const Mesh::HalfedgeHandle h0 = m_.halfedge_handle(e, 0), h1 = m_.halfedge_handle(e, 1);
      const Mesh::VertexHandle a = m_.from_vertex_handle(h0), b = m_.to_vertex_handle(h0);
      const Mesh::VertexHandle c = m_.to_vertex_handle(m_.next_halfedge_handle(h0));
      const Mesh::VertexHandle d = m_.to_vertex_handle(m_.next_halfedge_handle(h1));
      auto dev = [&](Mesh::VertexHandle v, int change) {
        const int x = valence[std::size_t(v.idx())] + change - target_valence(v);
        return x * x;
      };
      const int before = dev(a, 0) + dev(b, 0) + dev(c, 0) + dev(d, 0);
      const int after = dev(a, -1) + dev(b, -1) + dev(c, 1) + dev(d, 1);
      if (after >= before || !flip_keeps_surface(e, quad_of(e), 0.5)) continue;
      m_.flip(e);
      --valence[std::size_t(a.idx())], --valence[std::size_t(b.idx())];
      ++valence[std::size_t(c.idx())], ++valence[std::size_t(d.idx())];
      ++stats_.flips;
    }
  }

  // The area-weighted normal of v's faces (not normalised).
  P vertex_normal(Mesh::VertexHandle v) const {
    P normal(0, 0, 0);
    for (Mesh::FaceHandle f : m_.vf_range(v)) {
      auto it = m_.cfv_begin(f);
      const P a = m_.point(*it++), b = m_.point(*it++), c = m_.point(*it);
      normal += normal_of(a, b, c);
    }
    return normal;
  }

  // Each vertex off the feature lines towards the centroid of its neighbours, within its
  // tangent plane (the normal is the area-weighted one of its faces); a vertex of a feature
  // line (boundaries included) along the line, towards the middle of its two neighbours on it;
  // corners stay.
  void smooth_tangentially() {
    std::vector<P> moved(m_.n_vertices());
    for (Mesh::VertexHandle v : m_.vertices()) {
      const P p = m_.point(v);
      moved[std::size_t(v.idx())] = p;
      P ends[2];
      int k = 0;
      for (Mesh::HalfedgeHandle o : m_.voh_range(v))
        if (m_.property(feature_, m_.edge_handle(o)) && k++ < 2) ends[k - 1] = m_.point(m_.to_vertex_handle(o));
      if (k != 0) {
        if (corner(v)) continue;
        const P along = ends[1] - ends[0];
        const double l2 = OpenMesh::dot(along, along);
        if (!(l2 > 0)) continue;
        moved[std::size_t(v.idx())] = p + (OpenMesh::dot(0.5 * (ends[0] + ends[1]) - p, along) / l2) * along;
        continue;
      }
      P centroid(0, 0, 0);
      int n = 0;
      for (Mesh::VertexHandle w : m_.vv_range(v)) centroid += m_.point(w), ++n;
      if (n == 0) continue;
      P normal = vertex_normal(v);
      const double nn = normal.norm();
      if (!(nn > 0)) continue;
      normal /= nn;
      const P d = centroid / double(n) - p;
      moved[std::size_t(v.idx())] = p + d - OpenMesh::dot(d, normal) * normal;
    }
    for (Mesh::VertexHandle v : m_.vertices()) m_.point(v) = moved[std::size_t(v.idx())];
  }

  // Every vertex onto the input's closest point (searched from the face it was on before).
  // Not onto a face that faces the other way (the far side of a handle or wall thinner than
  // the spacing, nearer than the vertex's own side): the vertex then stays where the smoothing
  // put it, a second-order distance off its own side.
  void project() {
    for (Mesh::VertexHandle v : m_.vertices()) {
      const P& p = m_.point(v);
      const ClosestPoint c = surface_.closest(Vec3{p[0], p[1], p[2]}, m_.property(hint, v));
      if (c.point.element == kInvalidIndex) continue;
      const Triangle& t = input_.triangles[c.point.element];
      if (OpenMesh::dot(input_normal(input_.positions[t[0]], input_.positions[t[1]], input_.positions[t[2]]), vertex_normal(v)) < 0)
        continue;
      // Nor onto a neighbour's place (two vertices met at the sensor STL's screw holes: a
      // duplicate vertex, and the component was kept).
      const P q(c.position.x, c.position.y, c.position.z);
      bool taken = false;
      for (Mesh::VertexHandle w : m_.vv_range(v)) taken |= (m_.point(w) - q).norm() <= 1e-6 * low(v, w);
      if (taken) continue;
      m_.point(v) = q;
      m_.property(hint, v) = c.point.element;
      if (!input_share_.empty()) {   // the share where it landed, interpolated over the input face
        const Vec3 &a = input_.positions[t[0]], &b = input_.positions[t[1]], &d = input_.positions[t[2]];
        const std::array<double, 3> w = closest_point_on_triangle(c.position, a, b, d);
        m_.property(share_, v) = w[0] * input_share_[t[0]] + w[1] * input_share_[t[1]] + w[2] * input_share_[t[2]];
      }
    }
  }

  Mesh& m_;
  const TriangleMesh& input_;
  const ClosestPointIndex& surface_;
  double length_;   // the spacing L where the share is 1
  double feature_cos_;
  OpenMesh::EPropHandleT<bool> feature_;   // per edge: on a feature line
  OpenMesh::VPropHandleT<double> share_;   // per vertex: its share of L (1 without a sizing field)
  std::vector<double> input_share_;        // per input vertex; empty without a sizing field
  std::size_t max_vertices_;
  EdgeRemeshStats& stats_;
};

// The faces and the vertices they use, numbered in the order the faces first use them.
TriangleMesh to_triangle_mesh(const Mesh& m) {
  TriangleMesh out;
  std::vector<Index> index(m.n_vertices(), kInvalidIndex);
  for (Mesh::FaceHandle f : m.faces()) {
    Triangle t;
    int k = 0;
    for (Mesh::VertexHandle v : m.fv_range(f)) {
      Index& i = index[std::size_t(v.idx())];
      if (i == kInvalidIndex) {
        i = Index(out.positions.size());
        const P& p = m.point(v);
        out.positions.push_back(Vec3{p[0], p[1], p[2]});
      }
      t[k++] = i;
    }
    out.triangles.push_back(t);
  }
  return out;
}

}  // namespace

namespace {

// What one remesh at given shares left: the mesh (empty where OpenMesh refused a face or the
// splits passed the cap), the spacing it ended at, and whether it folded.
struct Pass {
  TriangleMesh out;
  double spacing = 0;
  bool folded = false;
};

// The remesh at the shares `share` (empty: one spacing everywhere; on the first pass the sizing
// field, when asked for, is computed into it and into `asked`: the shares the fold check holds
// every pass to).
Pass remesh_once(const TriangleMesh& input, const ClosestPointIndex& surface, double target_length, double feature_angle_deg,
                 int iterations, std::size_t max_vertices, std::size_t target_vertices, EdgeRemeshStats& stats,
                 const SizingOptions* sizing, bool first, std::vector<double>& share, std::vector<double>& asked) {
  Pass pass;
  Mesh m;
  m.request_vertex_status();
  m.request_edge_status();
  m.request_halfedge_status();
  m.request_face_status();
  std::vector<Mesh::VertexHandle> handle(input.num_vertices());
  for (std::size_t v = 0; v < input.num_vertices(); ++v) {
    const Vec3& x = input.positions[v];
    handle[v] = m.add_vertex(P(x.x, x.y, x.z));
  }
  stats = {};
  Remesher r(m, input, surface, target_length, feature_angle_deg, max_vertices, stats);
  for (std::size_t f = 0; f < input.num_faces(); ++f) {
    const Triangle& t = input.triangles[f];
    if (!m.add_face(handle[t[0]], handle[t[1]], handle[t[2]]).is_valid()) return pass;
    for (int k = 0; k < 3; ++k) m.property(r.hint, handle[t[k]]) = Index(f);
  }
  // Vertices of no face (none in a component) would stay isolated: dropped by the export below.
  r.mark_features(input, feature_angle_deg, target_length);
  if (first && sizing) share = asked = curvature_sizing(input, r.feature_edges(), target_length, *sizing);
  r.set_sizing(share);
  // Edges within [4/5, 4/3] of a spacing L average below L on a curved or bounded surface, and
  // crease lines add vertices: L from the area alone gave 10-40% more vertices than asked for
  // (spot 5,259, demosthenes 6,987 at 5,000). The count goes as 1 / L^2, so after each of the
  // first rounds the spacing is scaled by sqrt(count / target) and the later rounds settle.
  double length = target_length;
  for (int i = 0; i < iterations; ++i) {
    if (!r.round()) return pass;
    if (target_vertices > 0 && i + 4 < iterations) {
      // n_vertices() counts the live vertices: a round deletes only in its collapses, which
      // collect their garbage.
      length *= std::clamp(std::sqrt(double(m.n_vertices()) / double(target_vertices)), 0.5, 2.0);
      r.set_length(length);
    }
  }
  r.clean_small_angles(5);
  m.garbage_collection();
  pass.out = to_triangle_mesh(m);
  pass.spacing = std::max(length, target_length);
  if (pass.out.triangles.empty()) return pass;
  // A remesh with the topology can still have folded onto one side of a thin part (collapses
  // move vertices; the projection keeps them on the input, not spread over it): every input
  // vertex must lie within two spacings of it (of its own spacing, with a sizing field).
  const ClosestPointIndex index(pass.out);
  Index hint = kInvalidIndex;
  for (std::size_t v = 0; v < input.num_vertices() && !pass.folded; ++v)
    pass.folded = !index.within(input.positions[v], 2 * pass.spacing * (asked.empty() ? 1.0 : asked[v]), hint);
  return pass;
}

// The input vertices farther than one of their own spacings (`share`: empty for 1) from a
// remesh: the places the next pass refines.
std::vector<Index> far_from(const TriangleMesh& input, const TriangleMesh& out, double spacing,
                            const std::vector<double>& share) {
  const ClosestPointIndex index(out);
  std::vector<Index> far;
  Index hint = kInvalidIndex;
  for (std::size_t v = 0; v < input.num_vertices(); ++v)
    if (!index.within(input.positions[v], spacing * (share.empty() ? 1.0 : share[v]), hint)) far.push_back(Index(v));
  return far;
}

}  // namespace

TriangleMesh remesh_by_edge_operations(const TriangleMesh& input, const ClosestPointIndex& surface,
                                       double target_length, double feature_angle_deg, int iterations,
                                       std::size_t max_vertices, std::size_t target_vertices, EdgeRemeshStats* stats,
                                       const SizingOptions* sizing, int fold_refinements) {
  EdgeRemeshStats local;
  EdgeRemeshStats& st = stats ? *stats : local;
  std::vector<double> share, asked;
  // A remesh that folded onto one side of parts thinner than the spacing is made again with
  // the spacing halved around the input vertices it left farther than their spacing away, and
  // again while such vertices are left (twice at most): the spacing there then follows the
  // part instead of cutting across it (docs/cvt.md, "Cap flips without rebuilds, and refined
  // where the edge remesh folded"). The fold check stays the one asked for; the last pass that passes it is kept.
  TriangleMesh kept;
  for (int refinement = 0;; ++refinement) {
    Pass pass = remesh_once(input, surface, target_length, feature_angle_deg, iterations, max_vertices, target_vertices,
                            st, sizing, refinement == 0, share, asked);
    st.fold_refinements = std::size_t(refinement);
    if (pass.out.triangles.empty()) return kept;
    if (!pass.folded) {
      if (refinement == 0) return std::move(pass.out);
      kept = std::move(pass.out);
    }
    if (refinement >= fold_refinements) return kept;
    const std::vector<Index> far = far_from(input, pass.folded ? pass.out : kept, pass.spacing, share);
    if (far.empty()) return kept;
    refine_around(input, far, pass.spacing, 0.5, 0.2, 0.125, share);
  }
}

}  // namespace gsp::cvt::detail
