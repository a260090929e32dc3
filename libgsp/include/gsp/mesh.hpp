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
// not finite. Repeated indices, zero areas and duplicates are *not* errors (see topology.hpp).
void validate(const TriangleMesh& mesh);

// The axis-aligned box of all positions (unreferenced vertices included); a zero box at the
// origin for a mesh without vertices.
struct BoundingBox {
  Vec3 min, max;
  double diagonal() const { return distance(min, max); }
  Vec3 center() const { return 0.5 * (min + max); }
};
BoundingBox bounding_box(const TriangleMesh& mesh);

}  // namespace gsp
