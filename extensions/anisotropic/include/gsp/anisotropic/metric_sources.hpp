#pragma once
// Metrics built from geometry or data: a global direction field, principal curvature
// directions, tensors stored as vertex attributes, tensors in a text file.
#include <gsp/anisotropic/metric_field.hpp>
#include <gsp/io/mesh_io.hpp>

#include <istream>
#include <string>

namespace gsp::anisotropic {

// Per face: the direction projected into the face's plane and normalised, d; the tensor
// I + (ratio^2 - 1) d d^T. A unit step along d costs `ratio`, across it 1, so on a plane the
// distance is sqrt((ratio * along)^2 + across^2). Faces whose plane is perpendicular to the
// direction (projection shorter than 1e-9) and zero-area faces get the identity.
// Throws InvalidInput for a zero or non-finite direction or a ratio that is not finite > 0.
MetricField direction_metric(const TriangleMesh& mesh, Vec3 direction, double ratio);

// Per vertex: I + (ratio^2 - 1) k k^T with k the direction of largest absolute principal
// curvature (principal_curvatures(); around a cylinder, not along it): a step along it costs
// `ratio`. The directions are first smoothed: `smoothing_rounds` one-ring averages of the
// sign-free tensors w k k^T, w = (|k_max| - |k_min|) / (|k_max| + |k_min|) (how sure the
// direction is), so noisy, flat and umbilic vertices follow their neighbours; k is then the
// dominant tangent eigenvector. With 0 rounds the raw per-vertex directions are used. Vertices
// with no dominant direction (top two eigenvalues within 1e-3; raw: |k_max| - |k_min| <=
// 1e-3 |k_max| or a failed fit) get the identity. Throws InvalidInput for a ratio that is not
// finite > 0 or negative rounds.
MetricField curvature_metric(const TriangleMesh& mesh, double ratio, int smoothing_rounds = 3);

// Per-vertex tensors from the scalar vertex attributes tensor_xx, tensor_xy, tensor_xz,
// tensor_yy, tensor_yz, tensor_zz (PLY float/double properties; names compared without case,
// so glTF's _TENSOR_XX works too). Throws InvalidInput when some are missing or their length is
// not `num_vertices`. Positive definiteness is checked by validate() / metric_edge_lengths().
MetricField metric_from_attributes(const io::VertexAttributes& attributes, std::size_t num_vertices);
bool has_tensor_attributes(const io::VertexAttributes& attributes);

// The text format (docs/anisotropic.md): '#' starts a comment; an optional first line
// `constant`, `per-face` or `per-vertex`; then one tensor per line, six numbers
// "xx xy xz yy yz zz". Without the keyword the count decides: 1 = constant, the face count =
// per face, the vertex count = per vertex (an error when both counts are equal).
// Throws IoError naming `name` and the line.
MetricField parse_metric_text(std::istream& in, const std::string& name, std::size_t num_vertices,
                              std::size_t num_faces);
MetricField read_metric_file(const std::string& path, std::size_t num_vertices, std::size_t num_faces);

}  // namespace gsp::anisotropic
