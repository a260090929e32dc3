#include "view_options.hpp"

#include <gsp/cli/app.hpp>
#include <gsp/cli/parse.hpp>

#include <cmath>

namespace gsp::render_app {

namespace {

int parse_side(const std::string& item, const std::string& text) {
  int v = 0;
  bool ok = !item.empty() && item.size() <= 5;
  for (char c : item) {
    if (c < '0' || c > '9') { ok = false; break; }
    v = v * 10 + (c - '0');
  }
  if (!ok || v < 1 || v > 16384)
    throw cli::UsageError("--size: \"" + text + "\": expected WxH or N with sides 1..16384");
  return v;
}

}  // namespace

void parse_size(const std::string& text, render::RenderOptions& o) {
  const std::size_t x = text.find_first_of("xX");
  if (x == std::string::npos) {
    o.width = o.height = parse_side(text, text);
  } else {
    o.width = parse_side(text.substr(0, x), text);
    o.height = parse_side(text.substr(x + 1), text);
  }
}

void parse_view(const std::string& text, render::RenderOptions& o) {
  const std::vector<double> v = cli::parse_number_list(text, "--view");
  if (v.size() != 2) throw cli::UsageError("--view: \"" + text + "\": expected azimuth,elevation in degrees");
  o.azimuth = v[0];
  o.elevation = v[1];
}

render::Rgba parse_color(const std::string& text, const char* option) {
  if (text == "white") return {255, 255, 255, 255};
  if (text == "black") return {0, 0, 0, 255};
  if (text == "transparent") return {255, 255, 255, 0};
  const std::vector<double> v = cli::parse_number_list(text, option);
  render::Rgba c = {0, 0, 0, 255};
  bool ok = v.size() == 3;
  for (std::size_t i = 0; ok && i < 3; ++i) {
    ok = v[i] >= 0 && v[i] <= 255 && v[i] == std::floor(v[i]);
    if (ok) c[i] = std::uint8_t(v[i]);
  }
  if (!ok)
    throw cli::UsageError(std::string(option) + ": \"" + text +
                          "\": expected white, black, transparent or r,g,b with integers 0..255");
  return c;
}

void parse_range(const std::string& text, render::RenderOptions& o) {
  const std::vector<double> v = cli::parse_number_list(text, "--range");
  if (v.size() != 2 || !(v[0] < v[1])) throw cli::UsageError("--range: \"" + text + "\": expected lo,hi with lo < hi");
  o.range_lo = v[0];
  o.range_hi = v[1];
}

}  // namespace gsp::render_app
