#include <gsp/pathfinding/path_tracer.hpp>

#include <gsp/intrinsic/edge_lengths.hpp>

#include "descent_faces.hpp"
#include "source_field.hpp"
#include "walk.hpp"

namespace gsp::pathfinding {

// The walk's tolerances are in the core's unit, the mean edge length over the faces that
// take part (faces repeating a vertex are left out, as in the field being traced).
PathTracer::PathTracer(const TriangleMesh& mesh, const TraceOptions& options)
    : mesh_(mesh),
      conn_(build_connectivity(mesh)),
      options_(options),
      mean_edge_(intrinsic::mean_edge_length(intrinsic::halfedge_lengths(mesh), intrinsic::skipped_faces(mesh))) {}

GeodesicPath PathTracer::trace(const GeodesicResult& field, const Endpoint& end) const {
  if (field.face_sources.size() != mesh_.num_faces())
    throw InvalidInput("path tracing needs a field computed with want_face_sources on this mesh");
  return trace_in(detail::GspSourceField(field), end);
}

GeodesicPath PathTracer::trace(const WindowField& field, const Endpoint& end) const {
  if (field.vertex_distance.size() != mesh_.num_vertices())
    throw InvalidInput("path tracing needs a window field computed on this mesh");
  return trace_in(detail::WindowSourceField(field), end);
}

const WindowGeodesics& PathTracer::windows() const {
  LazyWindows& lazy = *windows_;
  std::call_once(lazy.once, [&] { lazy.windows = std::make_unique<WindowGeodesics>(mesh_, conn_, false); });
  return *lazy.windows;
}

GeodesicPath PathTracer::trace_in(const detail::SourceField& field, const Endpoint& end) const {
  check_endpoint(mesh_, end);
  const std::size_t max_steps = options_.max_steps ? options_.max_steps : 2 * mesh_.num_faces() + 64;
  try {
    return detail::Walk(mesh_, conn_, field, mean_edge_, max_steps, options_.shorten).run(end);
  } catch (const NoPath&) {
    throw;
  } catch (const Error&) {
    // The walk could not be completed (a cycle in an inconsistent field, a step off the
    // boundary): the route down the field's vertex distances, pulled taut, is the path.
    PathPoint last;
    last.position = end.position(mesh_);
    if (end.is_vertex()) {
      const Index c = conn_.vertex_corners[conn_.vertex_corner_begin[end.element]];
      last.point = SurfacePoint::in_face(face_of(c), detail::corner_bary(corner_of(c)));
    } else {
      last.point = end;
    }
    GeodesicPath path;
    if (!options_.shorten || !detail::descent_path(mesh_, conn_, field, last, path)) throw;
    path.field_distance =
        end.is_vertex() ? field.vertex_distance()[end.element] : field.distance_at(mesh_, end.element, end.barycentric);
    return path;
  }
}

std::vector<GeodesicPath> PathTracer::trace_all(const GeodesicResult& field, const std::vector<Endpoint>& ends) const {
  std::vector<GeodesicPath> paths;
  paths.reserve(ends.size());
  for (const Endpoint& e : ends) {
    try {
      paths.push_back(trace(field, e));
    } catch (const NoPath&) {
      paths.emplace_back();
    }
  }
  return paths;
}

}  // namespace gsp::pathfinding
