#include "corpus.hpp"

#include "report.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>

namespace gsp::bench {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// A reason on one line: the table and the CSV keep one mesh per line.
std::string one_line(std::string s) {
  for (char& c : s)
    if (c == '\n' || c == '\r') c = ' ';
  return s;
}
}  // namespace

const CorpusMethod* CorpusRow::method(const std::string& wanted) const {
  for (const CorpusMethod& m : methods)
    if (m.name == wanted && m.skipped.empty()) return &m;
  return nullptr;
}

double CorpusRow::mre(const std::string& method_name) const {
  const CorpusMethod* m = method(method_name);
  return m ? m->mre : kNaN;
}

CorpusRow corpus_row(const MeshRun& run, const std::string& category) {
  CorpusRow row;
  row.name = run.mesh->name;
  row.path = run.mesh->path;
  row.category = category;
  row.vertices = run.mesh->mesh.num_vertices();
  row.faces = run.mesh->mesh.num_faces();
  row.sources = run.sources.size();
  row.exact_references = run.exact_references;
  row.notes = run.notes;
  row.steps_per_face = kNaN;
  for (const MethodRun& m : run.methods) {
    const Summary s = summarise(run, m);
    CorpusMethod c;
    c.name = m.method.name;
    c.skipped = one_line(m.skipped);
    c.mre = s.mre, c.max_re = s.max_re, c.signed_re = s.signed_re, c.query_s = s.query_s;
    c.bounds = s.bounds, c.has_bounds = s.bound_sources > 0;
    for (const SourceRun& sr : m.sources) c.source_mre.push_back(sr.has_errors ? sr.errors.mre : kNaN);
    if (m.method.id == Method::gsp) row.steps_per_face = s.update_steps_per_triangle;
    row.methods.push_back(std::move(c));
  }
  return row;
}

CorpusRow failed_row(const std::string& path, const std::string& category, const std::string& reason) {
  CorpusRow row;
  row.name = std::filesystem::path(path).filename().string();
  row.path = path;
  row.category = category;
  row.status = "failed";
  row.reason = one_line(reason);
  row.steps_per_face = kNaN;
  return row;
}

int gsp_beats(const CorpusRow& row, const std::string& other) {
  const double g = row.mre("gsp"), o = row.mre(other);
  if (!std::isfinite(g) || !std::isfinite(o)) return -1;
  return g < o ? 1 : 0;
}

bool gsp_worse(const CorpusRow& row, const std::string& other) {
  const double g = row.mre("gsp"), o = row.mre(other);
  return std::isfinite(g) && std::isfinite(o) && g > o + kMreTie;
}

namespace {
// Calls visit(gsp_mre, other_mre) for each source both measured against exact.
template <class Visit>
void per_source(const CorpusRow& row, const std::string& other, Visit&& visit) {
  const CorpusMethod *g = row.method("gsp"), *o = row.method(other);
  if (!g || !o) return;
  for (std::size_t k = 0; k < std::min(g->source_mre.size(), o->source_mre.size()); ++k)
    if (std::isfinite(g->source_mre[k]) && std::isfinite(o->source_mre[k])) visit(g->source_mre[k], o->source_mre[k]);
}
}  // namespace

std::size_t gsp_worse_sources(const CorpusRow& row, const std::string& other) {
  std::size_t n = 0;
  per_source(row, other, [&](double g, double o) { n += g > o + kMreTie; });
  return n;
}

std::size_t compared_sources(const CorpusRow& row, const std::string& other) {
  std::size_t n = 0;
  per_source(row, other, [&](double, double) { ++n; });
  return n;
}

bool gsp_violates(const CorpusRow& row) {
  const CorpusMethod* g = row.method("gsp");
  return g && g->has_bounds && violates(g->bounds);
}

}  // namespace gsp::bench
