#include "corpus_aggregate.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

namespace gsp::bench {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

using Figure = std::function<double(const CorpusRow&)>;

double of_gsp(const CorpusRow& r, double CorpusMethod::*field) {
  const CorpusMethod* g = r.method("gsp");
  return g ? g->*field : kNaN;
}

double gsp_bound(const CorpusRow& r, double BoundStats::*field) {
  const CorpusMethod* g = r.method("gsp");
  return g && g->has_bounds ? g->bounds.*field : kNaN;
}

// The figures in report order, each read off a row.
const std::vector<std::pair<std::string, Figure>>& figures() {
  static const std::vector<std::pair<std::string, Figure>> list = {
      {"gsp_mre", [](const CorpusRow& r) { return of_gsp(r, &CorpusMethod::mre); }},
      {"gsp_max_re", [](const CorpusRow& r) { return of_gsp(r, &CorpusMethod::max_re); }},
      {"dijkstra_mre", [](const CorpusRow& r) { return r.mre("dijkstra"); }},
      {"heat_mre", [](const CorpusRow& r) { return r.mre("heat"); }},
      {"gsp_below_line", [](const CorpusRow& r) { return gsp_bound(r, &BoundStats::below_line); }},
      {"gsp_above_edge", [](const CorpusRow& r) { return gsp_bound(r, &BoundStats::above_edge); }},
      {"gsp_steps_per_face", [](const CorpusRow& r) { return r.steps_per_face; }},
      {"gsp_query_s", [](const CorpusRow& r) { return of_gsp(r, &CorpusMethod::query_s); }},
  };
  return list;
}

}  // namespace

Spread spread(std::vector<double> values) {
  values.erase(std::remove_if(values.begin(), values.end(), [](double v) { return !std::isfinite(v); }),
               values.end());
  Spread s{values.size(), kNaN, kNaN, kNaN, kNaN};
  if (values.empty()) return s;
  std::sort(values.begin(), values.end());
  double sum = 0;
  for (double v : values) sum += v;
  const auto quantile = [&](double q) {
    const double at = q * double(values.size() - 1);
    const std::size_t lo = std::size_t(std::floor(at)), hi = std::min(lo + 1, values.size() - 1);
    return values[lo] + (at - double(lo)) * (values[hi] - values[lo]);
  };
  s.mean = sum / double(values.size());
  s.median = quantile(0.5);
  s.p95 = quantile(0.95);
  s.worst = values.back();
  return s;
}

std::vector<CategoryAggregate> aggregate(const std::vector<CorpusRow>& rows) {
  std::vector<CategoryAggregate> out;
  for (const char* category : {"benign", "malign", "all"}) {
    CategoryAggregate a;
    a.category = category;
    std::vector<const CorpusRow*> in;
    for (const CorpusRow& r : rows)
      if (a.category == "all" || r.category == a.category) in.push_back(&r);
    for (const CorpusRow* r : in) {
      if (!r->ok()) {
        ++a.failed;
        continue;
      }
      ++a.run;
      a.with_exact += r->exact_references > 0;
      a.gsp_worse_than_dijkstra += gsp_worse(*r, "dijkstra");
      a.gsp_worse_than_heat += gsp_worse(*r, "heat");
      a.sources_worse_than_dijkstra += gsp_worse_sources(*r, "dijkstra");
      a.sources_worse_than_heat += gsp_worse_sources(*r, "heat");
      a.sources_vs_dijkstra += compared_sources(*r, "dijkstra");
      a.sources_vs_heat += compared_sources(*r, "heat");
      a.violating_bounds += gsp_violates(*r);
    }
    for (const auto& [name, figure] : figures()) {
      std::vector<double> values;
      for (const CorpusRow* r : in)
        if (r->ok()) values.push_back(figure(*r));
      a.figures.emplace_back(name, spread(std::move(values)));
    }
    out.push_back(std::move(a));
  }
  return out;
}

}  // namespace gsp::bench
