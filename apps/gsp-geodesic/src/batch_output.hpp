#pragma once
// The many-query modes of gsp-geodesic: --separate (a field per source) and --matrix.
#include <gsp/geodesics.hpp>

#include <string>
#include <vector>

namespace gsp::geodesic_app {

// OUT.ext -> OUT-<index>.ext (the index before the extension).
std::string numbered_path(const std::string& path, std::size_t index);

// Writes the n x n matrix (row i: distances from vertex i) as text: separator ' ' for .txt,
// ',' for .csv; "inf" for unreachable pairs. Atomic.
void write_matrix(const std::string& path, const std::vector<double>& matrix, std::size_t n);

}  // namespace gsp::geodesic_app
