#pragma once
// The corpus reports: JSON (every row, the bounds of every method, the aggregate), CSV (one
// row per mesh, for scripts/plot_corpus.py) and the text tables on stdout.
#include "corpus_aggregate.hpp"

#include <gsp/cli/json.hpp>

#include <string>
#include <vector>

namespace gsp::bench {

struct CorpusReport {
  std::vector<std::string> methods;    // --methods, in order: the CSV's per-method columns
  std::vector<CorpusRow> rows;         // one per mesh file, in file order
  std::vector<std::string> point_clouds;   // files skipped for having no faces
};

cli::Json corpus_json(const CorpusReport& report);
std::string corpus_csv(const CorpusReport& report);
std::string corpus_table(const CorpusReport& report);

}  // namespace gsp::bench
