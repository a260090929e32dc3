#pragma once
// A metric over a mesh: one tensor for the whole mesh, one per face, or one per vertex; and
// the intrinsic edge lengths it gives, which GeodesicSolver propagates on
// (SolverOptions::edge_lengths).
//
//   auto field = gsp::anisotropic::direction_metric(mesh, {1, 0, 0}, 3.0);
//   auto result = gsp::anisotropic::geodesic_distances(mesh, field, {gsp::Source::at_vertex(0)});
#include <gsp/anisotropic/tensor.hpp>
#include <gsp/geodesics.hpp>
#include <gsp/mesh.hpp>

#include <vector>

namespace gsp::anisotropic {

enum class MetricLocation { constant, per_face, per_vertex };

struct MetricField {
  MetricLocation location = MetricLocation::constant;
  std::vector<SymmetricTensor> tensors;   // 1, one per face, or one per vertex (input order)

  static MetricField constant(const SymmetricTensor& m) { return {MetricLocation::constant, {m}}; }
};

// "constant", "per-face", "per-vertex" (the text format's keywords).
const char* location_name(MetricLocation location);

// Throws InvalidInput when the tensor count does not match the location and the mesh, or a
// tensor is not finite or not positive definite (the message names its index).
void validate(const TriangleMesh& mesh, const MetricField& field);

// The metric of face f: its own tensor, the constant one, or the mean of its three corners'
// tensors (per-vertex fields; a mean of positive definite tensors is positive definite).
SymmetricTensor face_tensor(const TriangleMesh& mesh, const MetricField& field, Index f);

// Per halfedge 3f+i (corner i -> corner i+1): sqrt(e^T M_f e) with M_f the face's tensor,
// computed as sqrt(|e|^2 + e^T (M_f - I) e) so that the identity gives exactly the 3D lengths
// the core computes. Neighbouring faces with different tensors would give a shared edge two
// lengths: it takes the larger, and a face whose longest edge then exceeds the sum of the other
// two gets that sum (docs/anisotropic.md, "Per-face tensors that differ"). Validates first
// (InvalidInput).
std::vector<double> metric_edge_lengths(const TriangleMesh& mesh, const MetricField& field);

// sqrt of the smallest eigenvalue over the field's tensors: no path costs less in the metric
// than this times its 3D length (SolverOptions::edge_lengths_line_scale), so the core's
// straight-line bound holds, scaled. 0 for an empty field.
double line_scale(const MetricField& field);

// Solver options that propagate in the metric: `base` with edge_lengths and
// edge_lengths_line_scale filled.
SolverOptions with_metric(const TriangleMesh& mesh, const MetricField& field, SolverOptions base = {});

// One-off: geodesic distances in the metric (result fields as gsp::geodesic_distances; no
// want_face_sources, no goal_directed: see SolverOptions::edge_lengths).
GeodesicResult geodesic_distances(const TriangleMesh& mesh, const MetricField& field,
                                  const std::vector<Source>& sources, const GeodesicOptions& options = {},
                                  const SolverOptions& solver_options = {});

}  // namespace gsp::anisotropic
