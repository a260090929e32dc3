#pragma once
// Turning a face's stored corner distances back into a point in 3D (internal).
#include <gsp/mesh.hpp>

namespace gsp::detail {

// The point in the plane of face f whose squared distances to the corners are d2[0..2]
// (in units of `unit` model lengths, i.e. the propagation's normalised units). Trilateration:
// two corners fix the point up to a mirror image, the third picks the side.
Vec3 locate_virtual_source(const TriangleMesh& mesh, Index f, const double d2[3], double unit);

}  // namespace gsp::detail
