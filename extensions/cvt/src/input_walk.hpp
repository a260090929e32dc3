#pragma once
// Where a point of the surface lies on the input mesh, found by walking across its faces from
// a face near it. The working mesh's planar flips (working_flips.hpp) make working faces that
// straddle several input faces of one plane; their corners and the sites in them are mapped
// back to the input this way.
#include <gsp/mesh.hpp>
#include <gsp/surface_point.hpp>   // affine_coordinates

#include <array>
#include <utility>
#include <vector>

namespace gsp::cvt::detail {

class InputWalk {
 public:
  explicit InputWalk(const TriangleMesh& input);
  // From `start`, steps across the edge facing the most negative coordinate of x until a face
  // holds x (coordinates >= -1e-12), a boundary or non-manifold edge stops it, or after 1,000
  // steps; the face that came closest to holding x, and x's coordinates there (clamped to the
  // face and normalised when `clamp`, affine otherwise).
  std::pair<Index, std::array<double, 3>> locate(Index start, Vec3 x, bool clamp) const;

 private:
  const TriangleMesh& mesh_;
  std::vector<Index> across_;   // per halfedge 3 f + k (edge k -> k + 1): the other face, or kInvalidIndex
};

}  // namespace gsp::cvt::detail
