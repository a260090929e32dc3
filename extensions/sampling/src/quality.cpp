// Quality figures: nearest-neighbour distances with propagations bounded by 2r, the
// coverage radius with one propagation from all samples, and Lagae and Dutre's normalised
// radius.
#include "coverage_field.hpp"

#include <gsp/errors.hpp>
#include <gsp/sampling/quality.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace gsp::sampling {

SamplingQuality measure_quality(const Sampler& sampler, const SamplingResult& result,
                                const QualityOptions& options) {
  const TriangleMesh& mesh = sampler.mesh();
  const std::vector<Sample>& samples = result.samples;
  if (samples.empty()) throw InvalidInput("quality: no samples");
  for (const Sample& s : samples)
    if (!s.point.exists_in(mesh)) throw InvalidInput("quality: a sample names a face that does not exist");
  const double r = result.radius;
  SamplingQuality q;

  // Samples grouped by face (CSR), so each bounded run looks only at the faces it reached
  // that hold a sample.
  std::vector<Index> begin(mesh.num_faces() + 1, 0), by_face(samples.size());
  for (const Sample& s : samples) ++begin[s.point.element + 1];
  std::partial_sum(begin.begin(), begin.end(), begin.begin());
  {
    std::vector<Index> fill(begin.begin(), begin.end() - 1);
    for (std::size_t i = 0; i < samples.size(); ++i) by_face[fill[samples[i].point.element]++] = Index(i);
  }

  std::vector<bool> is_checked(samples.size(), options.max_checked == 0 || options.max_checked >= samples.size());
  if (!is_checked.empty() && !is_checked[0]) {
    std::vector<Index> order(samples.size());
    std::iota(order.begin(), order.end(), Index(0));
    Random random(options.seed);
    for (std::size_t i = 0; i < options.max_checked; ++i) {
      std::swap(order[i], order[i + random.below(order.size() - i)]);
      is_checked[order[i]] = true;
    }
  }
  const double inf = std::numeric_limits<double>::infinity();
  const double bound = std::isfinite(r) && r > 0 ? 2 * r : inf;
  GeodesicOptions go;
  go.max_distance = bound;   // every face that can hold a point within it is reached
  go.want_face_sources = true;
  q.min_distance = bound;
  std::vector<double> coverage(mesh.num_vertices(), inf), run_vertex(mesh.num_vertices(), inf);
  const detail::VertexFaces round(mesh);
  LocalWorkspace workspace = sampler.solver().make_workspace();
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const Sample& s = samples[i];
    const LocalField run = sampler.solver().compute_local({Source::at(s.point)}, go, workspace);
    for (std::size_t k = 0; k < run.vertices.size(); ++k)
      coverage[run.vertices[k]] = std::min(coverage[run.vertices[k]], run.vertex_distance[k]);
    if (is_checked[i]) {
      ++q.samples_checked;
      // A sample's distance is at most that of the run's virtual source in its face, and at
      // most a corner's value plus the straight segment from it: on a long sliver the one
      // virtual source can be a bend far too long at the sample, and a sliver whose source
      // reads beyond the bound is not among the run's faces, so the faces round every vertex
      // the run reached are read too (as the sampler's own test: coverage_field.hpp).
      for (std::size_t k = 0; k < run.vertices.size(); ++k) run_vertex[run.vertices[k]] = run.vertex_distance[k];
      auto through_corners = [&](Index f) {
        for (Index j = begin[f]; j < begin[f + 1]; ++j)
          if (by_face[j] != i)
            q.min_distance = std::min(q.min_distance, corner_paths(mesh, f, samples[by_face[j]].position, run_vertex));
      };
      for (Index v : run.vertices)
        for (Index c = round.begin[v]; c < round.begin[v + 1]; ++c) through_corners(round.faces[c]);
      for (std::size_t k = 0; k < run.faces.size(); ++k) {
        const Index f = run.faces[k];
        const VirtualSource& vs = run.face_sources[k];
        for (Index j = begin[f]; j < begin[f + 1]; ++j)
          if (by_face[j] != i)
            q.min_distance = std::min(q.min_distance, vs.sigma + distance(samples[by_face[j]].position, vs.position));
      }
      for (Index v : run.vertices) run_vertex[v] = inf;
    }
    if (options.progress) options.progress(double(i + 1) / double(samples.size() + 1));
  }
  q.min_distance_ratio = r > 0 ? q.min_distance / r : 0.0;

  const std::vector<bool>& used = sampler.referenced();
  bool all_reached = true;
  for (std::size_t v = 0; v < coverage.size(); ++v) all_reached &= !used[v] || std::isfinite(coverage[v]);
  if (!all_reached) {
    std::vector<Source> all;
    all.reserve(samples.size());
    for (const Sample& s : samples) all.push_back(Source::at(s.point));
    const GeodesicResult field = sampler.solver().compute(all);
    for (std::size_t v = 0; v < coverage.size(); ++v)
      if (!std::isfinite(coverage[v])) coverage[v] = field.vertex_distance[v];
  }
  for (std::size_t v = 0; v < coverage.size(); ++v)
    if (used[v]) q.coverage_radius = std::max(q.coverage_radius, coverage[v]);
  q.coverage_ratio = r > 0 ? q.coverage_radius / r : 0.0;
  if (options.progress) options.progress(1.0);

  q.area = sampler.area();
  q.packing_radius = packing_radius(q.area, samples.size());
  q.normalized_radius = q.packing_radius > 0 ? 0.5 * r / q.packing_radius : 0.0;
  return q;
}

}  // namespace gsp::sampling
