#include "batch_output.hpp"

#include <gsp/io/atomic_file.hpp>

#include <cmath>
#include <cstdio>

namespace gsp::geodesic_app {

std::string numbered_path(const std::string& path, std::size_t index) {
  const std::size_t slash = path.find_last_of('/');
  const std::size_t dot = path.find_last_of('.');
  const bool has_ext = dot != std::string::npos && (slash == std::string::npos || dot > slash);
  const std::string stem = has_ext ? path.substr(0, dot) : path;
  return stem + "-" + std::to_string(index) + (has_ext ? path.substr(dot) : "");
}

void write_matrix(const std::string& path, const std::vector<double>& matrix, std::size_t n) {
  const bool csv = path.size() >= 4 && path.compare(path.size() - 4, 4, ".csv") == 0;
  io::AtomicFile out(path);
  std::string line;
  char number[32];
  for (std::size_t i = 0; i < n; ++i) {
    line.clear();
    for (std::size_t j = 0; j < n; ++j) {
      const double d = matrix[i * n + j];
      if (std::isfinite(d)) std::snprintf(number, sizeof number, "%.9g", d);
      else std::snprintf(number, sizeof number, "inf");
      if (j) line += csv ? ',' : ' ';
      line += number;
    }
    line += '\n';
    out.write(line.data(), line.size());
  }
  out.commit();
}

}  // namespace gsp::geodesic_app
