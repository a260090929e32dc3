#include "objective.hpp"

#include <gsp/dijkstra.hpp>
#include <gsp/geodesics.hpp>

#include <algorithm>
#include <cmath>

namespace gsp::train {

ErrorStats score(const TrainingMesh& mesh, const std::vector<std::vector<double>>& approx) {
  ErrorStats s;
  std::size_t counted_sources = 0;
  for (std::size_t k = 0; k < mesh.sources.size(); ++k) {
    const std::vector<double>& exact = mesh.exact[k];
    double sum = 0, signed_sum = 0;
    std::size_t n = 0;
    for (std::size_t v = 0; v < exact.size(); ++v) {
      const double e = exact[v];
      if (!(e > 0) || !std::isfinite(e)) continue;   // the source itself, other components
      double re = 1, sre = 1;
      if (std::isfinite(approx[k][v])) {
        sre = (approx[k][v] - e) / e;
        re = std::abs(sre);
      } else {
        ++s.unreached;
      }
      sum += re, signed_sum += sre, ++n;
      s.max_re = std::max(s.max_re, re);
    }
    if (n == 0) continue;   // an isolated source: nothing to measure
    s.mre += sum / double(n);
    s.signed_mre += signed_sum / double(n);
    ++counted_sources;
  }
  if (counted_sources > 0) s.mre /= double(counted_sources), s.signed_mre /= double(counted_sources);
  return s;
}

ErrorStats evaluate_gsp(const TrainingMesh& mesh, const VisibilityHeuristic& heuristic) {
  SolverOptions options;
  options.optimize_layout = false;
  options.heuristic = heuristic;
  const GeodesicSolver solver(mesh.mesh, options);
  std::vector<std::vector<double>> approx;
  approx.reserve(mesh.sources.size());
  for (Index s : mesh.sources) approx.push_back(solver.compute({Source::at_vertex(s)}).vertex_distance);
  return score(mesh, approx);
}

ErrorStats evaluate_dijkstra(const TrainingMesh& mesh) {
  const DijkstraSolver solver(mesh.mesh);
  std::vector<std::vector<double>> approx;
  for (Index s : mesh.sources) approx.push_back(solver.compute({Source::at_vertex(s)}).vertex_distance);
  return score(mesh, approx);
}

double objective(const std::vector<TrainingMesh>& meshes, const VisibilityHeuristic& heuristic,
                 Aggregate aggregate) {
  if (meshes.empty()) return 0;
  double sum = 0;
  for (const TrainingMesh& m : meshes) {
    const double mre = evaluate_gsp(m, heuristic).mre;
    // A floor keeps a mesh GSP gets exactly right (a developable one) from sending log to -inf.
    sum += aggregate == Aggregate::mean ? mre : std::log(std::max(mre, 1e-6));
  }
  sum /= double(meshes.size());
  return aggregate == Aggregate::mean ? sum : std::exp(sum);
}

}  // namespace gsp::train
