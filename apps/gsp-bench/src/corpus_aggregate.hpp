#pragma once
// The corpus figures per category (benign, malign, all): the spread of each per-mesh figure
// (mean, median, 95th percentile, worst) and the counts the issue asks about (failures,
// meshes where GSP is less accurate than a baseline, meshes where it breaks a bound).
#include "corpus.hpp"

#include <string>
#include <utility>
#include <vector>

namespace gsp::bench {

// Over the finite values only (a mesh without exact distances has no MRE); NaN when none.
struct Spread {
  std::size_t n = 0;
  double mean, median, p95, worst;   // worst = largest: every figure here is "lower is better"
};
Spread spread(std::vector<double> values);   // p95 interpolated linearly between ranks (numpy's default)

struct CategoryAggregate {
  std::string category;                                 // benign | malign | all
  std::vector<std::pair<std::string, Spread>> figures;  // gsp_mre, gsp_max_re, ..., gsp_query_s
  std::size_t run = 0, failed = 0, with_exact = 0;
  std::size_t gsp_worse_than_dijkstra = 0, gsp_worse_than_heat = 0;   // gsp_worse (corpus.hpp)
  // The same per source (gsp_worse_sources), out of the sources compared.
  std::size_t sources_worse_than_dijkstra = 0, sources_worse_than_heat = 0;
  std::size_t sources_vs_dijkstra = 0, sources_vs_heat = 0;
  std::size_t violating_bounds = 0;                     // gsp_violates (corpus.hpp)
};

std::vector<CategoryAggregate> aggregate(const std::vector<CorpusRow>& rows);

}  // namespace gsp::bench
