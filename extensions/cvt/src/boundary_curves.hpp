#pragma once
// The boundary loops of a surface as closed polylines parametrised by arc length, for moving
// the dual's boundary vertices along the input's boundary (smoothing, boundary collapses).
#include <gsp/mesh.hpp>

#include <vector>

namespace gsp::cvt::detail {

// Loops run in the direction of their boundary halfedges (the direction the dual's boundary
// edges run too).
struct BoundaryCurves {
  struct Loop {
    std::vector<Vec3> points;   // closed: the segment from points.back() to points.front() too
    std::vector<double> s;      // s[i] = arc length at points[i]; s.back() = total length
    double length = 0;
  };
  std::vector<Loop> loops;

  explicit BoundaryCurves(const TriangleMesh& m);

  double wrap(std::size_t loop, double s) const;   // into [0, length)
  Vec3 at(std::size_t loop, double s) const;
  // Nearest point over all loops (a linear scan): loop, arc length, distance; false if no loop.
  bool project(Vec3 p, std::size_t& loop, double& s, double& d) const;
  // Largest distance of the curve's points between arc lengths s0 and s0 + span (span >= 0)
  // from the chord between the curve's points there.
  double chord_deviation(std::size_t loop, double s0, double span) const;
};

}  // namespace gsp::cvt::detail
