#pragma once
// A second route for a traced path: down the field's vertex distances along mesh edges. Each
// step goes to the neighbour with the smallest d[w] + |uw| among those with d[w] < d[u], so it
// follows the field without reading the virtual sources; the sleeve shortening (sleeve.hpp)
// pulls it taut. Where the walk through the virtual sources strays into a longer corridor
// (an inconsistent source near a saddle), this route usually does not, and the tracer keeps
// the shorter of the two taut paths; where the walk fails outright (a cycle in an inconsistent
// field, a step off the boundary) it is the path.
#include <gsp/connectivity.hpp>
#include <gsp/geodesics.hpp>
#include <gsp/pathfinding/path.hpp>

#include "source_field.hpp"

#include <vector>

namespace gsp::pathfinding::detail {

// The faces from `start` (the source end) to `end`, in order, consecutive ones sharing at least
// a vertex; empty when the descent gets stuck (a vertex with no lower neighbour that is not on
// the start's face) or `distance` does not cover the mesh.
std::vector<Index> descent_faces(const TriangleMesh& mesh, const Connectivity& conn, const std::vector<double>& distance,
                                 const PathPoint& start, const PathPoint& end);

// The whole path by descent alone: down to the vertex where the field bottoms out, where the
// source is found (a face whose virtual source lies in it with sigma about 0, else the vertex
// itself), then pulled taut; where no sleeve can be formed, the edge route as it is. False
// when the descent fails.
bool descent_path(const TriangleMesh& mesh, const Connectivity& conn, const SourceField& field,
                  const PathPoint& end, GeodesicPath& out);

}  // namespace gsp::pathfinding::detail
