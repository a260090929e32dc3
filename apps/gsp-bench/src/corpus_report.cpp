#include "corpus_report.hpp"

#include "format.hpp"
#include "report.hpp"

#include <cmath>
#include <cstdio>

namespace gsp::bench {

namespace {

cli::Json tri_state(int v) { return v < 0 ? cli::Json() : cli::Json(v == 1); }

std::string tri_field(int v) { return v < 0 ? "" : std::to_string(v); }

const CorpusMethod* any_method(const CorpusRow& row, const std::string& name) {
  for (const CorpusMethod& m : row.methods)
    if (m.name == name) return &m;
  return nullptr;
}

cli::Json row_json(const CorpusRow& r) {
  cli::Json j;
  j["name"] = r.name;
  j["path"] = r.path;
  j["category"] = r.category;
  j["status"] = r.status;
  j["reason"] = r.reason.empty() ? cli::Json() : cli::Json(r.reason);
  j["vertices"] = r.vertices;
  j["faces"] = r.faces;
  j["sources"] = r.sources;
  j["exact_references"] = r.exact_references;
  j["notes"] = cli::Json::array_of(r.notes);
  cli::Json& methods = j["methods"] = cli::Json::array();
  for (const CorpusMethod& m : r.methods) {
    cli::Json mj;
    mj["method"] = m.name;
    mj["status"] = m.skipped.empty() ? "ok" : "skipped";
    mj["reason"] = m.skipped.empty() ? cli::Json() : cli::Json(m.skipped);
    mj["mre"] = number_or_null(m.mre);
    mj["max_re"] = number_or_null(m.max_re);
    mj["signed_re"] = number_or_null(m.signed_re);
    mj["query_s"] = number_or_null(m.query_s);
    mj["bounds"] = m.has_bounds ? bounds_json(m.bounds) : cli::Json();
    methods.push_back(std::move(mj));
  }
  j["gsp_steps_per_face"] = number_or_null(r.steps_per_face);
  j["gsp_beats_dijkstra"] = tri_state(gsp_beats(r, "dijkstra"));
  j["gsp_beats_heat"] = tri_state(gsp_beats(r, "heat"));
  j["gsp_violates_bounds"] = gsp_violates(r);
  return j;
}

cli::Json aggregate_json(const CategoryAggregate& a) {
  cli::Json j;
  j["category"] = a.category;
  j["meshes_run"] = a.run;
  j["failed"] = a.failed;
  j["with_exact"] = a.with_exact;
  j["gsp_worse_than_dijkstra"] = a.gsp_worse_than_dijkstra;
  j["gsp_worse_than_heat"] = a.gsp_worse_than_heat;
  j["sources_gsp_worse_than_dijkstra"] = a.sources_worse_than_dijkstra;
  j["sources_gsp_worse_than_heat"] = a.sources_worse_than_heat;
  j["sources_compared_with_dijkstra"] = a.sources_vs_dijkstra;
  j["sources_compared_with_heat"] = a.sources_vs_heat;
  j["violating_bounds"] = a.violating_bounds;
  cli::Json& figures = j["figures"];
  for (const auto& [name, s] : a.figures) {
    cli::Json f;
    f["n"] = s.n;
    f["mean"] = number_or_null(s.mean);
    f["median"] = number_or_null(s.median);
    f["p95"] = number_or_null(s.p95);
    f["worst"] = number_or_null(s.worst);
    figures[name] = std::move(f);
  }
  return j;
}

}  // namespace

cli::Json corpus_json(const CorpusReport& report) {
  cli::Json doc;
  cli::Json& rows = doc["meshes"] = cli::Json::array();
  for (const CorpusRow& r : report.rows) rows.push_back(row_json(r));
  doc["point_clouds_skipped"] = cli::Json::array_of(report.point_clouds);
  cli::Json& agg = doc["aggregate"] = cli::Json::array();
  for (const CategoryAggregate& a : aggregate(report.rows)) agg.push_back(aggregate_json(a));
  return doc;
}

std::string corpus_csv(const CorpusReport& report) {
  std::string out = "mesh,category,status,reason,vertices,faces,sources,exact_references";
  for (const std::string& m : report.methods) out += "," + m + "_status," + m + "_reason," + m + "_mre," + m +
                                                     "_max_re," + m + "_query_s";
  out += ",gsp_below_line,gsp_below_line_count,gsp_above_edge,gsp_above_edge_count,gsp_edge_unreached,gsp_nan,"
         "gsp_steps_per_face,gsp_beats_dijkstra,gsp_beats_heat,gsp_violates_bounds\n";
  for (const CorpusRow& r : report.rows) {
    out += field(r.name) + "," + r.category + "," + r.status + "," + field(r.reason) + "," +
           std::to_string(r.vertices) + "," + std::to_string(r.faces) + "," + std::to_string(r.sources) + "," +
           std::to_string(r.exact_references);
    for (const std::string& name : report.methods) {
      const CorpusMethod* m = any_method(r, name);
      if (!m) {
        out += ",,,,,";
        continue;
      }
      out += std::string(",") + (m->skipped.empty() ? "ok" : "skipped") + "," + field(m->skipped) + "," +
             field(m->mre) + "," + field(m->max_re) + "," + field(m->query_s);
    }
    const CorpusMethod* g = r.method("gsp");
    if (g && g->has_bounds) {
      const BoundStats& b = g->bounds;
      out += "," + field(b.below_line) + "," + std::to_string(b.below_count) + "," + field(b.above_edge) + "," +
             std::to_string(b.above_count) + "," + std::to_string(b.unreached) + "," + std::to_string(b.nan);
    } else {
      out += ",,,,,,";
    }
    out += "," + field(r.steps_per_face) + "," + tri_field(gsp_beats(r, "dijkstra")) + "," +
           tri_field(gsp_beats(r, "heat")) + "," + (gsp_violates(r) ? "1" : "0") + "\n";
  }
  return out;
}

std::string corpus_table(const CorpusReport& report) {
  std::string out;
  char line[512];
  std::snprintf(line, sizeof line, "%-34s %-7s %8s %8s", "mesh", "class", "verts", "faces");
  out += line;
  for (const std::string& m : report.methods) {
    std::snprintf(line, sizeof line, " %12s %10s", (m + " MRE%").c_str(), (m + " ms").c_str());
    out += line;
  }
  out += "  gsp:maxRE%   <line%   >edge%   bad  steps/f\n";
  for (const CorpusRow& r : report.rows) {
    std::snprintf(line, sizeof line, "%-34s %-7s %8zu %8zu", r.name.c_str(), r.category.c_str(), r.vertices,
                  r.faces);
    out += line;
    if (!r.ok()) {
      out += "  FAILED: " + r.reason + "\n";
      continue;
    }
    for (const std::string& name : report.methods) {
      const CorpusMethod* m = r.method(name);
      out += " " + cell(m ? 100 * m->mre : NAN, 12, "%.4f") + " " + cell(m ? 1e3 * m->query_s : NAN, 10, "%.3f");
    }
    const CorpusMethod* g = r.method("gsp");
    const bool b = g && g->has_bounds;
    const double bad = b ? double(g->bounds.below_count + g->bounds.above_count + g->bounds.nan) : NAN;
    out += " " + cell(g ? 100 * g->max_re : NAN, 11, "%.3f") + " " + cell(b ? 100 * g->bounds.below_line : NAN, 8, "%.4f") +
           " " + cell(b ? 100 * g->bounds.above_edge : NAN, 8, "%.4f") + " " + cell(bad, 5, "%.0f") + " " +
           cell(r.steps_per_face, 8, "%.3f") + "\n";
    for (const CorpusMethod& m : r.methods)
      if (!m.skipped.empty()) out += "    " + m.name + " skipped: " + m.skipped + "\n";
  }
  out += "\nper category (over the meshes that ran; worst = largest)\n";
  for (const CategoryAggregate& a : aggregate(report.rows)) {
    std::snprintf(line, sizeof line,
                  "%s: %zu run, %zu failed, %zu with exact; GSP less accurate than dijkstra on %zu, than heat on "
                  "%zu; GSP breaks a bound by > 1%% on %zu\n",
                  a.category.c_str(), a.run, a.failed, a.with_exact, a.gsp_worse_than_dijkstra,
                  a.gsp_worse_than_heat, a.violating_bounds);
    out += line;
    std::snprintf(line, sizeof line, "  per source: GSP less accurate than dijkstra on %zu of %zu, than heat on %zu of %zu\n",
                  a.sources_worse_than_dijkstra, a.sources_vs_dijkstra, a.sources_worse_than_heat, a.sources_vs_heat);
    out += line;
    std::snprintf(line, sizeof line, "  %-20s %5s %12s %12s %12s %12s\n", "figure", "n", "mean", "median", "p95",
                  "worst");
    out += line;
    for (const auto& [name, s] : a.figures) {
      // Relative figures in %, the query time in ms, steps per face as they are.
      const bool time = name == "gsp_query_s", steps = name == "gsp_steps_per_face";
      const double k = time ? 1e3 : steps ? 1 : 100;
      const std::string label = name + (time ? " (ms)" : steps ? "" : " (%)");
      std::snprintf(line, sizeof line, "  %-20s %5zu", label.c_str(), s.n);
      out += line;
      for (double v : {s.mean, s.median, s.p95, s.worst}) out += " " + cell(k * v, 12, "%.4g");
      out += "\n";
    }
  }
  return out;
}

}  // namespace gsp::bench
