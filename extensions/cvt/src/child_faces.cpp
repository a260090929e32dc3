#include "child_faces.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace gsp::cvt::detail {

namespace {

// Children up to this many are scanned: a grid pays only where a parent has many.
constexpr std::size_t kScan = 32;
// Padding of a child's barycentric box: a point on a shared edge or a corner, or off it by
// rounding, must find every child that touches it. A child left out is more than this away
// in the parent's barycentric plane; the children holding the point are at distance 0 (up to
// rounding), so the scan's winner is among the candidates.
constexpr double kPad = 1e-9;

int cell_of(double b, int n) {
  const int c = int(std::floor(b * n));
  return std::clamp(c, 0, n - 1);
}

}  // namespace

ChildFaces::ChildFaces(const WorkingMesh& w, std::size_t input_faces) {
  begin_.assign(input_faces + 1, 0);
  for (Index p : w.parent) ++begin_[p + 1];
  for (std::size_t f = 0; f < input_faces; ++f) begin_[f + 1] += begin_[f];
  children_.resize(w.parent.size());
  std::vector<std::size_t> fill(begin_.begin(), begin_.end() - 1);
  for (Index f = 0; f < w.parent.size(); ++f) children_[fill[w.parent[f]]++] = f;

  grids_.resize(input_faces);
  cell_begin_.push_back(0);
  std::vector<std::size_t> counts;
  for (std::size_t p = 0; p < input_faces; ++p) {
    const std::size_t c = begin_[p + 1] - begin_[p];
    if (c <= kScan) continue;
    Grid& grid = grids_[p];
    grid.n = std::max(1, int(std::sqrt(double(c) / 2)));
    grid.cells_begin = cell_begin_.size() - 1;
    const int n = grid.n;
    auto box = [&](Index f, int& x0, int& x1, int& y0, int& y1) {
      double lo1 = 2, hi1 = -1, lo2 = 2, hi2 = -1;
      for (int k = 0; k < 3; ++k) {
        lo1 = std::min(lo1, w.corner_bary[f][k][1]), hi1 = std::max(hi1, w.corner_bary[f][k][1]);
        lo2 = std::min(lo2, w.corner_bary[f][k][2]), hi2 = std::max(hi2, w.corner_bary[f][k][2]);
      }
      x0 = cell_of(lo1 - kPad, n), x1 = cell_of(hi1 + kPad, n);
      y0 = cell_of(lo2 - kPad, n), y1 = cell_of(hi2 + kPad, n);
    };
    // Two passes (count, fill) into one CSR per grid; children stay in index order per cell.
    counts.assign(std::size_t(n) * n, 0);
    for (std::size_t i = begin_[p]; i < begin_[p + 1]; ++i) {
      int x0, x1, y0, y1;
      box(children_[i], x0, x1, y0, y1);
      for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) ++counts[std::size_t(y) * n + x];
    }
    const std::size_t base = cell_children_.size();
    std::size_t total = base;
    for (std::size_t k = 0; k < counts.size(); ++k) {
      const std::size_t size = counts[k];
      counts[k] = total;   // now the fill cursor
      total += size;
      cell_begin_.push_back(total);
    }
    cell_children_.resize(total);
    for (std::size_t i = begin_[p]; i < begin_[p + 1]; ++i) {
      int x0, x1, y0, y1;
      box(children_[i], x0, x1, y0, y1);
      for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) cell_children_[counts[std::size_t(y) * n + x]++] = children_[i];
    }
  }
}

SurfaceSite ChildFaces::closest(const WorkingGeometry& g, Index parent, const std::array<double, 3>& bary,
                                Vec3 p) const {
  SurfaceSite best;
  double best_d = std::numeric_limits<double>::infinity();
  auto consider = [&](Index f) {
    const SurfaceSite q = g.closest_on_face(f, p);
    const double d = distance(q.position, p);
    if (d < best_d) best_d = d, best = q;
  };
  const Grid& grid = grids_[parent];
  if (grid.n == 0) {
    for (std::size_t i = begin_[parent]; i < begin_[parent + 1]; ++i) consider(children_[i]);
    return best;
  }
  const std::size_t cell = grid.cells_begin + std::size_t(cell_of(bary[2], grid.n)) * grid.n + cell_of(bary[1], grid.n);
  for (std::size_t i = cell_begin_[cell]; i < cell_begin_[cell + 1]; ++i) consider(cell_children_[i]);
  return best;
}

}  // namespace gsp::cvt::detail
