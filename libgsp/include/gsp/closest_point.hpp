#pragma once
// The closest point of a triangle mesh to a query point: a linear scan, exact and free of
// set-up cost (the apps snap a handful of user-given points; queries by the million belong to
// an acceleration structure such as Embree's).
#include <gsp/mesh.hpp>
#include <gsp/surface_point.hpp>

#include <array>

namespace gsp {

// The answer of a closest-point query: where on the surface (always a face point; face
// kInvalidIndex until one is found), that point in 3D, and how far it is from the query.
struct ClosestPoint {
  SurfacePoint point = SurfacePoint::in_face(kInvalidIndex, {1, 0, 0});
  Vec3 position;
  double distance = 0;   // from the query point
};

// Closest point on triangle (a, b, c) to p, as barycentric weights.
std::array<double, 3> closest_point_on_triangle(Vec3 p, Vec3 a, Vec3 b, Vec3 c);

// Over all faces that do not repeat a vertex; throws InvalidInput if there is none.
ClosestPoint closest_surface_point(const TriangleMesh& mesh, Vec3 p);

}  // namespace gsp
