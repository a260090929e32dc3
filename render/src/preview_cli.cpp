#include <gsp/render/preview_cli.hpp>

#include <gsp/cli/app.hpp>
#include <gsp/cli/parse.hpp>

#include <CLI/CLI.hpp>

namespace gsp::render {

void add_preview_options(CLI::App& app, PreviewRequest& r, const std::string& what) {
  app.add_option("--png", r.png, "also write a picture: " + what)->type_name("FILE.png");
  app.add_option("--view", r.view, "picture camera: azimuth,elevation in degrees (default 30,20)")
      ->type_name("AZ,EL");
  app.add_option("--png-size", r.size, "picture width and height in pixels (default 800)")
      ->check(CLI::Range(16, 8192));
}

RenderOptions preview_options(const PreviewRequest& r) {
  RenderOptions options;
  if (!r.wanted()) return options;
  if (r.png.size() < 4 || r.png.compare(r.png.size() - 4, 4, ".png") != 0)
    throw cli::UsageError("--png: \"" + r.png + "\" does not end in .png");
  const std::vector<double> view = cli::parse_number_list(r.view, "--view");
  if (view.size() != 2) throw cli::UsageError("--view: expected azimuth,elevation");
  options.azimuth = view[0], options.elevation = view[1];
  options.width = options.height = r.size;
  options.supersample = 2;
  return options;
}

}  // namespace gsp::render
