#pragma once
// Writing polylines (geodesic paths, iso-curves) by file extension:
//   .obj         `v x y z` then one `l i j k ...` element per polyline (1-based)
//   .ply         vertices plus an `edge` element (vertex1, vertex2) per segment; a per-vertex
//                `int polyline` property says which polyline a point belongs to
//   .gltf/.glb   one mesh, one LINE_STRIP primitive per polyline
// Written atomically. Throws gsp::IoError for other extensions or when writing fails, and
// gsp::InvalidInput for a non-finite point.
#include <gsp/types.hpp>

#include <string>
#include <vector>

namespace gsp::io {

void write_polylines(const std::string& path, const std::vector<std::vector<Vec3>>& polylines);

}  // namespace gsp::io
