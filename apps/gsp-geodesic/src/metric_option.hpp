#pragma once
// --metric: propagate in a Riemannian metric (gsp::anisotropic) instead of the 3D lengths.
//   --metric direction=X,Y,Z:ratio=R   a step along the direction costs R, across it 1
//   --metric curvature:ratio=R[:smooth=N]  a step along the largest principal curvature costs R
//                                      (directions smoothed over N one-rings, default 3)
//   --metric attributes                tensors from the input's tensor_xx ... tensor_zz vertex properties
//   --metric FILE                      tensors from a text file (docs/anisotropic.md)
#include <gsp/cli/load.hpp>
#include <gsp/geodesics.hpp>
#include <gsp/types.hpp>

#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace gsp::cli {
class Context;
}

namespace gsp::geodesic_app {

struct MetricRequest {
  enum class Kind { none, file, attributes, direction, curvature };
  Kind kind = Kind::none;
  std::string spec;            // as given
  Vec3 direction;              // Kind::direction
  double ratio = 1;            // Kind::direction and Kind::curvature
  int smoothing = 3;           // Kind::curvature: one-ring smoothing rounds of the directions
  bool wanted() const { return kind != Kind::none; }
};

void add_metric_option(CLI::App& app, std::string& spec);

// Syntax only; UsageError (exit 2) for a malformed spec, a ratio that is not > 0 or a zero
// direction. An empty spec is Kind::none; anything not starting with direction=, curvature or
// equal to "attributes" is a file name.
MetricRequest parse_metric(const std::string& spec);

// SolverOptions::edge_lengths and edge_lengths_line_scale for the loaded mesh (phase "metric";
// settings "metric"); nothing when no metric is asked for. Throws IoError / InvalidInput (exit
// 1): unreadable or malformed file, wrong tensor count, a tensor that is not positive definite,
// no tensor properties in the input.
void apply_metric(cli::Context& ctx, const MetricRequest& request, const cli::LoadedMesh& in, SolverOptions& so);

}  // namespace gsp::geodesic_app
