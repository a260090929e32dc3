#pragma once
// The working faces of each input face, and which of them holds a point given in the input
// face's barycentric coordinates. A working mesh of few input faces has hundreds of thousands
// of children per input face (one triangle at 5,000 sites: 260,000), so a scan of them per
// point is quadratic; input faces with many children get a grid over their barycentric plane.
#include "working_geometry.hpp"

#include <gsp/cvt/cvt.hpp>

#include <array>
#include <cstddef>
#include <vector>

namespace gsp::cvt::detail {

class ChildFaces {
 public:
  ChildFaces(const WorkingMesh& w, std::size_t input_faces);

  // The point of input face `parent`'s working faces closest to `p` (the point at `bary` of
  // that face): the first child in index order at the least distance, as a scan of them all
  // would find it. The grid only narrows the scan to the children whose barycentric bounding
  // box (padded) holds `bary`; the one holding p is among them.
  SurfaceSite closest(const WorkingGeometry& g, Index parent, const std::array<double, 3>& bary, Vec3 p) const;

 private:
  struct Grid {
    std::size_t cells_begin = 0;   // into cell_begin_
    int n = 0;                     // n x n cells over (b1, b2) in [0, 1]^2; 0: no grid
  };
  std::vector<std::size_t> begin_;   // children_[begin_[p], begin_[p + 1]) are parent p's
  std::vector<Index> children_;
  std::vector<Grid> grids_;
  std::vector<std::size_t> cell_begin_;   // per cell of every grid, + 1: into cell_children_
  std::vector<Index> cell_children_;
};

}  // namespace gsp::cvt::detail
