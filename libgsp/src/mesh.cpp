#include <gsp/errors.hpp>
#include <gsp/mesh.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace gsp {

void validate(const TriangleMesh& mesh) {
  const std::size_t nv = mesh.num_vertices();
  if (nv >= kInvalidIndex) throw InvalidInput("mesh has too many vertices for 32-bit indices");
  validate_positions(mesh.positions);
  if (!mesh.normals.empty() && mesh.normals.size() != nv)
    throw InvalidInput("normal count " + std::to_string(mesh.normals.size()) +
                       " differs from vertex count " + std::to_string(nv));
  for (std::size_t f = 0; f < mesh.num_faces(); ++f)
    for (Index v : mesh.triangles[f])
      if (v >= nv)
        throw InvalidInput("face " + std::to_string(f) + " names vertex " + std::to_string(v) +
                           " but there are only " + std::to_string(nv));
}

void validate_positions(const std::vector<Vec3>& positions, const char* what) {
  Vec3 lo{0, 0, 0}, hi{0, 0, 0};
  for (std::size_t i = 0; i < positions.size(); ++i) {
    const Vec3& p = positions[i];
    if (!is_finite(p)) throw InvalidInput(std::string(what) + " " + std::to_string(i) + " has a non-finite coordinate");
    const double m = std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)});
    if (m > kMaxCoordinate) {
      char buf[160];
      std::snprintf(buf, sizeof buf, " has a coordinate of magnitude %.3g, beyond the %.0e every module can square; scale the input", m, kMaxCoordinate);
      throw InvalidInput(std::string(what) + " " + std::to_string(i) + buf);
    }
    if (i == 0) lo = hi = p;
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
  const double span = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
  if (span > 0 && span < kMinExtent) {
    char buf[200];
    std::snprintf(buf, sizeof buf, "the positions span only %.3g, below the %.0e every module can square; scale the input", span, kMinExtent);
    throw InvalidInput(buf);
  }
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
