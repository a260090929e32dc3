#pragma once
// Writing a sample set: PLY/glTF/GLB/OBJ as a point cloud with face normals (PLY adds
// `int face`, `float u`, `float v`; glTF the attributes _FACE, _U, _V), or .txt with one
// sample per line: "x y z nx ny nz face u v". u, v are the barycentric weights of the face's
// corners 1 and 2 (as gsp-geodesic --source-face F:u,v takes them).
#include <gsp/sampling/surface_points.hpp>

#include <string>
#include <vector>

namespace gsp::sample_app {

void write_samples(const std::string& path, const std::vector<sampling::Sample>& samples, bool ascii);

}  // namespace gsp::sample_app
