#pragma once
// How gsp-bench writes a number or a text into its reports, shared by the per-method reports
// (report.cpp, table.cpp) and the corpus reports (corpus_report.cpp) so they read the same.
#include <gsp/cli/json.hpp>

#include <cmath>
#include <cstdio>
#include <string>

namespace gsp::bench {

// JSON: a figure that does not apply (NaN, no timing) is null.
inline cli::Json number_or_null(double d) { return std::isfinite(d) ? cli::Json(d) : cli::Json(); }

// CSV field: numbers with enough digits to read back, empty when they do not apply; text
// quoted when it has to be (RFC 4180).
inline std::string field(double d) {
  if (!std::isfinite(d)) return "";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", d);
  return buf;
}
inline std::string field(const std::string& s) {
  if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += (c == '"') ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

// Table cell: a number right-aligned in `width`, "-" when it does not apply.
inline std::string cell(double v, int width, const char* format) {
  char num[48], buf[64];
  if (std::isfinite(v)) std::snprintf(num, sizeof num, format, v);
  else std::snprintf(num, sizeof num, "-");
  std::snprintf(buf, sizeof buf, "%*s", width, num);
  return buf;
}

}  // namespace gsp::bench
