#pragma once
// What gsp-cvt-compare measures of one remesh against its input: angles, Hausdorff distance,
// topology as a whole and per component (the remesh must keep each component's Euler
// characteristic and boundary loops), duplicate vertices.
#include <gsp/cli/json.hpp>
#include <gsp/mesh.hpp>
#include <gsp/topology.hpp>

#include <cmath>
#include <cstddef>
#include <string>

namespace gsp::cvt_compare {

// The input's figures the rows are judged against; surface_components: manifold and
// orientable components (those a surface remesh can take as they are).
cli::Json describe_input(const TriangleMesh& input);

struct Measures {
  TopologyReport topology;
  std::size_t duplicate_vertices = 0;
  double min_angle = 0, mean_min_angle = 0, percent_below_30 = 0, mean_aspect_ratio = 0;
  std::size_t degenerate = 0;
  double hausdorff_percent = NAN;   // NaN: a surface without area
  // Largest distance from the input's feature curves (creases over 40 degrees, boundaries,
  // non-manifold edges; cvt::detect_features) to the output, % of the diagonal: how much of a
  // crease or a corner the remesh cut off. NaN: no feature edge.
  double feature_distance_percent = NAN;
  // Manifold, oriented, no duplicates, the per-component topology of the surface the input
  // describes (cvt::described_surface: its seams closed, without its doubled faces and faces
  // with a repeated vertex, with its non-manifold vertices split).
  bool topology_kept = false;
  std::string topology_difference;
};

// The remesh's figures; `hausdorff_samples` area-uniform points per surface.
Measures measure_output(const TriangleMesh& input, const TriangleMesh& output, std::size_t hausdorff_samples);
cli::Json to_json(const Measures& m);

}  // namespace gsp::cvt_compare
