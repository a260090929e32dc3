#pragma once
// Experimental (issue 18): geodesic distances with a few *windows* per face instead of GSP's
// one virtual source. A window is a virtual source S with its sigma, the two rays from S through
// the vertices that bound what S sees through the faces it crossed, and beyond each ray a
// shadow wedge at the ray's vertex W (bounded by the ray's continuation and a ray W -> U) in
// which a point takes the path bent at W. A point beyond a ray and outside its shadow wedge
// gets nothing from that window. Every value a window gives is meant to be the length of a path
// on the surface, so never below the exact geodesic distance (measured: none on camelhead and
// fertility, at most 0.07% below at single vertices of CAD plates and pizza); a face
// keeps the K windows that together give it the lowest values at seven sample points (corners,
// centroid, edge midpoints). Windows of one source that touch are merged (exact on a plane).
// Afterwards the values are relaxed along the input's edges (as GSP's vertex relaxation), so no
// vertex ends farther than its shortest edge path.
//
// Measured against GSP and CGAL's exact method in docs/benchmarks.md ("Windows per face");
// single-threaded, double precision, priority-queue order. Not used by GSP's solver:
// gsp-geodesic --method windows and gsp-bench's `gsp-windows` / `gsp-windows3` run it, and
// paths (gsp::pathfinding, PathMethod::windows, the default) walk back through a WindowField.
#include <gsp/connectivity.hpp>
#include <gsp/geodesics.hpp>
#include <gsp/mesh.hpp>

#include <cstddef>
#include <memory>
#include <vector>

namespace gsp {

struct WindowOptions {
  unsigned windows = 2;   // per face, 1 to 8
  // Where a ray's vertex W hides part of the next edge, that part also gets a window of its own
  // from W, which can bend again further on (round a chain of reflex corners along a boundary,
  // as on a partial gear: 2.0 -> 0.02% MRE); otherwise only the shadow wedge the window carries
  // reaches it, and it ends at the next corner. On the corpus with 3 windows: benign worst
  // 0.047 -> 0.039%, malign worst 1.54 -> 0.70% (docs/benchmarks.md, session 15).
  bool shadow_sources = true;
  // A new window is also judged at a point it sees (the middle of what it sees of its entry
  // edge), not only at the face's seven sample points: on a sliver the part a window reaches
  // may hold no sample. With the above: benign worst 0.034%, malign 0.33%; 1.3x the time.
  bool own_points = true;
  // Stop once these vertices are settled: the queue's least key is past the largest of their
  // values by two mean edge lengths (a face's key is its least value at seven sample points,
  // so a face can hold a value up to about an edge below its key). Up to 16 targets the order
  // is A*'s (the key plus a straight-line lower bound to the nearest target), so the
  // propagation stays near the corridors that lead to them. Empty: the whole mesh.
  // Paths to a few end points need no more (gsp::pathfinding, method windows).
  std::vector<Index> targets;
};

struct WindowStats {
  std::size_t window_updates = 0;   // windows a face took (new or merged)
  std::size_t faces_reached = 0;
  std::size_t relaxed = 0;          // vertex values lowered along the input's edges afterwards
};

class WindowGeodesics;

// A computed field: the vertex distances and every face's windows, for walking a geodesic back
// from any point of the surface (gsp::pathfinding traces paths through it). Holds a reference
// to the WindowGeodesics that made it, which must outlive it.
class WindowField {
 public:
  std::vector<double> vertex_distance;   // +inf where unreached
  std::vector<Index> vertex_source;      // index into the sources of the nearest; kInvalidIndex unreached

  bool reached(Index face) const;
  // Where the geodesic into point x (3D, projected into the face's plane) of `face` comes from
  // in a straight line: `position` is the window's source S (a 3D point in the face's plane,
  // usually outside it) or, when the geodesic bends at a vertex W on the way (x in a window's
  // shadow wedge), W unfolded into the plane; `sigma` is the distance left there. Of the face's
  // windows the one giving x the least value. Unreached faces: sigma +inf, source kInvalidIndex.
  // Throws InvalidInput when the field was computed on the intrinsic Delaunay faces (they are
  // not the input's faces; build the WindowGeodesics with intrinsic_delaunay = false).
  VirtualSource source_at(Index face, Vec3 x) const;
  // The field's value at a point of an input face (least over its windows; the same error).
  double distance_at(Index face, const std::array<double, 3>& barycentric) const;

  WindowField();
  ~WindowField();
  WindowField(WindowField&&) noexcept;
  WindowField& operator=(WindowField&&) noexcept;

 private:
  friend class WindowGeodesics;
  struct Data;
  std::unique_ptr<Data> data_;
};

class WindowGeodesics {
 public:
  // Prepares the faces (by default the intrinsic Delaunay flip of the input's, as GSP's solver
  // does), their planar frames and the edge rings (non-manifold edges: every other face of the
  // edge is a neighbour, as in GSP). The mesh must outlive the object.
  explicit WindowGeodesics(const TriangleMesh& mesh, bool intrinsic_delaunay = true);
  // The same from the mesh's connectivity when the caller has built it already (a path
  // tracer has).
  WindowGeodesics(const TriangleMesh& mesh, const Connectivity& conn, bool intrinsic_delaunay);
  ~WindowGeodesics();
  WindowGeodesics(WindowGeodesics&&) noexcept;
  WindowGeodesics& operator=(WindowGeodesics&&) noexcept;

  // Distances from one source vertex (+inf where unreached). Throws std::invalid_argument for
  // a vertex out of range or a window count outside 1..8.
  std::vector<double> distances_from_vertex(Index source, const WindowOptions& options = {},
                                            WindowStats* stats = nullptr) const;

  // Distances from the nearest of several source vertices, and (label, when given) the index
  // in `sources` of that nearest one (kInvalidIndex where unreached). The same errors, and for
  // an empty list.
  std::vector<double> distances(const std::vector<Index>& sources, const WindowOptions& options = {},
                                WindowStats* stats = nullptr, std::vector<Index>* label = nullptr) const;

  // The field from the nearest of several sources, vertices or points in faces (a face point
  // on the propagation's faces: the input's when built with intrinsic_delaunay = false; on the
  // intrinsic faces only vertex sources are accepted). Offsets are not supported. Throws
  // std::invalid_argument as above, for a malformed source and a source offset.
  WindowField field(const std::vector<Source>& sources, const WindowOptions& options = {},
                    WindowStats* stats = nullptr) const;

  // The faces are the input's (built with intrinsic_delaunay = false).
  bool on_input_faces() const;

  struct Impl;   // window_geodesics_impl.hpp

 private:
  std::unique_ptr<Impl> impl_;
};

}  // namespace gsp
