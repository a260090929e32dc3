#pragma once
// What is in a picture: a triangle mesh (with an optional per-vertex field or per-face labels),
// points, polylines and marked sources. Plain data: fill the members, then render().
#include <gsp/mesh.hpp>
#include <gsp/types.hpp>

#include <cstdint>
#include <vector>

namespace gsp::render {

struct Scene {
  TriangleMesh mesh;                        // may be empty (points / lines only)
  std::vector<double> vertex_field;         // empty, or one value per mesh vertex; NaN/inf = unreached (grey)
  // Empty, or one per face (e.g. Voronoi regions); < 0 = none. Labels colour their faces in
  // place of the field; the field's iso-lines are still drawn over them.
  std::vector<std::int32_t> face_labels;
  std::vector<Vec3> points;                 // drawn as small spheres
  std::vector<std::vector<Vec3>> polylines; // drawn as tubes (paths, iso-curves)
  std::vector<Vec3> sources;                // drawn as larger red spheres

  // Radii in model units; 0 = a fraction of the scene's bounding radius
  // (points 0.008, lines 0.004, sources 0.02).
  double point_radius = 0.0, line_radius = 0.0, source_radius = 0.0;
};

// Throws gsp::InvalidInput when a field or label array has the wrong length, a position is
// not finite, a triangle names a missing vertex, a radius is negative, or the scene is empty.
void validate(const Scene& scene);

struct BoundingSphere {
  Vec3 center;
  double radius = 0.0;
};

// Centre of the axis-aligned box of everything drawn (mesh, points, lines, sources), radius
// the largest distance from it; 1 when everything is at one point.
BoundingSphere bounding_sphere(const Scene& scene);

}  // namespace gsp::render
