#pragma once
// How a picture is taken: size, view direction, colouring, line overlays, quality.
#include <gsp/io/colormap.hpp>
#include <gsp/render/image.hpp>

namespace gsp::render {

// The world axis that points up in the picture: y for most scans and glTF, z for CAD/STL.
enum class UpAxis { y, z };

struct RenderOptions {
  int width = 1024, height = 1024;

  // The view (degrees). Elevation 0 looks horizontally; 90 looks straight down the up axis.
  // Azimuth turns the camera around the up axis; at (0, 0) the camera sits on +z (y up) or
  // on -y (z up), i.e. the usual front view.
  double azimuth = 30.0, elevation = 20.0;
  UpAxis up = UpAxis::y;
  // Perspective camera: field of view across the shorter image side (degrees). The camera is
  // placed so that the scene's bounding sphere, scaled by `margin`, just fills that angle.
  double fov = 30.0;
  double margin = 1.05;

  // Scalar field colouring: t = (value - lo) / (hi - lo); hi <= lo means the finite min/max.
  io::ColorMap colormap = io::ColorMap::viridis;
  double range_lo = 0.0, range_hi = -1.0;
  int iso_lines = 20;         // dark lines at (lo + k (hi - lo) / iso_lines), k = 1..n-1; 0 = none
  double line_width = 1.25;   // iso-line and wireframe width in output pixels
  bool wireframe = false;     // darken the mesh edges

  Rgba background = {255, 255, 255, 255};
  Rgba surface_color = {205, 205, 200, 255};   // the mesh without a field or labels
  Rgba unreached_color = {128, 128, 128, 255}; // NaN / infinite field values
  Rgba point_color = {40, 40, 40, 255};
  Rgba line_color = {230, 90, 20, 255};
  Rgba source_color = {220, 25, 25, 255};
  double ambient = 0.3;       // shade = ambient + (1 - ambient) |cos| to the headlight

  int supersample = 1;        // samples per pixel along each axis (2 = 2x2 anti-aliasing)
  int threads = 0;            // 0: all hardware threads
};

// Throws gsp::InvalidInput for sizes < 1 or > 16384, non-finite angles, fov outside (0, 180),
// supersample outside 1..4, negative iso_lines or line_width, margin < 1.
void validate(const RenderOptions& options);

}  // namespace gsp::render
