#pragma once
// Turning a point of a face's canonical 2D frame back into 3D (internal).
#include <gsp/mesh.hpp>

namespace gsp::detail {

// The canonical frame of face f (intrinsic_geometry.hpp) placed in 3D: corner 0 at the origin,
// x towards corner 1, y towards corner 2. (x, y) in model units.
Vec3 canonical_to_3d(const TriangleMesh& mesh, Index f, double x, double y);

}  // namespace gsp::detail
