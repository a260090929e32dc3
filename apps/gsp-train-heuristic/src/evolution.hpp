#pragma once
// The (1+1) evolution strategy the authors trained the heuristic with: perturb all 20
// parameters with Gaussian noise, keep the child when it is at least as good, and adapt the
// step size by the 1/5th success rule. Thresholds mutate in log space (they stay > 0 and a
// step is a relative change); lambdas are clamped to [0, 1].
#include <gsp/heuristic.hpp>

#include <cstdint>
#include <functional>

namespace gsp::train {

struct EvolutionOptions {
  int iterations = 300;        // children evaluated
  std::uint64_t seed = 1;      // the run is a deterministic function of the seed
  double sigma = 0.1;          // initial step (lambda units; log units for thresholds)
  double min_sigma = 1e-3;     // the step never shrinks below this (keeps exploring)
  double max_sigma = 0.5;
};

struct EvolutionStep {
  int iteration = 0;
  double child = 0, best = 0;   // objective of this child and of the parent after the step
  double sigma = 0;             // step size for the next child
  bool improved = false;        // strictly better than the parent
};

struct EvolutionResult {
  VisibilityHeuristic best;
  double start_value = 0, best_value = 0;
  int improvements = 0;
};

using ObjectiveFn = std::function<double(const VisibilityHeuristic&)>;
using StepFn = std::function<void(const EvolutionStep&)>;

EvolutionResult evolve(const VisibilityHeuristic& start, const ObjectiveFn& objective,
                       const EvolutionOptions& options, const StepFn& on_step = {});

}  // namespace gsp::train
