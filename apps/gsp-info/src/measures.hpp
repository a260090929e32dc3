#pragma once
// The geometric measures gsp-info reports: bounding box, edge lengths, triangle shape.
// Definitions follow data/meshes/SOURCES.md so the figures can be compared with it.
#include <gsp/connectivity.hpp>
#include <gsp/mesh.hpp>

#include <vector>

namespace gsp::info {

// Order statistics of a sample; percentiles interpolate linearly between the closest ranks
// (NumPy's default), so they match figures computed with np.percentile.
struct Summary {
  std::size_t count = 0;
  double min = 0, max = 0, mean = 0, stddev = 0, median = 0, p99 = 0;
};
Summary summarize(std::vector<double> values);


struct ShapeMeasures {
  std::size_t degenerate_faces = 0;     // repeated index or zero area: excluded below
  // Mean over non-degenerate triangles of longest / shortest edge (the paper's anisotropy).
  double anisotropy = 0;
  // AR = l_max * perimeter / (4 sqrt(3) area) over non-degenerate triangles; 1 = equilateral.
  Summary aspect_ratio;
  double aspect_ratio_above_10 = 0;     // fraction of non-degenerate triangles with AR > 10
};
ShapeMeasures shape_measures(const TriangleMesh& mesh);

// Lengths of the undirected edges of the connectivity (each edge once).
Summary edge_lengths(const TriangleMesh& mesh, const Connectivity& conn);

// Largest number of triangle corners at one vertex (a vertex's valence in triangles).
std::size_t max_valence(const Connectivity& conn);

}  // namespace gsp::info
