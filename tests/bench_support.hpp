#pragma once
// Support for the gsp-bench tests: run the built binary (with a longer time limit than the
// other app tests: exact geodesics take a few tenths of a second per source), read its CSV,
// and find things in its JSON report.
#include "apps_support.hpp"

#include <string>
#include <vector>

namespace gsp::test {

// The sample mesh shipped in the repository (data/samples), so these tests need no shared data.
inline std::string sample_fertility() { return std::string(GSP_TEST_DIR) + "/../data/samples/fertility.off"; }

inline const std::string& bench_bin() {
  static const std::string path = bin("gsp-bench");
  return path;
}

// Runs gsp-bench with `args` (already quoted) under `timeout 120`.
inline RunResult run_bench(const std::string& args, const ScratchDir& scratch) {
  const fs::path out = scratch / ".stdout", err = scratch / ".stderr";
  const std::string line = "timeout 120 " + quote(bench_bin()) + " " + args + " < /dev/null > " +
                           quote(out.string()) + " 2> " + quote(err.string());
  const int status = std::system(line.c_str());
  RunResult r;
  r.exit_code = (status != -1 && WIFEXITED(status)) ? WEXITSTATUS(status) : -1;
  r.out = slurp(out);
  r.err = slurp(err);
  fs::remove(out);
  fs::remove(err);
  return r;
}

// CSV (RFC 4180 quoting) as rows of fields.
inline std::vector<std::vector<std::string>> parse_csv(const std::string& text) {
  std::vector<std::vector<std::string>> rows;
  for (const std::string& line : lines(text)) {
    std::vector<std::string> fields(1);
    bool quoted = false;
    for (std::size_t i = 0; i < line.size(); ++i) {
      const char c = line[i];
      if (quoted) {
        if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') fields.back() += '"', ++i;
        else if (c == '"') quoted = false;
        else fields.back() += c;
      } else if (c == '"') {
        quoted = true;
      } else if (c == ',') {
        fields.emplace_back();
      } else {
        fields.back() += c;
      }
    }
    rows.push_back(fields);
  }
  return rows;
}

// The method entry `name` of mesh entry `mesh` in a gsp-bench JSON report.
inline const JsonValue& bench_method(const JsonValue& mesh, const std::string& name) {
  for (const JsonValue& m : mesh["methods"].items)
    if (m["method"].str == name) return m;
  throw std::runtime_error("no method " + name + " in the report of " + mesh["name"].str);
}

inline const JsonValue& bench_mesh(const JsonValue& report, const std::string& name) {
  for (const JsonValue& m : report["meshes"].items)
    if (m["name"].str == name) return m;
  throw std::runtime_error("no mesh " + name + " in the report");
}

}  // namespace gsp::test
