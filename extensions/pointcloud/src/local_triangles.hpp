#pragma once
// Triangles from a point cloud's neighbourhoods: each point's neighbours projected into its
// tangent plane, the 2D Delaunay triangles incident to the point kept (its local one-ring, as
// in Sharp & Crane's tufted point-cloud Laplacian), and the union over all points, each
// triangle once with the number of its corners whose one-ring holds it (its votes).
// consistent_triangles() then picks the soup the mesh core propagates on. docs/pointcloud.md
// ("Local triangles") says why and what was measured.
#include <gsp/types.hpp>

#include "tangent_frames.hpp"

#include <cstdint>
#include <vector>

namespace gsp::pointcloud::detail {

struct LocalTriangles {
  std::vector<Triangle> triangles;   // sorted corner indices, each triangle once
  std::vector<std::uint8_t> votes;   // 1..3: how many of its corners' one-rings hold it
};

// neighbours: CSR (begin has points.size() + 1 entries) of each point's candidate neighbours.
// A neighbour q of p is left out where |n . (q - p)| > steep_slope |q - p| at p or at q.
LocalTriangles local_triangles(const std::vector<Vec3>& points, const TangentFrames& frames,
                               const std::vector<Index>& begin, const std::vector<Index>& neighbours,
                               double steep_slope);

// The triangles at least two corners agree on, plus those only one corner has that close an
// edge the agreed ones leave open (where neighbouring one-rings disagree, e.g. on the diagonal
// of four co-circular points, neither holds two votes and the agreed set has a hole there).
std::vector<Triangle> consistent_triangles(const LocalTriangles& local);

}  // namespace gsp::pointcloud::detail
