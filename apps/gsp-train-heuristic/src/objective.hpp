#pragma once
// The error measure the heuristic is trained on: per mesh, the mean over its sources of the
// mean relative error |approx - exact| / exact over the vertices with a finite, positive
// exact distance; the objective is the mean of that over the meshes (every mesh weighs the
// same, whatever its size).
#include "training_set.hpp"

#include <gsp/heuristic.hpp>

#include <vector>

namespace gsp::train {

struct ErrorStats {
  double mre = 0;          // mean relative error (fraction, not percent)
  double signed_mre = 0;   // mean of (approx - exact) / exact: < 0 under-estimates
  double max_re = 0;       // largest relative error of any vertex and source
  std::size_t unreached = 0;   // vertices with a finite exact distance that the method left at +inf (error 1 each)
};

// Scores per-source approximations (approx[k][v] for mesh.sources[k]) against the exact ones.
ErrorStats score(const TrainingMesh& mesh, const std::vector<std::vector<double>>& approx);

// GSP with this heuristic (one solver, all sources of the mesh; single precision, default
// queue, no layout optimisation: the layout changes the speed, not the distances).
ErrorStats evaluate_gsp(const TrainingMesh& mesh, const VisibilityHeuristic& heuristic);
// Dijkstra on the edge graph, for scale.
ErrorStats evaluate_dijkstra(const TrainingMesh& mesh);

// How the per-mesh MREs are combined. `mean`: their mean (meshes with large errors, the CAD
// ones, dominate). `geomean`: their geometric mean, i.e. every mesh's *relative* improvement
// counts the same, so 0.3% -> 0.2% on a statue weighs as much as 3% -> 2% on a CAD part.
enum class Aggregate { mean, geomean };

double objective(const std::vector<TrainingMesh>& meshes, const VisibilityHeuristic& heuristic,
                 Aggregate aggregate = Aggregate::mean);

}  // namespace gsp::train
