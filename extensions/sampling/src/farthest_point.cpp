// Farthest-point sampling on the vertices: each new sample is the vertex farthest from all
// earlier ones, and its propagation is bounded by that distance (only vertices closer to the
// new sample than to every earlier one change, and those are within it). Bounded runs
// (compute_local) and a max-heap of coverage values with lazy deletion keep each sample's
// cost to its neighbourhood.
#include <gsp/errors.hpp>
#include <gsp/sampling/sampler.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>
#include <utility>

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
  const auto& w = first.point.barycentric;
  const int corner = int(std::max_element(w.begin(), w.end()) - w.begin());
  Index next = mesh_.triangles[first.point.element][corner];
  double next_distance = inf;
  result.radius = inf;

  // (coverage, -vertex): the largest coverage first, the smallest index among equals.
  std::priority_queue<std::pair<double, std::int64_t>> heap;
  std::size_t unreached = available;   // referenced vertices no run has reached yet
  std::size_t scan = 0;                // unreached ones are found by a forward scan
  LocalWorkspace workspace = solver_.make_workspace();
  while (result.samples.size() < want) {
    if (options.radius > 0 && next_distance < options.radius) break;
    GeodesicOptions go;
    go.max_distance = next_distance;
    const LocalField run = solver_.compute_local({Source::at_vertex(next)}, go, workspace);
    ++result.stats.propagations;
    result.stats.update_steps += run.stats.update_steps;
    result.stats.faces_reached += run.stats.faces_reached;
    const Index f = vertex_face_[next];
    const Triangle& t = mesh_.triangles[f];
    std::array<double, 3> b{0, 0, 0};
    b[t[0] == next ? 0 : (t[1] == next ? 1 : 2)] = 1;
    result.samples.push_back(make_sample(mesh_, f, b));
    result.radius = next_distance;

    for (std::size_t k = 0; k < run.vertices.size(); ++k) {
      const Index v = run.vertices[k];
      double& c = result.coverage[v];
      if (!referenced_[v] || !(run.vertex_distance[k] < c)) continue;
      if (c == inf) --unreached;
      c = run.vertex_distance[k];
      heap.push({c, -std::int64_t(v)});
    }
    // The next sample: a vertex of a component no sample has reached yet (infinitely far),
    // else the farthest one.
    next = kInvalidIndex;
    next_distance = -1;
    if (unreached > 0) {
      while (!(referenced_[scan] && result.coverage[scan] == inf)) ++scan;
      next = Index(scan), next_distance = inf;
    } else {
      while (!heap.empty() && heap.top().first != result.coverage[Index(-heap.top().second)]) heap.pop();
      if (!heap.empty()) next = Index(-heap.top().second), next_distance = heap.top().first;
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
