// Poisson-disk sampling with a target count: the radius is searched. The count of a
// saturated sampling goes like A / r^2, so each step is a secant step on (log r, log n),
// starting from slope -2 and a guess of normalised radius 0.75; once the target is
// bracketed, a step that leaves the bracket is replaced by bisection (geometric mean).
#include <gsp/errors.hpp>
#include <gsp/sampling/sampler.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>

namespace gsp::sampling {

namespace {

// Per vertex, the distance to the nearest kept sample (one multi-source propagation).
std::vector<double> coverage_of(const GeodesicSolver& solver, const std::vector<Sample>& samples) {
  std::vector<Source> sources;
  sources.reserve(samples.size());
  for (const Sample& s : samples) sources.push_back(Source::at(s.point));
  GeodesicOptions options;
  options.want_face_distances = false;
  return solver.compute(sources, options).vertex_distance;
}

}  // namespace

SamplingResult Sampler::poisson_count(const SamplingOptions& options) const {
  const double target = double(options.count);
  const double tolerance = std::floor(options.count_tolerance * target);
  double r = 2 * 0.75 * packing_radius(area(), options.count);
  double lo = 0, hi = std::numeric_limits<double>::infinity();   // radii giving too many / too few
  double prev_log_r = 0, prev_log_n = 0;
  bool have_prev = false;
  SamplingResult best, best_over;   // closest run; closest run with at least `count` (exact_count)
  double best_error = std::numeric_limits<double>::infinity();
  double best_over_error = std::numeric_limits<double>::infinity();
  SamplingStats total;
  int iterations = 0;
  for (; iterations < options.max_search_iterations; ++iterations) {
    SamplingResult run = poisson(r, options);
    total.propagations += run.stats.propagations;
    total.update_steps += run.stats.update_steps;
    total.faces_reached += run.stats.faces_reached;
    const double n = double(run.samples.size());
    const double error = std::abs(n - target);
    const bool over = n >= target;
    if (options.exact_count && over && error < best_over_error) {
      best_over_error = error, best_over = run;
      if (error <= tolerance) break;
    }
    if (error < best_error) best_error = error, best = std::move(run);
    if (!options.exact_count && error <= tolerance) break;
    if (n > target) lo = std::max(lo, r); else hi = std::min(hi, r);
    double slope = -2;
    const double log_r = std::log(r), log_n = std::log(std::max(n, 0.5));
    if (have_prev && std::abs(log_r - prev_log_r) > 1e-12) {
      const double s = (log_n - prev_log_n) / (log_r - prev_log_r);
      if (s < -0.5 && s > -8) slope = s;   // noise can make a secant useless; keep the model then
    }
    prev_log_r = log_r, prev_log_n = log_n, have_prev = true;
    double next = std::exp(log_r + (std::log(target) - log_n) / slope);
    if (!(next > lo && next < hi)) next = std::isfinite(hi) && lo > 0 ? std::sqrt(lo * hi) : next;
    if (!(next > lo && next < hi)) next = lo > 0 ? 2 * lo : 0.5 * hi;
    if (std::abs(next - r) <= 1e-12 * r) break;   // the bracket has closed: counts jump here
    r = next;
  }
  if (options.exact_count && std::isfinite(best_over_error)) {
    best = std::move(best_over);
    best.samples.resize(options.count);   // the last added go: the rest stay `radius` apart
    best.coverage = coverage_of(solver_, best.samples);
    ++total.propagations;
    best_error = 0;
  } else if (options.exact_count) {
    best_error = std::numeric_limits<double>::infinity();   // fewer than asked for
  }
  best.stats.propagations = total.propagations;
  best.stats.update_steps = total.update_steps;
  best.stats.faces_reached = total.faces_reached;
  best.stats.search_iterations = std::min(iterations + 1, options.max_search_iterations);
  best.stats.count_met = best_error <= tolerance;
  return best;
}

}  // namespace gsp::sampling
