#pragma once
// Parsing of gsp-render's picture options (--size, --view, --background, ...) into
// gsp::render::RenderOptions. Malformed values throw gsp::cli::UsageError (exit code 2).
#include <gsp/render/options.hpp>

#include <string>

namespace gsp::render_app {

// "W x H" or "WxH" or "N" (square), each 1..16384.
void parse_size(const std::string& text, render::RenderOptions& options);
// "az,el" in degrees.
void parse_view(const std::string& text, render::RenderOptions& options);
// "white", "black", "transparent" or "r,g,b" (0..255).
render::Rgba parse_color(const std::string& text, const char* option);
// "lo,hi" with lo < hi.
void parse_range(const std::string& text, render::RenderOptions& options);

}  // namespace gsp::render_app
