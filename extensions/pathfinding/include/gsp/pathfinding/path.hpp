#pragma once
// Geodesic paths as surface polylines, and where they start and end.
#include <gsp/errors.hpp>
#include <gsp/mesh.hpp>

#include <array>
#include <limits>
#include <vector>

namespace gsp::pathfinding {

// A point of the surface: a vertex, or a point inside a face (barycentric weights of the
// face's corners 0, 1, 2, >= 0, summing to 1).
struct Endpoint {
  Index vertex = kInvalidIndex;
  Index face = kInvalidIndex;
  std::array<double, 3> barycentric{1, 0, 0};

  static Endpoint at_vertex(Index v) { return {v, kInvalidIndex, {1, 0, 0}}; }
  static Endpoint in_face(Index f, std::array<double, 3> bary) { return {kInvalidIndex, f, bary}; }
  bool is_vertex() const { return vertex != kInvalidIndex; }
};

// One point of a path: on face `face` at `barycentric`, i.e. at `position` in 3D. Consecutive
// points of a path share a face, so the segment between them lies on the surface.
struct PathPoint {
  Index face = kInvalidIndex;
  std::array<double, 3> barycentric{1, 0, 0};
  Vec3 position;
};

struct GeodesicPath {
  std::vector<PathPoint> points;   // from the source to the end point; empty if unreachable
  double length = std::numeric_limits<double>::infinity();   // 3D length of the polyline
  double field_distance = std::numeric_limits<double>::infinity();   // the field's value at the end
  Index source = kInvalidIndex;    // the source (index into the field's sources) it leads to
  bool found() const { return !points.empty(); }
};

// The end point is not reached by the field: it lies on a component without a source (or
// beyond max_distance).
struct NoPath : Error {
  using Error::Error;
};

// 3D position of an endpoint; throws InvalidInput when it names a missing vertex or face.
Vec3 endpoint_position(const TriangleMesh& mesh, const Endpoint& end);

// Sum of the segment lengths.
double polyline_length(const std::vector<PathPoint>& points);

}  // namespace gsp::pathfinding
