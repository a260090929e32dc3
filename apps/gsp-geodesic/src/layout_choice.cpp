#include "layout_choice.hpp"

#include <algorithm>
#include <cmath>

namespace gsp::geodesic_app {

namespace {

// The mean of log2(1 + |i - j|) over the edges of 64 runs of consecutive faces spread over
// the file (at most ~200,000 faces in all; every face when there are fewer):
// gsp::mean_log_neighbour_index_distance estimated from the triangles alone, read in order
// (the exact measure gathers the edges, which on a scattered 1M-vertex file cost 10% of the
// run it was to save). Runs, not a stride: a stride can alias with the order's own period
// (the 4 children of a subdivided face).
double sampled_log_gap(const TriangleMesh& mesh) {
  const std::size_t nf = mesh.num_faces(), runs = 64, run = std::max<std::size_t>(1, 200000 / runs);
  double sum = 0;
  std::size_t n = 0;
  auto add = [&](std::size_t f) {
    for (int k = 0; k < 3; ++k) {
      const Index a = mesh.triangles[f][k], b = mesh.triangles[f][(k + 1) % 3];
      sum += std::log2(1.0 + double(a > b ? a - b : b - a));
      ++n;
    }
  };
  if (nf <= runs * run) {
    for (std::size_t f = 0; f < nf; ++f) add(f);
  } else {
    for (std::size_t r = 0; r < runs; ++r)
      for (std::size_t f = r * (nf / runs), end = f + run; f < end; ++f) add(f);
  }
  return n ? sum / double(n) : 0.0;
}

}  // namespace

LayoutChoice choose_layout(const std::string& mode, const TriangleMesh& mesh, bool one_field) {
  LayoutChoice c;
  if (mode == "on") return c.reason = "--layout on", c;
  if (mode == "off") return c.optimize = false, c.reason = "--layout off", c;
  if (!one_field) return c.reason = "several fields: the layout pays back", c;
  c.file_gap = sampled_log_gap(mesh);
  c.random_gap = std::log2(double(std::max<std::size_t>(mesh.num_vertices(), 4))) - 2;
  c.optimize = c.random_gap - c.file_gap < kCoherentGap;
  c.reason = c.optimize ? "one field, the file's order is scattered" : "one field, the file's order is coherent";
  return c;
}

}  // namespace gsp::geodesic_app
