#include <gsp/strategy_names.hpp>

#include <algorithm>
#include <array>
#include <utility>

namespace gsp {

namespace {

constexpr std::array<std::pair<Strategy, const char*>, 7> kNames{{
    {Strategy::speed_limiter, "speed-limiter"},
    {Strategy::speed_limiter_postpone, "speed-limiter-postpone"},
    {Strategy::static_postpone, "static-postpone"},
    {Strategy::dynamic_postpone, "dynamic-postpone"},
    {Strategy::hybrid_postpone, "hybrid-postpone"},
    {Strategy::bfs, "bfs"},
    {Strategy::priority_queue, "priority-queue"},
}};

}  // namespace

std::optional<Strategy> strategy_from_name(std::string name) {
  std::replace(name.begin(), name.end(), '_', '-');
  for (const auto& [strategy, text] : kNames)
    if (name == text) return strategy;
  return std::nullopt;
}

const char* strategy_name(Strategy strategy) {
  for (const auto& [s, text] : kNames)
    if (s == strategy) return text;
  return "?";
}

std::string strategy_names() {
  std::string out;
  for (const auto& entry : kNames) out += (out.empty() ? "" : ", ") + std::string(entry.second);
  return out;
}

}  // namespace gsp
