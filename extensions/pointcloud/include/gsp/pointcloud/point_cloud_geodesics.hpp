#pragma once
// Geodesic distances on point clouds by Geodesic Source Propagation (paper Section 4.4).
// The k-nearest-neighbour graph (nanoflann) and per-point tangent frames are built once. By
// default (PointMethod::gsp) each point's neighbours are triangulated in its tangent plane
// (local Delaunay one-rings), the triangles its neighbours agree on form a soup, and the mesh
// core's virtual sources propagate over it. PointMethod::graph_gsp carries a virtual source
// per point over the graph's links instead, unfolded from one tangent plane into the next.
// docs/pointcloud.md states both and what each measures.
//
//   gsp::pointcloud::PointCloudGeodesics solver(cloud);            // k-d tree, frames, graph
//   auto r = solver.compute({gsp::pointcloud::PointSource::at_point(0)});
//   r.distance[i]   // per input point, +inf where unreachable (another graph component)
#include <gsp/geodesics.hpp>
#include <gsp/mesh.hpp>
#include <gsp/pointcloud/neighbour_graph.hpp>

#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

namespace gsp::pointcloud {

struct PointCloudOptions {
  NeighbourOptions neighbours;      // k = 10 nearest neighbours by default
  bool use_input_normals = true;    // else (or where a normal is zero/not finite) local PCA
  // Build the local triangles PointMethod::gsp propagates on (about as long again as the
  // graph and the frames). Without them only graph_gsp and dijkstra can be computed.
  bool local_triangles = true;
};

// A source: an input point, or any position in space (see PositionSeeding). `offset` is an
// initial distance added to everything the source reaches.
struct PointSource {
  enum class Kind : std::uint8_t { point, position };
  Kind kind = Kind::point;
  Index point = 0;
  Vec3 position;
  double offset = 0;

