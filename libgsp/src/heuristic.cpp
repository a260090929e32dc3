#include <gsp/errors.hpp>
#include <gsp/heuristic.hpp>

#include <cmath>
#include <sstream>

namespace gsp {

VisibilityHeuristic VisibilityHeuristic::centroid() {
  VisibilityHeuristic h;
  h.lambda.fill(1.0);
  return h;
}

VisibilityHeuristic VisibilityHeuristic::opposite_corner() {
  VisibilityHeuristic h;
  h.lambda.fill(0.0);
  return h;
}

std::string VisibilityHeuristic::to_string() const {
  std::ostringstream out;
  out.precision(9);
  out << c << ' ' << g << ' ' << hh << ' ' << hg;
  for (double l : lambda) out << ' ' << l;
  return out.str();
}

VisibilityHeuristic VisibilityHeuristic::from_string(const std::string& text) {
  std::istringstream in(text);
  VisibilityHeuristic h;
  double* fields[4] = {&h.c, &h.g, &h.hh, &h.hg};
  for (double* f : fields)
    if (!(in >> *f)) throw InvalidInput("heuristic: expected 20 numbers (c g hh hg and 16 lambdas)");
  for (double& l : h.lambda)
    if (!(in >> l)) throw InvalidInput("heuristic: expected 20 numbers (c g hh hg and 16 lambdas)");
  for (double l : h.lambda)
    if (!(l >= 0.0 && l <= 1.0)) throw InvalidInput("heuristic: lambda values must lie in [0, 1]");
  for (double* f : fields)
    if (!std::isfinite(*f)) throw InvalidInput("heuristic: thresholds must be finite");
  return h;
}

}  // namespace gsp
