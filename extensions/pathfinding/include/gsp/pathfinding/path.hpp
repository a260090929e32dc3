#pragma once
// Geodesic paths as surface polylines, and where they start and end.
#include <gsp/errors.hpp>
#include <gsp/mesh.hpp>
#include <gsp/surface_point.hpp>

#include <array>
#include <limits>
#include <vector>

namespace gsp::pathfinding {

// Where a path starts or ends: any surface point (a vertex, or a point inside a face whose
// barycentric weights are >= 0 and sum to 1: gsp::are_barycentric).
using Endpoint = SurfacePoint;

// One point of a path: `point`, always a face point (a vertex is named as a corner of one of
// its faces; face kInvalidIndex until placed), is at `position` in 3D. Consecutive points of a
// path share a face, so the segment between them lies on the surface.
struct PathPoint {
  SurfacePoint point = SurfacePoint::in_face(kInvalidIndex, {1, 0, 0});
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

// Throws InvalidInput when `end` names a missing vertex or face, or a face point's weights are
// not barycentric: what every path query checks of the end points it is given.
void check_endpoint(const TriangleMesh& mesh, const Endpoint& end);

// Sum of the segment lengths.
double polyline_length(const std::vector<PathPoint>& points);

// Barycentric weights of x (a point of face f: on its plane up to rounding) in f, clamped to
// >= 0 and summing to 1.
std::array<double, 3> weights_in(const TriangleMesh& mesh, Index f, Vec3 x);

// The path the other way round. Each point is given the face of the segment that now ends at
// it (the face the point before it named in the old order: the convention of a traced path)
// where every point lies on that face; otherwise (the path named the face of the segment after
// each point, as a walk does in its own order) every point keeps its own face. Either way each
// point lies on the face it names and each segment in a face one of its ends names.
std::vector<PathPoint> reversed_path(const TriangleMesh& mesh, const std::vector<PathPoint>& points);

}  // namespace gsp::pathfinding
