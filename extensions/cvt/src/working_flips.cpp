#include "working_flips.hpp"

#include "flips.hpp"

#include <vector>

namespace gsp::cvt::detail {

std::size_t flip_in_planes(WorkingMesh& w, const TriangleMesh& input, double max_height,
                           std::unique_ptr<InputWalk>& walk) {
  std::vector<bool> changed(w.mesh.num_faces(), false);
  const std::size_t flips = delaunay_flips_in_planes(w.mesh, max_height, 20 * w.mesh.num_faces(), changed);
  if (flips == 0) return 0;
  walk = std::make_unique<InputWalk>(input);
  for (Index f = 0; f < w.mesh.num_faces(); ++f) {
    if (!changed[f]) continue;
    const Triangle& t = w.mesh.triangles[f];
    const Vec3 centroid = (1.0 / 3) * (w.mesh.positions[t[0]] + w.mesh.positions[t[1]] + w.mesh.positions[t[2]]);
    const Index p = walk->locate(w.parent[f], centroid, false).first;
    w.parent[f] = p;
    for (int k = 0; k < 3; ++k) w.corner_bary[f][k] = affine_coordinates(input, p, w.mesh.positions[t[k]]);
  }
  return flips;
}

}  // namespace gsp::cvt::detail
