#pragma once
// What gsp-info reports about one mesh, and its two renderings (aligned text, JSON).
#include "measures.hpp"

#include <gsp/cli/json.hpp>
#include <gsp/cli/load.hpp>
#include <gsp/topology.hpp>

#include <cstdio>
#include <optional>
#include <string>

namespace gsp::info {

struct LayoutMeasure {
  double before = 0;   // mean |i - j| over edges (i, j), vertex order as stored
  double after = 0;    // the same after gsp::compute_cache_layout
  double seconds = 0;  // time of compute_cache_layout
};

struct Report {
  std::string path;
  io::ReadInfo info;
  std::size_t triangles = 0;          // after fan-triangulation of polygons
  bool weld_enabled = true;
  double weld_tolerance = 0;
  std::size_t welded_vertices = 0;
  std::size_t merged_vertices = 0;
  bool point_cloud = false;
  TopologyReport raw, welded;         // meshes only
  BoundingBox bbox;
  Summary edge_length;                // welded edges, each once
  ShapeMeasures shape;
  std::size_t max_valence = 0;        // welded
  std::optional<LayoutMeasure> layout;
};

cli::Json to_json(const Report& r);
void print_text(const Report& r, std::FILE* out);

}  // namespace gsp::info
