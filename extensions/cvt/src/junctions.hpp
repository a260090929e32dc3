#pragma once
// The places where three or more Voronoi regions meet and the dual triangles they give
// (see remesh.hpp), shared by the dual and by the region fixes of the Lloyd iterations.
#include <gsp/connectivity.hpp>
#include <gsp/cvt/remesh.hpp>

#include <vector>

namespace gsp::cvt::detail {

struct DualTriangles {
  std::vector<Triangle> triangles;     // site indices, oriented like the faces under them
  std::vector<Index> junction_vertex;  // per triangle: the working vertex it came from
  // Working vertices where the dual goes wrong: a triangle repeating one already made, a
  // region met twice around the vertex, a non-manifold vertex.
  std::vector<Index> trouble_vertices;
  RemeshStats stats;
};

// `sites`: site positions; where more than three regions meet, the polygon is fanned from
// the corner that gives the largest smallest angle.
DualTriangles dual_triangles(const TriangleMesh& m, const Connectivity& conn, const std::vector<Index>& label,
                             const std::vector<Vec3>& sites);

// Working vertices of triangles beyond the second on a dual edge (two regions whose common
// border has more than two ends).
std::vector<Index> overused_edge_vertices(const DualTriangles& d);

}  // namespace gsp::cvt::detail
