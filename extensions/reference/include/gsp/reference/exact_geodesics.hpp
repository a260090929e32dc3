#pragma once
// Exact polyhedral geodesic distances (the ground truth GSP is measured against), computed by
// CGAL's Surface_mesh_shortest_path (Xin-Wang's improvement of Chen-Han). Target
// gsp::reference, GPL because of CGAL; nothing of CGAL shows in this header.
//
// The mesh must be a manifold without degenerate faces; anything else is refused with
// gsp::TopologyError before CGAL sees it. Inconsistent face orientation is repaired
// internally, vertices referenced by no face are tolerated (their distance is +infinity,
// or 0 for a source), and distances on components without a source are +infinity.
#include <gsp/mesh.hpp>
#include <gsp/surface_point.hpp>

#include <array>
#include <memory>
#include <vector>

namespace gsp::reference {

// A source: an input vertex, or a point inside an input face given by the barycentric
// weights of the face's corners 0, 1, 2 (non-negative, summing to 1 within 1e-9: the
// reference checks its own, stricter than GSP's gsp::are_barycentric).
using ExactSource = SurfacePoint;

// Checks and converts the mesh once, then answers any number of source sets. Not thread-safe
// (one solver per thread).
class ExactGeodesicSolver {
 public:
  // Throws InvalidInput (bad indices, non-finite positions) or TopologyError (no faces,
  // non-manifold edge or vertex, degenerate face, non-orientable component).
  explicit ExactGeodesicSolver(const TriangleMesh& mesh);
  ~ExactGeodesicSolver();
  ExactGeodesicSolver(ExactGeodesicSolver&&) noexcept;
  ExactGeodesicSolver& operator=(ExactGeodesicSolver&&) noexcept;

  // Builds the shortest-path sequence tree for this source set (the expensive step). Throws
  // InvalidInput for an empty set, an index out of range or invalid barycentric weights.
  void set_sources(const std::vector<ExactSource>& sources);

  // Distances from the current source set, per input vertex (+infinity where unreachable).
  std::vector<double> vertex_distances() const;
  double distance_to_vertex(Index v) const;
  // Distance to a point inside an input face (weights of corners 0, 1, 2); cheap once the
  // sources are set.
  double distance_to_point(Index face, const std::array<double, 3>& barycentric) const;

  // set_sources + vertex_distances.
  std::vector<double> distances(const std::vector<ExactSource>& sources);
  std::vector<double> distances_from_vertex(Index v) { return distances({ExactSource::at_vertex(v)}); }

  std::size_t num_vertices() const;
  std::size_t num_components() const;     // connected components with faces
  std::size_t isolated_vertices() const;  // vertices referenced by no face
  std::size_t flipped_faces() const;      // faces turned to make orientation consistent

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// One-off: per input vertex, the exact distance to the nearest source.
std::vector<double> exact_geodesic_distances(const TriangleMesh& mesh,
                                             const std::vector<ExactSource>& sources);

}  // namespace gsp::reference
