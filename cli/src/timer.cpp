#include <gsp/cli/memory.hpp>
#include <gsp/cli/timer.hpp>

#include <algorithm>

namespace gsp::cli {

void PhaseTimer::add(const std::string& name, double seconds) {
  // The kernel's per-thread RSS counters are folded in lazily, so a later reading of the
  // peak can come out a few pages lower: keep the running maximum.
  peak_ = std::max(peak_, resident_memory().peak);
  const std::size_t peak = peak_;
  for (Phase& p : phases_)
    if (p.name == name) {
      p.seconds += seconds;
      p.peak_after = peak;
      return;
    }
  phases_.push_back({name, seconds, peak});
}

double PhaseTimer::seconds(const std::string& name) const {
  for (const Phase& p : phases_)
    if (p.name == name) return p.seconds;
  return 0.0;
}

Json PhaseTimer::to_json() const {
  Json j = Json::object();
  for (const Phase& p : phases_) j[p.name] = p.seconds;
  j["total"] = elapsed();
  return j;
}

void PhaseTimer::write_memory(Json& j, std::size_t vertices) const {
  const std::size_t peak = std::max(peak_, resident_memory().peak);
  j["peak_bytes"] = peak;
  Json after = Json::object(), per_vertex = Json::object();
  for (const Phase& p : phases_) {
    after[p.name] = p.peak_after;
    if (vertices) per_vertex[p.name] = double(p.peak_after) / double(vertices);
  }
  j["peak_after"] = after;
  if (vertices) {
    j["peak_bytes_per_vertex"] = double(peak) / double(vertices);
    j["peak_after_per_vertex"] = per_vertex;
  }
}

}  // namespace gsp::cli
