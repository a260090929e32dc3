#pragma once
// Points on a triangle mesh: a sample as a point in a face with its position and face
// normal, and candidates drawn uniformly by area (face picked through a prefix sum of the
// face areas, then a uniform point of the triangle).
#include <gsp/mesh.hpp>
#include <gsp/sampling/random.hpp>
#include <gsp/surface_point.hpp>

#include <array>
#include <vector>

namespace gsp::sampling {

struct Sample {
  SurfacePoint point = SurfacePoint::in_face(kInvalidIndex, {1, 0, 0});   // always in a face
  Vec3 position;
  Vec3 normal;   // unit face normal ((0,0,0) for a zero-area face)
};

// The sample at (face, barycentric) of `mesh` (position and face normal filled in).
Sample make_sample(const TriangleMesh& mesh, Index face, std::array<double, 3> barycentric);

double triangle_area(const TriangleMesh& mesh, Index face);

// Draws points uniformly over the surface. Faces that repeat a vertex or have zero area are
// never drawn. Throws InvalidInput when the mesh has no face of positive area.
class AreaSampler {
 public:
  explicit AreaSampler(const TriangleMesh& mesh);
  // Only the faces marked in `faces` (one flag per face); the same throw when none has area.
  AreaSampler(const TriangleMesh& mesh, const std::vector<bool>& faces);
  double total_area() const { return prefix_.empty() ? 0.0 : prefix_.back(); }
  // A face by area, then uniform barycentric weights (the square-root map of Osada et al.).
  Sample draw(const TriangleMesh& mesh, Random& random) const;

 private:
  std::vector<double> prefix_;   // prefix_[f] = area of faces 0..f
};

}  // namespace gsp::sampling
