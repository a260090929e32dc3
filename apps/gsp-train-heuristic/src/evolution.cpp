#include "evolution.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <random>

namespace gsp::train {

namespace {

using Genes = std::array<double, 20>;

Genes encode(const VisibilityHeuristic& h) {
  Genes g{};
  g[0] = std::log(h.c), g[1] = std::log(h.g), g[2] = std::log(h.hh), g[3] = std::log(h.hg);
  for (int i = 0; i < 16; ++i) g[4 + i] = h.lambda[i];
  return g;
}

VisibilityHeuristic decode(const Genes& g, const VisibilityHeuristic& like) {
  VisibilityHeuristic h = like;   // keeps anything beyond the 20 numbers
  h.c = std::exp(g[0]), h.g = std::exp(g[1]), h.hh = std::exp(g[2]), h.hg = std::exp(g[3]);
  for (int i = 0; i < 16; ++i) h.lambda[i] = std::clamp(g[4 + i], 0.0, 1.0);
  return h;
}

// Standard normal from the raw engine (std::normal_distribution differs between standard
// libraries; this keeps a seed's run identical everywhere).
class Normal {
 public:
  explicit Normal(std::uint64_t seed) : rng_(seed) {}
  double operator()() {
    if (has_spare_) {
      has_spare_ = false;
      return spare_;
    }
    const double u1 = (double(rng_() >> 11) + 0.5) * 0x1.0p-53;
    const double u2 = double(rng_() >> 11) * 0x1.0p-53;
    const double r = std::sqrt(-2 * std::log(u1));
    spare_ = r * std::sin(2 * M_PI * u2), has_spare_ = true;
    return r * std::cos(2 * M_PI * u2);
  }

 private:
  std::mt19937_64 rng_;
  double spare_ = 0;
  bool has_spare_ = false;
};

}  // namespace

EvolutionResult evolve(const VisibilityHeuristic& start, const ObjectiveFn& objective,
                       const EvolutionOptions& options, const StepFn& on_step) {
  Normal normal(options.seed);
  Genes parent = encode(start);
  // Clamp the start too, so that the parent is exactly what decode() would produce.
  for (int i = 4; i < 20; ++i) parent[i] = std::clamp(parent[i], 0.0, 1.0);
  EvolutionResult result;
  result.best = decode(parent, start);
  result.start_value = result.best_value = objective(result.best);
  double sigma = options.sigma;
  // 1/5th success rule (Kern et al. 2004): grow on success, shrink on failure; the factors
  // balance when one child in five succeeds.
  const double grow = std::exp(1.0 / 3.0), shrink = std::exp(-1.0 / 12.0);
  for (int it = 1; it <= options.iterations; ++it) {
    Genes child = parent;
    for (double& x : child) x += sigma * normal();
    for (int i = 4; i < 20; ++i) child[i] = std::clamp(child[i], 0.0, 1.0);
    const VisibilityHeuristic candidate = decode(child, start);
    const double value = objective(candidate);
    EvolutionStep step;
    step.iteration = it;
    step.child = value;
    step.improved = value < result.best_value;
    if (value <= result.best_value) {   // ties drift across plateaus (unused table entries)
      parent = child;
      result.best = candidate;
      result.best_value = value;
      if (step.improved) ++result.improvements;
    }
    sigma = std::clamp(sigma * (step.improved ? grow : shrink), options.min_sigma, options.max_sigma);
    step.best = result.best_value;
    step.sigma = sigma;
    if (on_step) on_step(step);
  }
  return result;
}

}  // namespace gsp::train
