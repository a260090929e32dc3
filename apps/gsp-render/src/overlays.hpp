#pragma once
// What gsp-render reads besides the mesh: per-vertex fields (a .txt file or a PLY property),
// per-face labels, point sets and polylines. Problems in these files throw gsp::IoError naming
// the file and the line (exit code 1).
#include <gsp/types.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace gsp::render_app {

// One value per line (gsp::io::read_values_txt); `expected` values or an IoError.
std::vector<double> read_field(const std::string& path, std::size_t expected, const char* what);

// The per-vertex scalar property `name` of a mesh file (PLY `float NAME`, glTF `_NAME`,
// integer properties too). IoError listing the properties the file has when it is missing.
std::vector<double> read_property(const std::string& mesh_path, const std::string& name);

// Integers, one per line (face labels): IoError for a value that is not an integer.
std::vector<std::int32_t> read_labels(const std::string& path, std::size_t expected);

// Face labels from per-vertex labels (e.g. gsp-geodesic's `source` property): the label most
// corners of a face have, the first corner's when all three differ. Non-integer values throw
// IoError naming `path`.
std::vector<std::int32_t> face_labels_from_vertices(const std::vector<double>& vertex_labels,
                                                    const std::vector<Triangle>& triangles, const std::string& path);

// Points: any format gsp::io::read_mesh reads (.xyz, .ply, .obj, ...); its vertex positions.
std::vector<Vec3> read_points(const std::string& path);

// Polylines: "x y z" per line (commas allowed), '#' starts a comment, a blank line ends one
// polyline and starts the next.
std::vector<std::vector<Vec3>> read_polylines(const std::string& path);

}  // namespace gsp::render_app
