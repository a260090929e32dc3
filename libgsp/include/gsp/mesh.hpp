#pragma once
// The data model: a triangle soup as read from a file, with nothing assumed about it.
// Connectivity, topology and layout are computed from it by the functions in
// connectivity.hpp, topology.hpp and layout.hpp; the soup itself is never repaired in place.
#include <gsp/types.hpp>

#include <vector>

namespace gsp {

struct TriangleMesh {
  std::vector<Vec3> positions;       // one per vertex, in the file's order
  std::vector<Triangle> triangles;   // may be empty: a point cloud
  std::vector<Vec3> normals;         // optional per-vertex normals (empty or one per vertex)

  std::size_t num_vertices() const { return positions.size(); }
  std::size_t num_faces() const { return triangles.size(); }
  bool is_point_cloud() const { return triangles.empty(); }
};

// Throws InvalidInput if a triangle names a vertex that does not exist or a position is
// not usable (validate_positions). Repeated indices, zero areas and duplicates are *not*
// errors (see topology.hpp).
void validate(const TriangleMesh& mesh);

// Coordinates every module can square: at most kMaxCoordinate in magnitude, and positions
// that span either nothing (all at one point: a degenerate input, not an error) or at least
// kMinExtent. The closest-point and ray searches (Embree) hold positions in single precision,
// whose squares overflow from about 1.8e19 (gsp-cvt's Hausdorff distance was NaN at 1e20) and
// lose their precision below about 1e-19; the core's double precision has fourth powers of
// lengths (Heron's areas: GSP was 1.4% off at 9e99, and gave zeros everywhere at 1e300).
// Throws InvalidInput naming the first position (`what`: "vertex", "point cloud: point") that
// is not finite or too large, or the span.
inline constexpr double kMaxCoordinate = 1e18;
inline constexpr double kMinExtent = 1e-18;
void validate_positions(const std::vector<Vec3>& positions, const char* what = "vertex");

// True when a triangle names one vertex twice: it has no plane, no angles, no unfolding, and
// every module leaves it out (topology.hpp counts such faces).
inline bool repeats_vertex(const Triangle& t) { return t[0] == t[1] || t[1] == t[2] || t[0] == t[2]; }

// An axis-aligned box; a zero box at the origin when there is nothing in it.
struct BoundingBox {
  Vec3 min, max;
  double diagonal() const { return distance(min, max); }
  Vec3 center() const { return 0.5 * (min + max); }
};
BoundingBox bounding_box(const std::vector<Vec3>& points);
// All positions, unreferenced vertices included.
BoundingBox bounding_box(const TriangleMesh& mesh);
// Only the vertices the faces name (a file's stray vertices do not count); a zero box for a
// mesh without faces.
BoundingBox face_bounding_box(const TriangleMesh& mesh);

}  // namespace gsp
