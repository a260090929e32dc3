#include <gsp/render/options.hpp>

#include <gsp/errors.hpp>

#include <cmath>
#include <string>

namespace gsp::render {

void validate(const RenderOptions& o) {
  auto fail = [](const std::string& what) { throw InvalidInput("render options: " + what); };
  if (o.width < 1 || o.height < 1 || o.width > 16384 || o.height > 16384)
    fail("image size " + std::to_string(o.width) + "x" + std::to_string(o.height) + " is outside 1..16384");
  if (!std::isfinite(o.azimuth) || !std::isfinite(o.elevation)) fail("the view angles must be finite");
  if (!(o.fov > 0.0 && o.fov < 180.0)) fail("fov must be in (0, 180) degrees");
  if (!(o.margin >= 1.0) || !std::isfinite(o.margin)) fail("margin must be >= 1");
  if (o.supersample < 1 || o.supersample > 4) fail("supersample must be 1..4");
  if (o.iso_lines < 0) fail("iso_lines must be >= 0");
  if (!(o.line_width >= 0.0) || !std::isfinite(o.line_width)) fail("line_width must be >= 0");
  if (!(o.ambient >= 0.0 && o.ambient <= 1.0)) fail("ambient must be in [0, 1]");
  if (!std::isfinite(o.range_lo) || !std::isfinite(o.range_hi)) fail("the field range must be finite");
  if (o.threads < 0) fail("threads must be >= 0");
}

}  // namespace gsp::render
