#pragma once
// The closest point of a triangle mesh to a query point: a linear scan, exact and free of
// set-up cost (the apps snap a handful of user-given points; queries by the million belong to
// an acceleration structure such as Embree's).
#include <gsp/mesh.hpp>

#include <array>

namespace gsp {

struct SurfacePoint {
  Index face = kInvalidIndex;
  std::array<double, 3> barycentric{1, 0, 0};   // weights of the face's corners 0, 1, 2
  Vec3 position;
  double distance = 0;   // from the query point
};

// Closest point on triangle (a, b, c) to p, as barycentric weights.
std::array<double, 3> closest_point_on_triangle(Vec3 p, Vec3 a, Vec3 b, Vec3 c);

// Over all faces that do not repeat a vertex; throws InvalidInput if there is none.
SurfacePoint closest_surface_point(const TriangleMesh& mesh, Vec3 p);

}  // namespace gsp
