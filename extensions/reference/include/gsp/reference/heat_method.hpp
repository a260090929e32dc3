#pragma once
// The heat method (Crane, Weischedel, Wardetzky 2013) as implemented by CGAL's Heat_method_3:
// the speed/accuracy peer GSP is compared with. Target gsp::reference (GPL because of CGAL).
//
// The constructor does everything that depends on the mesh only (cotan Laplacian, mass
// matrix, time step, both sparse Cholesky factorisations), solve() what depends on the
// sources (two back-substitutions, gradient, divergence), so a benchmark can time them apart.
// Same mesh requirements as ExactGeodesicSolver (see exact_geodesics.hpp).
#include <gsp/mesh.hpp>

#include <memory>
#include <vector>

namespace gsp::reference {

enum class HeatMethodMode {
  direct,              // on the input triangles (needs well-shaped triangles)
  intrinsic_delaunay,  // on an intrinsic Delaunay retriangulation (robust to slivers)
};

class HeatMethodSolver {
 public:
  // Throws InvalidInput, TopologyError (see ExactGeodesicSolver), or gsp::Error when the
  // factorisation fails.
  explicit HeatMethodSolver(const TriangleMesh& mesh, HeatMethodMode mode = HeatMethodMode::direct);
  ~HeatMethodSolver();
  HeatMethodSolver(HeatMethodSolver&&) noexcept;
  HeatMethodSolver& operator=(HeatMethodSolver&&) noexcept;

  // Per input vertex, the approximate distance to the nearest source vertex; +infinity on
  // components without a source and on unreferenced vertices (0 if one is a source).
  // Throws InvalidInput for an empty set or an index out of range.
  std::vector<double> solve(const std::vector<Index>& source_vertices);

  HeatMethodMode mode() const;
  std::size_t num_vertices() const;
  std::size_t num_components() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// One-off: constructor + solve.
std::vector<double> heat_method_distances(const TriangleMesh& mesh,
                                          const std::vector<Index>& source_vertices,
                                          HeatMethodMode mode = HeatMethodMode::direct);

}  // namespace gsp::reference
