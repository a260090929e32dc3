#pragma once
// Preview pictures by ray casting (Embree): a mesh coloured by a scalar field with iso-lines,
// or by face labels, with points, polylines and sources, seen by a perspective camera framed
// automatically (camera.hpp), shaded by a headlight (two-sided Lambert plus ambient).
//
//   gsp::render::Scene scene;
//   scene.mesh = mesh;
//   scene.vertex_field = distances;        // one per vertex
//   scene.sources = {mesh.positions[0]};
//   gsp::render::RenderOptions options;    // 1024 x 1024, viridis, 20 iso-lines
//   gsp::render::write_png("distance.png", gsp::render::render(scene, options));
#include <gsp/render/camera.hpp>
#include <gsp/render/image.hpp>
#include <gsp/render/options.hpp>
#include <gsp/render/scene.hpp>

#include <string>
#include <vector>

namespace gsp::render {

// Time spent in the two phases of render(), for --stats.
struct RenderTimings {
  double build = 0.0;   // Embree scene (BVH) and per-vertex normals
  double trace = 0.0;   // casting and shading all pixels
};

// Throws gsp::InvalidInput for a scene or options that fail validate(), gsp::Error if Embree
// cannot be set up.
Image render(const Scene& scene, const RenderOptions& options, RenderTimings* timings = nullptr);

// The picture gsp-geodesic --png writes: the mesh coloured by the field (iso-lines per
// options), the sources as red spheres; written atomically. Throws like render() and
// write_png().
void render_field_preview(const std::string& png_path, const TriangleMesh& mesh,
                          const std::vector<double>& vertex_field, const std::vector<Vec3>& source_points,
                          const RenderOptions& options);

}  // namespace gsp::render
