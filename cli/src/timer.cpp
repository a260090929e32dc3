#include <gsp/cli/timer.hpp>

namespace gsp::cli {

void PhaseTimer::add(const std::string& name, double seconds) {
  for (auto& [n, s] : phases_)
    if (n == name) {
      s += seconds;
      return;
    }
  phases_.emplace_back(name, seconds);
}

double PhaseTimer::seconds(const std::string& name) const {
  for (const auto& [n, s] : phases_)
    if (n == name) return s;
  return 0.0;
}

Json PhaseTimer::to_json() const {
  Json j = Json::object();
  for (const auto& [n, s] : phases_) j[n] = s;
  j["total"] = elapsed();
  return j;
}

}  // namespace gsp::cli
