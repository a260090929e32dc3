#pragma once
// Quality figures of a triangle mesh (angles, aspect ratios, valences) and the two-sided
// Hausdorff distance between two surfaces, for judging a remesh.
#include <gsp/mesh.hpp>

#include <cstdint>
#include <vector>

namespace gsp::cvt {

struct MeshQuality {
  std::size_t vertices = 0, triangles = 0;   // vertices used by a triangle
  double min_angle = 0;          // degrees, over all angles of non-degenerate triangles
  double max_angle = 0;
  double mean_min_angle = 0;     // mean over triangles of the smallest angle
  double below_30 = 0;           // fraction of all angles below 30 degrees
  // Aspect ratio l_max * perimeter / (4 sqrt(3) area): 1 for an equilateral triangle.
  double mean_aspect_ratio = 0;
  double max_aspect_ratio = 0;
  std::size_t degenerate = 0;    // zero-area or repeated-index triangles (left out above)
  std::vector<std::size_t> valence_histogram;   // [k] = vertices with k incident edges
  double mean_edge_length = 0;
};

MeshQuality measure_mesh_quality(const TriangleMesh& mesh);

struct HausdorffOptions {
  std::size_t samples = 200000;   // area-uniform points per surface, plus every vertex
  std::uint64_t seed = 1;
};

struct HausdorffDistance {
  double a_to_b = 0;     // largest distance from a point of a to surface b
  double b_to_a = 0;
  double two_sided = 0;  // max of both
  double mean = 0;       // mean of all sampled distances, both ways
  double diagonal = 0;   // of a's bounding box
  double relative = 0;   // two_sided / diagonal
};

// Sampled two-sided Hausdorff distance (a lower bound of the true one that converges with
// the sample count). Throws InvalidInput when either mesh has no area.
HausdorffDistance hausdorff_distance(const TriangleMesh& a, const TriangleMesh& b,
                                     const HausdorffOptions& options = {});

}  // namespace gsp::cvt
