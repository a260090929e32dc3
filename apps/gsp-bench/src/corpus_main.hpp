#pragma once
// gsp-bench --corpus: every mesh of the folders given, loaded and benchmarked one at a time,
// each inside its own try/catch so that one bad file is a failed row, never the end of the run.
#include "options.hpp"

#include <gsp/cli/app.hpp>

namespace gsp::bench {

void run_corpus(cli::Context& ctx, const Options& options, const Settings& settings);

}  // namespace gsp::bench
