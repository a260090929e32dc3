#pragma once
// The human-readable report on stdout: one block per mesh, one line per method, then the
// ratios the benchmark is about (GSP against Dijkstra and the heat method's solve, layouts
// against each other) per mesh and as geometric means.
#include "report.hpp"

#include <string>

namespace gsp::bench {

std::string format_table(const Report& report);

}  // namespace gsp::bench
