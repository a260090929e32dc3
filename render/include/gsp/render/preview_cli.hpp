#pragma once
// The picture options every app shares — --png FILE.png, --view AZ,EL, --png-size N — declared
// and checked in one place so the apps agree on names, defaults and error messages.
#include <gsp/render/options.hpp>

#include <string>

namespace CLI {
class App;
}

namespace gsp::render {

struct PreviewRequest {
  std::string png;              // empty: no picture
  std::string view = "30,20";   // azimuth,elevation in degrees
  int size = 800;               // width = height in pixels
  bool wanted() const { return !png.empty(); }
};

// `what` completes the --png help: "also write a picture: <what>".
void add_preview_options(CLI::App& app, PreviewRequest& request, const std::string& what);

// The render settings for the request (2x2 supersampling); throws gsp::cli::UsageError for a
// name not ending in .png or a malformed --view. Call it before the work.
RenderOptions preview_options(const PreviewRequest& request);

}  // namespace gsp::render
