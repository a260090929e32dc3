#pragma once
// The post-pass on a remesh (remesh.hpp, RemeshOptions): the angle-raising flips, then the
// boundary snaps, collapses and splits, the vertex moves along the surface with their flips and
// pulls, and the insertions at input points far from the remesh. Run on the CVT's dual
// (restricted_delaunay) and on a component's remesh by edge operations (component_remesh.cpp).
#include <gsp/cvt/closest_point_index.hpp>
#include <gsp/cvt/remesh.hpp>
#include <gsp/mesh.hpp>

#include <cstddef>
#include <vector>

namespace gsp::cvt::detail {

// `surface`: what the remesh lies on (its vertices are the input points of the insertions);
// `diagonal`: the length the options' distances are fractions of; `sites`: what the insertions'
// cap is a fraction of. `vertex_site` follows the vertices (new ones kInvalidIndex; entries of
// vertices the boundary collapses dropped go). `locked` (per vertex, or null): vertices no
// flip, move or split touches. Counts go to `stats`. `surface_index`: over `surface`, or null
// (built here).
void improve_remesh(TriangleMesh& mesh, std::vector<Index>& vertex_site, const TriangleMesh& surface, double diagonal,
                    std::size_t sites, const RemeshOptions& options, const std::vector<bool>* locked, RemeshStats& stats,
                    const ClosestPointIndex* surface_index = nullptr);

}  // namespace gsp::cvt::detail
