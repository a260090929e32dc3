#include <gsp/errors.hpp>
#include <gsp/mesh.hpp>

#include <algorithm>
#include <string>

namespace gsp {

void validate(const TriangleMesh& mesh) {
  const std::size_t nv = mesh.num_vertices();
  if (nv >= kInvalidIndex) throw InvalidInput("mesh has too many vertices for 32-bit indices");
  for (std::size_t i = 0; i < nv; ++i)
    if (!is_finite(mesh.positions[i]))
      throw InvalidInput("vertex " + std::to_string(i) + " has a non-finite coordinate");
  if (!mesh.normals.empty() && mesh.normals.size() != nv)
    throw InvalidInput("normal count " + std::to_string(mesh.normals.size()) +
                       " differs from vertex count " + std::to_string(nv));
  for (std::size_t f = 0; f < mesh.num_faces(); ++f)
    for (Index v : mesh.triangles[f])
      if (v >= nv)
        throw InvalidInput("face " + std::to_string(f) + " names vertex " + std::to_string(v) +
                           " but there are only " + std::to_string(nv));
}

namespace {

void grow(BoundingBox& b, const Vec3& p) {
  b.min = {std::min(b.min.x, p.x), std::min(b.min.y, p.y), std::min(b.min.z, p.z)};
  b.max = {std::max(b.max.x, p.x), std::max(b.max.y, p.y), std::max(b.max.z, p.z)};
}

}  // namespace

BoundingBox bounding_box(const std::vector<Vec3>& points) {
  BoundingBox b;
  if (points.empty()) return b;
  b.min = b.max = points.front();
  for (const Vec3& p : points) grow(b, p);
  return b;
}

BoundingBox bounding_box(const TriangleMesh& mesh) { return bounding_box(mesh.positions); }

BoundingBox face_bounding_box(const TriangleMesh& mesh) {
  BoundingBox b;
  if (mesh.triangles.empty()) return b;
  b.min = b.max = mesh.positions[mesh.triangles.front()[0]];
  for (const Triangle& t : mesh.triangles)
    for (Index v : t) grow(b, mesh.positions[v]);
  return b;
}

}  // namespace gsp
