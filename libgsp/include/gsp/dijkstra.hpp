#pragma once
// The baseline: Dijkstra on the edge graph with a binary heap. Distances run along edges only,
// so they over-estimate the geodesic (zig-zag); it is the speed reference of the benchmarks.
#include <gsp/geodesics.hpp>

#include <vector>

namespace gsp {

class DijkstraSolver {
 public:
  explicit DijkstraSolver(const TriangleMesh& mesh);   // builds the weighted adjacency (CSR)
  // Vertex sources start at their offset; a face point seeds its three corners with the
  // straight distances inside the face. `max_distance` stops the search there.
  GeodesicResult compute(const std::vector<Source>& sources,
                         double max_distance = std::numeric_limits<double>::infinity()) const;
  std::size_t num_vertices() const { return begin_.empty() ? 0 : begin_.size() - 1; }

 private:
  TriangleMesh mesh_;
  std::vector<Index> begin_;      // CSR offsets per vertex
  std::vector<Index> neighbour_;
  std::vector<double> length_;
};

GeodesicResult dijkstra_distances(const TriangleMesh& mesh, const std::vector<Source>& sources,
                                  double max_distance = std::numeric_limits<double>::infinity());

}  // namespace gsp
