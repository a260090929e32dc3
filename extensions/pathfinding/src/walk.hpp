#pragma once
// The backward walk of a traced path (path_tracer.hpp): from the end point through the faces'
// virtual sources to the field's source, then pulled taut. walk.cpp drives it; walk_moves.cpp
// holds its moves inside a face, at a vertex and across an edge.
#include <gsp/connectivity.hpp>
#include <gsp/geodesics.hpp>
#include <gsp/pathfinding/path.hpp>
#include <gsp/surface_point.hpp>

#include "source_field.hpp"

#include <algorithm>
#include <array>
#include <cstddef>
#include <limits>
#include <vector>

namespace gsp::pathfinding::detail {

using Bary = std::array<double, 3>;
constexpr double kInf = std::numeric_limits<double>::infinity();
// Barycentric slack: a coordinate this far below 0 still counts as on the edge (the sources
// are stored in single precision by default; relative position errors are about 1e-7).
constexpr double kBaryTol = 1e-6;
// A point this close to a corner (in barycentric terms) is that vertex.
constexpr double kVertexTol = 1e-6;
// A virtual source with sigma > 0 this close to a corner is that corner.
constexpr double kCornerSnap = 1e-3;

// A point exactly at a face's corner, the way the walk and its fallback name vertices.
inline Bary corner_bary(Index corner) {
  Bary b{0, 0, 0};
  b[corner] = 1;
  return b;
}

// The walk's state: a point of a face, the halfedge it entered the face through (so that a
// path running along that edge is not bounced back across it), and the source it is heading
// for: a point S in the face's plane and sigma, the face's own virtual source or one carried
// over from the faces behind, unfolded across the edges crossed.
struct Walker {
  Index face = kInvalidIndex;
  Bary bary{1, 0, 0};
  Vec3 position;
  Index entry = kInvalidIndex;
  // The face before and the edge it crossed to come here (kept where `entry` is reset).
  Index came_from = kInvalidIndex, came_over = kInvalidIndex;
  Vec3 target;
  double sigma = kInf;
  Index label = kInvalidIndex;
  bool own = false;   // target is the face's own virtual source
  double value() const { return sigma + distance(position, target); }
};

class Walk {
 public:
  Walk(const TriangleMesh& mesh, const Connectivity& conn, const SourceField& field, double mean_edge,
       std::size_t max_steps, bool shorten)
      : mesh_(mesh), conn_(conn), field_(field), eps_(1e-7 * mean_edge), max_steps_(max_steps), shorten_(shorten) {}

  // The path from the field's source to `end`. Throws NoPath where the field does not reach
  // it, Error where the walk cannot be completed (the tracer then takes the descent route).
  GeodesicPath run(const Endpoint& end);

 private:
  bool reached(Index f) const { return field_.reached(f); }

  // Barycentric coordinates of x (projected into f's plane); false for a degenerate face: the
  // sine of its smallest angle below 1e-12 (a CAD needle of aspect 8e6 is a face, its
  // barycentrics good to about eps * aspect; at 1e-6 the walk stopped at such needles). The
  // test and the coordinates from cross products (affine_coordinates): from the Gram
  // determinant, a needle of aspect 7e7 on the toilet-seat handle STL had or had no plane
  // depending on the model's scale, and at 10x its size the walk could not enter the needle
  // the field went through (a path 3.5% long).
  bool bary_of(Index f, Vec3 x, Bary& b) const {
    return !repeats_vertex(mesh_.triangles[f]) && affine_coordinates(mesh_, f, x, 1e-24, b);
  }
  bool usable(Index f) const {
    Bary b;
    return reached(f) && bary_of(f, mesh_.positions[mesh_.triangles[f][0]], b);
  }
  double own_value(Index f, Vec3 x) const {
    const VirtualSource s = field_.source_at(f, x);
    return s.sigma + distance(x, s.position);
  }
  void adopt_own(Walker& w) const {
    const VirtualSource s = field_.source_at(w.face, w.position);
    w.target = s.position, w.sigma = s.sigma, w.label = s.source, w.own = true;
  }
  // Appends w's point; its face is the one the segment from the previous point lies in.
  void emit(const Walker& w) {
    if (!out_.points.empty() && distance(out_.points.back().position, w.position) <= eps_) return;
    out_.points.push_back({SurfacePoint::in_face(w.face, w.bary), w.position});
  }

  // The moves (walk_moves.cpp).
  // The straight walk from w towards its target: the parameter t in [0, 1] where it leaves the
  // face and through which corner's opposite edge (-1: the target is inside the face).
  bool exit_of(const Walker& w, double& t_exit, int& exit_corner, Bary& bs) const;
  // The own source of w's face leads into the face from w (not straight back out).
  bool own_enters(const Walker& w) const {
    Walker o = w;
    adopt_own(o);
    double t;
    int corner;
    Bary bs;
    return exit_of(o, t, corner, bs) && (corner < 0 || t > 1e-9);
  }
  enum class VertexStep { moved, source, keep, stuck };
  VertexStep at_vertex(Index v, Walker& w);
  bool cross(const Walker& from, Index h, const Bary& bq, Walker& to) const;
  bool unfold_target(const Walker& from, Index h, Index g, Vec3& target) const;
  bool cross_past_flat(const Walker& from, Index h, Walker& to) const;
  double continuation_mismatch(const Walker& from, Index h, Index g, Vec3 q) const;
  // Of the faces across h's edge that each(visit) lists (it calls visit(g) for the halfedge g
  // of each, and is called twice): the least own distance at q and, of those within rounding
  // of it, the face where the straight line goes on (continuation_mismatch; at a fin edge or a
  // T-junction several faces give q one distance). The first listed where no value is finite;
  // kInvalidIndex where none is listed.
  template <class ForEach>
  Index best_neighbour(const Walker& from, Index h, Vec3 q, ForEach&& each) const {
    Index first = kInvalidIndex;
    double best = kInf;
    each([&](Index g) {
      if (first == kInvalidIndex) first = g;
      best = std::min(best, own_value(face_of(g), q));
    });
    if (!(best < kInf)) return first;
    const double tol = 1e-6 * best + 10 * eps_;
    Index pick = kInvalidIndex;
    double best_mismatch = kInf;
    each([&](Index g) {
      if (!(own_value(face_of(g), q) <= best + tol)) return;
      const double mismatch = continuation_mismatch(from, h, g, q);
      if (pick == kInvalidIndex || mismatch < best_mismatch) best_mismatch = mismatch, pick = g;
    });
    return pick;
  }
  // `to`: `from` in the face of halfedge g at weights b, the target it carries unfolded about
  // h's edge into that face's plane (the face's own source where the edge has no length).
  void enter(const Walker& from, Index h, Index g, const Bary& b, Walker& to) const;

  // The walk's course (walk.cpp).
  Walker start(const Endpoint& end);
  double end_distance(const Endpoint& end) const;
  VertexStep step_vertex(Index v, Walker& w);
  void prefer_own(Walker& w) const;
  void step(Walker& w);
  void reach_target(Walker& w, Walker next, int top);
  Index vertex_across(Index f, Vec3 x) const;
  void leave_face(Walker& w, const Walker& next, int exit_corner);
  void pull_taut();
  void keep_shortest(std::vector<PathPoint>& taut, const PathPoint& first, const PathPoint& last);

  const TriangleMesh& mesh_;
  const Connectivity& conn_;
  const SourceField& field_;
  double eps_;
  std::size_t max_steps_;
  bool shorten_;
  GeodesicPath out_;
  bool at_source_ = false;   // the walk has found the field's source: it ends
};

}  // namespace gsp::pathfinding::detail
