#pragma once
// Tracing geodesic paths back through a GSP field's per-face virtual sources.
//
// Every reached face of a field computed with want_face_sources carries a virtual source S
// (a 3D point in the face's plane) and sigma: the geodesic to any point of the face runs
// straight (in the face's plane) to S, then sigma further. So a path is walked backwards: from
// the end point straight towards the current face's S, across the exit edge into the
// neighbour, on towards that face's S, ...; when the walk reaches S and S is a mesh vertex with
// sigma > 0, the path turns there (a corner of the geodesic) and continues in the incident face
// whose source explains the vertex's distance best; it ends at the real source.
//
//   gsp::GeodesicOptions o;
//   o.want_face_sources = true;
//   auto field = solver.compute({gsp::Source::at_vertex(s)}, o);
//   gsp::pathfinding::PathTracer tracer(mesh);
//   auto path = tracer.trace(field, gsp::pathfinding::Endpoint::at_vertex(t));
#include <gsp/connectivity.hpp>
#include <gsp/geodesics.hpp>
#include <gsp/pathfinding/path.hpp>
#include <gsp/window_geodesics.hpp>

#include <cstddef>
#include <memory>
#include <mutex>
#include <vector>

namespace gsp::pathfinding {

namespace detail {
class SourceField;
}

struct TraceOptions {
  // Walk steps (face crossings and turns) before giving up; 0: 2 * faces + 64. Guards against
  // cycles in an inconsistent field; a walk that gives up falls back to the route down the
  // field's vertex distances.
  std::size_t max_steps = 0;
  // Pull the walk taut (sleeve + funnel) and compare it with the descent route. Off: the raw
  // walk, straight segments towards the per-face virtual sources, as the field explains the
  // end point's distance (for measuring the field against its own paths; docs/pathfinding.md);
  // where the walk cannot be completed, trace() throws instead of falling back to the descent.
  bool shorten = true;
};

class PathTracer {
 public:
  // Builds the connectivity once. Keeps a reference to `mesh`: it must outlive the tracer.
  explicit PathTracer(const TriangleMesh& mesh, const TraceOptions& options = {});

  // The path from the field's nearest source to `end`. Throws InvalidInput when the field has
  // no face sources or `end` is malformed, NoPath when `end` is not reached, gsp::Error when
  // neither the walk (a cycle, max_steps exceeded, a walk off the boundary) nor the descent
  // route can be completed.
  GeodesicPath trace(const GeodesicResult& field, const Endpoint& end) const;
  // The same through a window field (gsp/window_geodesics.hpp) computed on this mesh's own
  // faces (windows(), or a WindowGeodesics built with intrinsic_delaunay = false): at each
  // point the walk follows the window that explains it, so it keeps to the corridor of that
  // point's geodesic where GSP's one source per face may have taken another's.
  GeodesicPath trace(const WindowField& field, const Endpoint& end) const;

  // The window propagation on this mesh's faces, built on first use (thread-safe).
  const WindowGeodesics& windows() const;

  // One field, many end points (one source to many targets). An end point the field does not
  // reach gives an empty path (found() false) instead of NoPath.
  std::vector<GeodesicPath> trace_all(const GeodesicResult& field, const std::vector<Endpoint>& ends) const;

  const TriangleMesh& mesh() const { return mesh_; }
  const Connectivity& connectivity() const { return conn_; }

 private:
  GeodesicPath trace_in(const detail::SourceField& field, const Endpoint& end) const;

  const TriangleMesh& mesh_;
  Connectivity conn_;
  TraceOptions options_;
  double mean_edge_ = 1;
  // Built on first use; behind a pointer so that the tracer stays movable.
  struct LazyWindows {
    std::once_flag once;
    std::unique_ptr<WindowGeodesics> windows;
  };
  std::shared_ptr<LazyWindows> windows_ = std::make_shared<LazyWindows>();
};

}  // namespace gsp::pathfinding
