#pragma once
// A point on the surface of a triangle mesh, named by the mesh's elements: a vertex, or a point
// inside a face given by the barycentric weights of its corners 0, 1, 2. One type for every
// place that names such a point (sources, path end points, path points, samples, CVT sites,
// closest points), so that "does it exist" and "where is it in 3D" are written once.
//
//   gsp::SurfacePoint::at_vertex(12).position(mesh)                  // mesh.positions[12]
//   gsp::SurfacePoint::in_face(7, {0.2, 0.3, 0.5}).position(mesh)    // inside face 7
#include <gsp/mesh.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <string>

namespace gsp {

struct SurfacePoint {
  enum class Kind : std::uint8_t { vertex, face_point };
  // The default is vertex 0: what gsp::Source, built on this type, has always defaulted to.
  Kind kind = Kind::vertex;
  Index element = 0;                            // vertex index or face index
  std::array<double, 3> barycentric{1, 0, 0};   // face points: weights of the corners 0, 1, 2

  static SurfacePoint at_vertex(Index v) { return {Kind::vertex, v, {1, 0, 0}}; }
  static SurfacePoint in_face(Index f, std::array<double, 3> bary) { return {Kind::face_point, f, bary}; }
  bool is_vertex() const { return kind == Kind::vertex; }

  // Whether `mesh` has the vertex or face. The weights are not looked at: callers check them
  // (are_barycentric) where they come from outside, with their own tolerance if need be.
  bool exists_in(const TriangleMesh& mesh) const;
  // What exists_in found missing, e.g. "face 12 does not exist (10 faces)", for the caller to
  // put in front where the point came from ("source ", "--to: ").
  std::string missing_from(const TriangleMesh& mesh) const;
  // The point in 3D: the vertex's position, or the corners weighted as given (no
  // renormalisation, so a caller's arithmetic stays the same). Throws InvalidInput with
  // missing_from(mesh) when the vertex or face does not exist.
  Vec3 position(const TriangleMesh& mesh) const;
};

// Affine coordinates of x (projected into the plane of `face`) with respect to the face's
// corners 0, 1, 2: they sum to 1, and are all >= 0 where the projection lies in the face
// (walks over faces and clamped weights build on this). Zeros for a face of no area.
std::array<double, 3> affine_coordinates(const TriangleMesh& mesh, Index face, Vec3 x);
// The same, false (and `out` untouched) where the face has no plane to within min_sine2: the
// squared sine of its angle at corner 0 at most that (0: no area at all).
bool affine_coordinates(const TriangleMesh& mesh, Index face, Vec3 x, double min_sine2, std::array<double, 3>& out);

// Weights >= 0 that sum to 1 within 1e-6: what a face point handed to the library (a source, a
// path end point) must have. NaN fails.
inline bool are_barycentric(const std::array<double, 3>& w) {
  return w[0] >= 0 && w[1] >= 0 && w[2] >= 0 && !(std::abs(w[0] + w[1] + w[2] - 1) > 1e-6);
}

}  // namespace gsp
