#pragma once
// The perspective camera render() uses, exposed so that callers (and tests) can tell where a
// point of the model lands in the picture.
#include <gsp/render/options.hpp>
#include <gsp/render/scene.hpp>
#include <gsp/types.hpp>

namespace gsp::render {

struct Camera {
  Vec3 eye;                      // centre of projection
  Vec3 forward, right, up;       // orthonormal; the picture's x runs along right, y along -up
  double tan_half_x = 0.0, tan_half_y = 0.0;  // half extent of the image plane at distance 1
  int width = 0, height = 0;

  // The (unnormalised) ray direction through the picture point (px, py) in pixel units,
  // (0, 0) the top-left corner, (width, height) the bottom-right one; forward has length 1.
  Vec3 direction(double px, double py) const;
  // Where a world point lands, in the same pixel units; false if it is not in front.
  bool project(Vec3 p, double& px, double& py) const;
};

// Looks at the sphere's centre from the options' azimuth/elevation, at the distance where the
// sphere (radius scaled by options.margin) is tangent to the view cone of half-angle fov / 2
// across the shorter side of the picture.
Camera frame_camera(const BoundingSphere& sphere, const RenderOptions& options);

}  // namespace gsp::render
