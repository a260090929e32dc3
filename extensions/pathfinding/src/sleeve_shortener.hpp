#pragma once
// The parts of the sleeve shortening (sleeve.hpp): building the sleeve of faces (sleeve.cpp),
// unfolding it and pulling the path straight in it (sleeve_funnel.cpp), rerouting the bends
// that can be undone (sleeve_reroute.cpp).
#include <gsp/connectivity.hpp>
#include <gsp/pathfinding/path.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace gsp::pathfinding::detail {

using P2 = std::array<double, 2>;

inline double cross2(P2 a, P2 b) { return a[0] * b[1] - a[1] * b[0]; }
inline P2 sub(P2 a, P2 b) { return {a[0] - b[0], a[1] - b[1]}; }
inline double angle2(P2 a, P2 b) { return std::atan2(std::abs(cross2(a, b)), a[0] * b[0] + a[1] * b[1]); }

// An end of the path as the mesh vertices it is a weighted sum of (one for a vertex, two on
// an edge, three inside a face).
struct End {
  Index vertex[3];
  double weight[3];
  int n = 0;
};

// A walk through faces: faces[k] is entered from faces[k - 1] over the edge whose halfedge in
// faces[k - 1] is exit[k - 1] and in faces[k] is entry[k].
struct Sleeve {
  std::vector<Index> faces, entry, exit;

  // Cuts out every detour that comes back to a face it already passed (the walk can circle a
  // vertex or step back and forth); a shortest path crosses a face at most once (a
  // simplification: on strongly curved meshes a geodesic may cross a long face twice).
  void remove_loops();
  // A fan round a vertex joins the sleeve as a piece of it: its faces with their entries, and
  // the exits that lead into them.
  void append(const Sleeve& fan) {
    for (std::size_t k = 0; k < fan.faces.size(); ++k)
      exit.push_back(fan.exit[k]), faces.push_back(fan.faces[k]), entry.push_back(fan.entry[k]);
  }
  // The path's ends lie in faces first and last: nothing before or after them is crossed.
  void keep(std::size_t first, std::size_t last) {
    faces = {faces.begin() + first, faces.begin() + last + 1};
    entry = {entry.begin() + first, entry.begin() + last + 1};
    exit = {exit.begin() + first, exit.begin() + last + 1};
    entry.front() = kInvalidIndex, exit.back() = kInvalidIndex;
  }
};

class Shortener {
 public:
  Shortener(const TriangleMesh& mesh, const Connectivity& conn) : mesh_(mesh), conn_(conn) {}

  bool build(const PathPoint& start, const PathPoint& end, const std::vector<Index>& segment_faces);
  // One round: funnel, then reroute every bend that can be undone; false when none could.
  bool reroute_round();
  void emit(std::vector<PathPoint>& out);
  std::size_t sleeve_size() const { return s_.faces.size(); }

 private:
  struct Portal {
    P2 left, right;
    Index left_vertex, right_vertex;   // kInvalidIndex for the two end "portals"
  };
  struct Bend {
    std::size_t portal;
    bool left;
  };

  bool valid_face(Index f) const {
    const Triangle& t = mesh_.triangles[f];
    return t[0] != t[1] && t[1] != t[2] && t[0] != t[2];
  }
  bool contains(Index f, const End& e) const {
    const Triangle& t = mesh_.triangles[f];
    for (int i = 0; i < e.n; ++i)
      if (t[0] != e.vertex[i] && t[1] != e.vertex[i] && t[2] != e.vertex[i]) return false;
    return true;
  }
  Index corner_at(Index f, Index v) const {
    for (Index c = 0; c < 3; ++c)
      if (mesh_.triangles[f][c] == v) return c;
    return kInvalidIndex;
  }
  // Remembered per shortening: the rerouting rounds ask for the same fans again and again
  // (on a CAD part of needles the arctangents were 29% of gsp-path's time).
  double corner_angle(Index f, Index c) const {
    const auto [it, fresh] = angles_.try_emplace(3 * std::uint64_t(f) + c, 0.0);
    if (!fresh) return it->second;
    const Triangle& t = mesh_.triangles[f];
    const Vec3 p = mesh_.positions[t[c]];
    const Vec3 a = mesh_.positions[t[(c + 1) % 3]] - p, b = mesh_.positions[t[(c + 2) % 3]] - p;
    return it->second = std::atan2(norm(gsp::cross(a, b)), dot(a, b));
  }
  // The halfedge of face b on the edge that halfedge h of face a lies on, if any.
  Index across(Index h, Index b) const {
    for (Index g = conn_.radial_next[h]; g != h; g = conn_.radial_next[g])
      if (face_of(g) == b) return g;
    return kInvalidIndex;
  }
  bool link(Index a, Index b, Index& ha, Index& hb) const {
    for (Index i = 0; i < 3; ++i)
      if ((hb = across(3 * a + i, b)) != kInvalidIndex) return ha = 3 * a + i, true;
    return false;
  }
  // The point the path bends at: the portal end on the bend's side.
  P2 bend_point(const Bend& b) const { return b.left ? portals_[b.portal].left : portals_[b.portal].right; }

  // Building the sleeve (sleeve.cpp).
  // The faces round v from the face of `first_exit` (one of its halfedges at v, the edge to
  // leave by) to `to` (not including the first face, including `to`); manifold edges only.
  // Appends to `out` (face, entry halfedge, exit halfedge of the previous face) and gives the
  // summed corner angles at v of the faces strictly in between.
  bool fan(Index v, Index to, Index first_exit, Sleeve& out, double* angle) const;
  bool fan_round_shared_vertex(Index a, Index f, Sleeve& best) const;
  bool cut_to_ends();

  // Unfolding and string pulling (sleeve_funnel.cpp).
  void unfold();
  void funnel();
  P2 end_point(std::size_t k, const End& e) const;
  PathPoint bary_point(Index f, const End& e) const;

  // Rerouting (sleeve_reroute.cpp).
  bool reroute_bend(std::size_t b, std::size_t& limit);
  void portals_round(Index v, std::size_t portal, std::size_t& lo, std::size_t& hi) const;
  bool other_fan(Index v, std::size_t i, std::size_t j, Sleeve& side, double& between) const;
  double other_side_angle(std::size_t b, Index v, std::size_t lo, std::size_t hi, double between) const;
  void splice(std::size_t i, std::size_t j, const Sleeve& side);
  void trim_to_ends();

  const TriangleMesh& mesh_;
  const Connectivity& conn_;
  mutable std::unordered_map<std::uint64_t, double> angles_;   // corner_angle(), by 3 f + c
  Sleeve s_;
  End start_, end_;
  std::vector<std::array<P2, 3>> corner2_;   // per sleeve face: its corners in the unfolding
  std::vector<Portal> portals_;              // start, the edges between sleeve faces, end
  std::vector<Bend> bends_;
};

}  // namespace gsp::pathfinding::detail
