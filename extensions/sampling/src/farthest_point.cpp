// Farthest-point sampling on the vertices: each new sample is the vertex farthest from all
// earlier ones, and its propagation is bounded by that distance (only vertices closer to the
// new sample than to every earlier one change, and those are within it).
#include <gsp/errors.hpp>
#include <gsp/sampling/sampler.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace gsp::sampling {

SamplingResult Sampler::farthest(const SamplingOptions& options) const {
  const double inf = std::numeric_limits<double>::infinity();
  SamplingResult result;
  result.coverage.assign(mesh_.num_vertices(), inf);
  std::size_t available = 0;
  for (bool r : referenced_) available += r;
  const std::size_t want = options.count ? std::min(options.count, available) : available;

  // The first sample: the corner with the largest weight of a point drawn by area.
  Random random(options.seed);
  const Sample first = points_.draw(mesh_, random);
  const int corner = int(std::max_element(first.barycentric.begin(), first.barycentric.end()) -
                         first.barycentric.begin());
  Index next = mesh_.triangles[first.face][corner];
  double next_distance = inf;
  result.radius = inf;

  while (result.samples.size() < want) {
    if (options.radius > 0 && next_distance < options.radius) break;
    GeodesicOptions go;
    go.max_distance = next_distance;
    const GeodesicResult run = solver_.compute({Source::at_vertex(next)}, go);
    ++result.stats.propagations;
    result.stats.update_steps += run.stats.update_steps;
    result.stats.faces_reached += run.stats.faces_reached;
    const Index f = vertex_face_[next];
    const Triangle& t = mesh_.triangles[f];
    std::array<double, 3> b{0, 0, 0};
    b[t[0] == next ? 0 : (t[1] == next ? 1 : 2)] = 1;
    result.samples.push_back(make_sample(mesh_, f, b));
    result.radius = next_distance;

    // Merge and find the next farthest vertex in one pass. A component no sample has reached
    // yet is infinitely far: it gets the next sample.
    next = kInvalidIndex;
    next_distance = -1;
    for (std::size_t v = 0; v < result.coverage.size(); ++v) {
      if (!referenced_[v]) continue;
      double& c = result.coverage[v];
      if (run.vertex_distance[v] < c) c = run.vertex_distance[v];
      if (c > next_distance) next_distance = c, next = Index(v);
    }
    if (next == kInvalidIndex || next_distance <= 0) break;   // every vertex is a sample
    if (options.progress) {
      const double done = options.count ? double(result.samples.size()) / double(want)
                                        : std::min(1.0, options.radius / next_distance);
      options.progress(done);
    }
  }
  // Reported radius: no two samples are closer than it (each was that far from the earlier
  // ones); with a single sample, the largest distance from it.
  if (result.samples.size() == 1) result.radius = next_distance;
  return result;
}

}  // namespace gsp::sampling
