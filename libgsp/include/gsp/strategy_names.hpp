#pragma once
// The queue strategies' names, one list for every front end (apps, Python): "speed-limiter",
// "priority-queue", ...; '_' is accepted for '-' ("speed_limiter").
#include <gsp/geodesics.hpp>

#include <optional>
#include <string>

namespace gsp {

// The strategy named `name`, or nothing when there is none.
std::optional<Strategy> strategy_from_name(std::string name);
// "speed-limiter", ...
const char* strategy_name(Strategy strategy);
// "speed-limiter, speed-limiter-postpone, ..." for error messages.
std::string strategy_names();

}  // namespace gsp
