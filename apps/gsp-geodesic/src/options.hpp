#pragma once
// What gsp-geodesic is asked to do, as parsed from the command line.
#include <gsp/cli/load.hpp>
#include <gsp/geodesics.hpp>
#include <gsp/render/preview_cli.hpp>

#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace gsp::geodesic_app {

struct Options {
  std::string input, output;
  std::vector<std::string> source_vertices;   // "I[,J,...]", repeatable
  std::vector<std::string> source_points;     // "x,y,z", repeatable
  std::vector<std::string> source_faces;      // "F:u,v", repeatable
  std::string source_polyline;                // line sources (line_sources.hpp): OBJ or x y z file
  std::string source_edges;                   // "a-b,b-c,..."
  bool source_boundary = false;
  std::string max_distance;                   // empty: none
  std::string method = "gsp";                 // gsp | dijkstra
  std::string strategy = "speed-limiter";
  std::string precision = "auto";
  std::string heuristic = "published";        // published | centroid | opposite-corner | FILE
  double f = 1.0;
  std::string layout = "auto";                // auto | on | off (layout_choice.hpp)
  bool no_layout = false;                     // = --layout off
  bool input_faces = false;
  bool ascii = false;
  bool labels = false;
  std::string domain = "auto";                // mesh | points | auto (points when the file has no faces)
  unsigned neighbours = 10;                   // --domain points: k nearest neighbours
  bool separate = false;                      // one field per source, OUT-<i>.<ext>
  bool matrix = false;                        // the distance matrix between the source vertices
  unsigned threads = 0;                       // for --separate / --matrix; 0: all hardware threads
  std::string metric;                         // --metric (metric_option.hpp); empty: 3D lengths
  render::PreviewRequest preview;             // --png, --view, --png-size
  cli::LoadOptions load;
};

void add_options(CLI::App& app, Options& options);

// Checked conversions (UsageError on unknown names).
Strategy parse_strategy(const std::string& name);
Precision parse_precision(const std::string& name);
VisibilityHeuristic parse_heuristic(const std::string& name_or_file);

}  // namespace gsp::geodesic_app