  static PointSource at_point(Index i, double offset = 0) { return {Kind::point, i, {}, offset}; }
  static PointSource at_position(Vec3 p, double offset = 0) { return {Kind::position, kInvalidIndex, p, offset}; }
};

enum class PositionSeeding : std::uint8_t {
  neighbours,   // the k nearest points get their straight distance and the position as virtual source
  snap,         // the nearest point becomes the source (distance 0 there)
};

enum class PointMethod : std::uint8_t {
  gsp,         // the mesh core's GSP on the cloud's local triangles (the default)
  graph_gsp,   // virtual sources in tangent planes carried over the graph's links
  dijkstra,    // shortest paths along the same graph's links (the baseline)
};

struct PointGeodesicOptions {
  PointMethod method = PointMethod::gsp;
  // gsp: any of the core's queue strategies (paper 4.2), f in mean edge lengths of the
  // triangles. graph_gsp runs the speed limiter only (other strategies: InvalidInput), f in
  // mean link lengths of the graph.
  Strategy strategy = Strategy::speed_limiter;
  double f = 1.0;
  // Points farther than this are not expanded and are reported as +inf.
  double max_distance = std::numeric_limits<double>::infinity();
  // The rest are graph_gsp's rules (docs/pointcloud.md, "The graph propagation").
  // Visibility: propagation p -> q stays straight while the line from q
  // to p's unfolded virtual source S passes within rho of p, with
  //   rho = min(|p - q| sin(visibility_angle), hinge_area |p - q|^2 / |S - q|);
  // beyond, the path bends at that distance from p. The second term bounds the area of the
  // triangle (S, p, q), which is what the flat unfolding gets wrong on curved (saddle) parts.
  // Smaller values bend more (over-estimate), larger ones cut more (under-estimate).
  double visibility_angle_deg = 10.0;
  // The angle used instead where both ends of the link are elliptic (Gaussian curvature > 0
  // by a quadric fitted to each point's neighbours): there the flat unfolding over-estimates
  // rather than cuts corners (a sphere is exact at any angle), so a wider window only removes
  // bends. Values at or below visibility_angle_deg turn this off. Measured in
  // docs/pointcloud.md ("Elliptic points").
  double elliptic_visibility_angle_deg = 20.0;
  double hinge_area = std::numeric_limits<double>::infinity();   // off by default
  // Links as arcs: a link of chord L whose directions in the two tangent planes turn by
  // theta is unfolded with the length of the circular arc tangent to both planes,
  // L (theta/2) / sin(theta/2). Chords cut below a curved surface: summed over a path they
  // under-estimate its length by the surface's normal curvature squared (docs/pointcloud.md).
  bool curved_links = true;
  // Steep links: where |n . (q - p)| > steep_link_slope |q - p| at either end, the link leaves
  // the tangent plane; on sampled surfaces such links jump across thin gaps (between a
  // handle and the body, two lips, a fold). GSP does not propagate over them, except into
  // points that no other link reaches (so every point of a reached graph component is still
  // reached). 1 or more: every link is used.
  double steep_link_slope = 0.8;
  // Gap links: steep at both ends, |n . (q - p)| > gap_link_slope |q - p| at p and at q. A
  // chord of a smooth, well-sampled surface leaves each tangent plane at about half the angle
  // the surface turns over it (a few degrees); one that leaves both planes at more than 20
  // degrees steps between two sheets closer than the sample spacing (lips, the rim of a thin
  // plate) or cuts a sharp edge. Treated like steep links. 1 or more: off.
  double gap_link_slope = 0.35;
  PositionSeeding seeding = PositionSeeding::neighbours;
  bool want_virtual_sources = false;
};

// Where a point's geodesic comes from: the straight segment (in the point's tangent plane)
// from the point to `position`, then `sigma` more. graph_gsp only: gsp and dijkstra report the
// point itself with sigma = its distance.
struct PointVirtualSource {
  Vec3 position;                    // 3D, in the point's tangent plane
  double sigma = std::numeric_limits<double>::infinity();
  Index source = kInvalidIndex;     // index into the sources list
};

// What the preparation found and how long it took.
struct PointCloudStats {
  std::size_t points = 0;               // input points
  std::size_t unique_points = 0;        // after merging bit-identical positions
  std::size_t duplicates = 0;           // points merged into an earlier identical one
  std::size_t components = 0;           // connected components of the neighbour graph
  std::size_t largest_component = 0;    // unique points in the largest one
  std::size_t links = 0;                // undirected links of the graph
  std::size_t normals_from_input = 0;   // unique points whose frame uses the file's normal
  std::size_t normals_estimated = 0;    // unique points whose normal came from local PCA
  std::size_t elliptic_points = 0;      // unique points with positive fitted Gaussian curvature
  std::size_t local_triangles = 0;      // triangles PointMethod::gsp propagates on (0 if not built)
  std::size_t triangle_components = 0;  // edge- or vertex-connected pieces of those triangles
  std::size_t points_without_triangle = 0;   // unique points no triangle touches (reached over links)
  double mean_link_length = 0;
  double seconds_tree = 0;              // k-d tree
  double seconds_graph = 0;             // neighbour queries + symmetric CSR
  double seconds_frames = 0;            // normals and tangent frames
  double seconds_triangles = 0;         // local triangles and the core's preparation of them
};

struct PointPropagationStats {
  std::uint64_t update_steps = 0;   // candidate evaluations (one per link tried; gsp: per face pair)
  std::uint64_t updates = 0;        // accepted (a point got a shorter distance; gsp: a face did)
  std::uint64_t bends = 0;          // accepted updates that created a new virtual source
  std::uint64_t steep_links_used = 0;   // graph_gsp: points reached only over steep or gap links (see options)
  std::uint64_t points_reached_over_links = 0;   // gsp: points the triangles did not reach, reached over graph links
  std::uint64_t enqueued = 0;
  std::uint64_t stale_skipped = 0;
  std::uint64_t iterations = 0;     // speed-limiter rounds (heap pops for Dijkstra)
  std::uint64_t points_reached = 0; // input points with a finite distance
  double seconds = 0;
};

struct PointCloudResult {
  std::vector<double> distance;   // per input point; +inf where unreachable or beyond max_distance
  std::vector<Index> source;      // per input point: nearest source, kInvalidIndex if none
  std::vector<PointVirtualSource> virtual_sources;   // per input point, with want_virtual_sources
  PointPropagationStats stats;
};

// Prepares a cloud once (k-d tree, merged duplicates, neighbour graph, tangent frames) and
// answers any number of queries. Thread-safe for concurrent compute() calls.
class PointCloudGeodesics {
 public:
  // normals: empty, or one per point (zero or non-finite entries fall back to PCA).
  // Throws InvalidInput for non-finite positions, a normals count mismatch or bad options.
  explicit PointCloudGeodesics(const std::vector<Vec3>& points, const std::vector<Vec3>& normals = {},
                               const PointCloudOptions& options = {});
  // Uses mesh.positions and mesh.normals; triangles, if any, are ignored.
  explicit PointCloudGeodesics(const TriangleMesh& cloud, const PointCloudOptions& options = {});
  ~PointCloudGeodesics();
  PointCloudGeodesics(PointCloudGeodesics&&) noexcept;
  PointCloudGeodesics& operator=(PointCloudGeodesics&&) noexcept;

  // Throws InvalidInput for a missing point, a non-finite position or offset, or a position
  // source on an empty cloud.
  PointCloudResult compute(const std::vector<PointSource>& sources, const PointGeodesicOptions& options = {}) const;

  std::size_t num_points() const;
  const PointCloudStats& stats() const;
  Index nearest_point(Vec3 position) const;        // kInvalidIndex on an empty cloud
  std::vector<Index> component_ids() const;        // per input point (duplicates share theirs)
  std::vector<Vec3> normals() const;               // per input point, unit, as used (unoriented if estimated)
  const NeighbourGraph& graph() const;             // over the unique points (see unique_index)
  const std::vector<Index>& unique_index() const;  // input point -> graph point
  // The local triangles PointMethod::gsp propagates on, over input point indices (each unique
  // point by its first input point); empty when not built. A mesh of the cloud, not a
  // watertight reconstruction: overlapping and non-manifold where one-rings disagree.
  std::vector<Triangle> local_triangles() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Row i: the distances from point rows[i] alone at the points cols[j], row-major
// (rows.size() x cols.size()); the rows are computed side by side on gsp::parallel_for with
// `threads` (0: all cores), as gsp::distance_matrix does on a mesh. Not exactly symmetric:
// each row is its own propagation.
std::vector<double> distance_matrix(const PointCloudGeodesics& cloud, const std::vector<Index>& rows,
                                    const std::vector<Index>& cols, const PointGeodesicOptions& options = {},
                                    unsigned threads = 0);

// One-off: prepare and compute.
PointCloudResult point_cloud_geodesic_distances(const TriangleMesh& cloud, const std::vector<PointSource>& sources,
                                                const PointGeodesicOptions& options = {},
                                                const PointCloudOptions& cloud_options = {});

}  // namespace gsp::pointcloud
