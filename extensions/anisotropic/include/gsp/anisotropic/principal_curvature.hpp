#pragma once
// Per-vertex principal curvatures and directions, estimated by fitting the shape operator to
// the change of the vertex normals over the one-ring.
#include <gsp/mesh.hpp>

#include <vector>

namespace gsp::anisotropic {

struct PrincipalCurvature {
  Vec3 normal;                 // unit, angle-weighted mean of the incident face normals
  Vec3 max_direction;          // unit tangent: direction of the larger |curvature|
  Vec3 min_direction;          // unit tangent, perpendicular to max_direction
  double max_curvature = 0;    // signed (positive where the surface bends away from the normal),
  double min_curvature = 0;    // |max_curvature| >= |min_curvature|
  bool valid = false;          // false: too few neighbours or a degenerate fit (directions zero)
};

// For vertex v with normal n and tangent basis (t1, t2): the symmetric 2x2 S that best maps
// each neighbour's tangent offset to the tangent part of its normal change, n_j - n_v ~ S (p_j -
// p_v) (least squares); its eigenvectors are the principal directions. Needs consistently
// oriented faces around v.
std::vector<PrincipalCurvature> principal_curvatures(const TriangleMesh& mesh);

}  // namespace gsp::anisotropic
