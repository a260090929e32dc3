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
// gsp-geodesic --method windows and gsp-bench's `gsp-windows` / `gsp-windows3` run it.
#include <gsp/mesh.hpp>

#include <cstddef>
#include <memory>
#include <vector>

namespace gsp {

struct WindowOptions {
  unsigned windows = 2;   // per face, 1 to 8
};

struct WindowStats {
  std::size_t window_updates = 0;   // windows a face took (new or merged)
  std::size_t faces_reached = 0;
  std::size_t relaxed = 0;          // vertex values lowered along the input's edges afterwards
};

class WindowGeodesics {
 public:
  // Prepares the faces (by default the intrinsic Delaunay flip of the input's, as GSP's solver
  // does), their planar frames and the edge rings (non-manifold edges: every other face of the
  // edge is a neighbour, as in GSP). The mesh must outlive the object.
  explicit WindowGeodesics(const TriangleMesh& mesh, bool intrinsic_delaunay = true);
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

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace gsp
