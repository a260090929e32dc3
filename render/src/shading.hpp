#pragma once
// Colour of a ray hit: the mesh coloured by field or labels with iso-lines and wireframe,
// points, tubes and sources in flat colours, all lit by a headlight (two-sided Lambert plus
// ambient). Line widths are measured in output pixels through ray differentials: how far the
// hit point moves on the hit triangle's plane when the ray moves by one pixel.
#include <gsp/render/options.hpp>
#include <gsp/render/scene.hpp>

#include <array>
#include <vector>

namespace gsp::render::detail {

using Color = std::array<float, 4>;   // 0..255 per channel

// Everything the shading of one picture needs, prepared once before tracing.
struct ShadingSetup {
  const Scene* scene = nullptr;
  const RenderOptions* options = nullptr;
  std::vector<float> normals;   // smooth per-vertex normals, 3 floats each (zero where undefined)
  bool has_field = false;
  double lo = 0.0, hi = 1.0;    // field value -> colour-map parameter
  double step = 0.0;            // iso-line spacing in field units (0: none)
  Vec3 pixel_dx, pixel_dy;      // change of the ray direction per output pixel
};

ShadingSetup prepare_shading(const Scene& scene, const RenderOptions& options, Vec3 pixel_dx, Vec3 pixel_dy);

struct RayHit {
  unsigned geometry = 0, primitive = 0;
  float u = 0, v = 0;     // Embree barycentrics: weights of corners 1 and 2
  Vec3 normal;            // Embree's geometric normal (not normalised)
  double t = 0;           // distance along `direction`
  Vec3 direction;         // the ray's direction as cast (not normalised)
};

Color shade(const ShadingSetup& setup, const RayHit& hit);

// A colour per label, far apart for neighbouring label numbers (golden-ratio hues).
Rgba label_color(std::int32_t label);

}  // namespace gsp::render::detail
