#include "validate_options.hpp"

#include <gsp/errors.hpp>

#include <cmath>
#include <string>

namespace gsp::detail {

void validate_options(const GeodesicOptions& options, QueryKind kind, bool custom_lengths, std::size_t num_vertices) {
  if (kind == QueryKind::local && (!options.targets.empty() || options.goal_directed))
    throw InvalidInput("compute_local: targets are not supported (use compute())");
  if (!(options.f > 0) || !(options.f0 > 0) || !(options.f1 > 0))
    throw InvalidInput("strategy parameters f, f0, f1 must be positive");
  if (std::isnan(options.max_distance) || options.max_distance < 0) throw InvalidInput("max_distance must be >= 0");
  if (options.goal_directed && options.targets.empty())
    throw InvalidInput("goal_directed (A*) needs at least one target");
  // Both are 3D constructions: a straight-line lower bound and a point in the face's plane.
  if (custom_lengths && options.goal_directed)
    throw InvalidInput("goal_directed (A*) bounds by 3D straight lines: not with SolverOptions::edge_lengths");
  if (custom_lengths && options.want_face_sources)
    throw InvalidInput("per-face virtual sources are 3D points: not with SolverOptions::edge_lengths");
  for (Index t : options.targets)
    if (t >= num_vertices)
      throw InvalidInput("target vertex " + std::to_string(t) + " does not exist (" + std::to_string(num_vertices) +
                         " vertices)");
}

}  // namespace gsp::detail
