// PointCloudGeodesics: merge identical points, centre the coordinates (georeferenced clouds
// carry offsets of 1e5 and more), build the k-d tree, the symmetric neighbour graph and the
// tangent frames once, and the local triangles; compute() seeds the sources and runs GSP on
// the triangles, GSP on the graph, or Dijkstra.
#include <gsp/batch.hpp>
#include <gsp/errors.hpp>
#include <gsp/pointcloud/point_cloud_geodesics.hpp>

#include "graph_builder.hpp"
#include "kd_tree.hpp"
#include "local_triangles.hpp"
#include "point_propagation.hpp"
#include "tangent_frames.hpp"
#include "triangle_domain.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>
#include <string>
#include <tuple>

namespace gsp::pointcloud {
namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

struct PointCloudGeodesics::Impl {
  PointCloudOptions options;
  Vec3 origin;                            // subtracted from every position
  std::vector<Vec3> position;             // unique points, centred
  std::vector<Index> unique_of;           // input point -> unique point
  std::vector<Index> representative;      // unique point -> its first input point
  std::unique_ptr<detail::PointTree> tree;
  NeighbourGraph graph;
  detail::TangentFrames frames;
  Components components;
  std::unique_ptr<detail::TriangleDomain> triangles;   // null unless options.local_triangles
  PointCloudStats stats;

  void merge_duplicates(const std::vector<Vec3>& points) {
    const std::size_t n = points.size();
    // Sorting by (x, y, z, index) puts identical positions next to each other, the smallest
    // input index first; unique ids then follow the input order (keeps its locality).
    std::vector<Index> order(n);
    std::iota(order.begin(), order.end(), Index{0});
    std::sort(order.begin(), order.end(), [&](Index a, Index b) {
      return std::tie(points[a].x, points[a].y, points[a].z, a) < std::tie(points[b].x, points[b].y, points[b].z, b);
    });
    std::vector<Index> first(n);
    for (std::size_t i = 0; i < n; ++i)
      first[order[i]] = (i > 0 && points[order[i]] == points[order[i - 1]]) ? first[order[i - 1]] : order[i];
    unique_of.assign(n, kInvalidIndex);
    for (Index i = 0; i < n; ++i) {
      if (first[i] == i) {
        unique_of[i] = static_cast<Index>(representative.size());
        representative.push_back(i);
      } else {
        unique_of[i] = unique_of[first[i]];
      }
    }
    origin = bounding_box(points).center();
    position.resize(representative.size());
    for (std::size_t u = 0; u < representative.size(); ++u) position[u] = points[representative[u]] - origin;
  }

  // Offset from unique point u to x (centred), in u's tangent plane, keeping its length.
  Vec3 tangent_offset(Index u, Vec3 x) const {
    const Vec3 off = x - position[u];
    const Vec3 n = frames.normal[u];
    const Vec3 t = off - dot(off, n) * n;
    const double lo = norm(off), lt = norm(t);
    if (lo == 0) return {0, 0, 0};
    return lt > 1e-9 * lo ? (lo / lt) * t : lo * frames.t1[u];
  }
};

PointCloudGeodesics::PointCloudGeodesics(const std::vector<Vec3>& points, const std::vector<Vec3>& normals,
                                         const PointCloudOptions& options)
    : impl_(std::make_unique<Impl>()) {
  detail::check_options(options.neighbours);
  validate_positions(points, "point cloud: point");
  if (!normals.empty() && normals.size() != points.size())
    throw InvalidInput("point cloud: " + std::to_string(normals.size()) + " normals for " +
                       std::to_string(points.size()) + " points");
  Impl& m = *impl_;
  m.options = options;
  m.merge_duplicates(points);

  auto t0 = std::chrono::steady_clock::now();
  m.tree = std::make_unique<detail::PointTree>(m.position);
  m.stats.seconds_tree = seconds_since(t0);

  t0 = std::chrono::steady_clock::now();
  m.graph = detail::build_graph(m.position, *m.tree, options.neighbours);
  m.components = connected_components(m.graph);
  m.stats.seconds_graph = seconds_since(t0);

  t0 = std::chrono::steady_clock::now();
  std::vector<Vec3> unique_normals;
  if (options.use_input_normals && !normals.empty()) {
    unique_normals.resize(m.position.size());
    for (std::size_t u = 0; u < m.position.size(); ++u) unique_normals[u] = normals[m.representative[u]];
  }
  m.frames = detail::tangent_frames(m.position, unique_normals, *m.tree, options.neighbours.k);
  m.stats.seconds_frames = seconds_since(t0);

  if (options.local_triangles) {
    t0 = std::chrono::steady_clock::now();
    // The one-rings leave out the links graph_gsp treats as steep by default.
    const detail::LocalTriangles local = detail::local_triangles(m.position, m.frames, m.graph.begin, m.graph.neighbour,
                                                                 PointGeodesicOptions{}.steep_link_slope);
    m.triangles = std::make_unique<detail::TriangleDomain>(m.position, detail::consistent_triangles(local));
    m.stats.seconds_triangles = seconds_since(t0);
  }

  PointCloudStats& s = m.stats;
  s.points = points.size();
  s.unique_points = m.position.size();
  s.duplicates = s.points - s.unique_points;
  s.components = m.components.count;
  std::vector<std::size_t> sizes(m.components.count, 0);
  for (Index c : m.components.id) ++sizes[c];
  s.largest_component = sizes.empty() ? 0 : *std::max_element(sizes.begin(), sizes.end());
  s.links = m.graph.num_links();
  double total = 0;
  for (double l : m.graph.length) total += l;
  s.mean_link_length = m.graph.length.empty() ? 0 : total / static_cast<double>(m.graph.length.size());
  s.normals_from_input = m.frames.from_input;
  s.normals_estimated = m.frames.estimated;
  s.elliptic_points = std::size_t(std::count(m.frames.elliptic.begin(), m.frames.elliptic.end(), std::uint8_t(1)));
  if (m.triangles) {
    s.local_triangles = m.triangles->num_triangles();
    s.triangle_components = m.triangles->num_components();
    s.points_without_triangle = m.triangles->num_points_without_face();
  }
}

PointCloudGeodesics::PointCloudGeodesics(const TriangleMesh& cloud, const PointCloudOptions& options)
    : PointCloudGeodesics(cloud.positions, cloud.normals, options) {}

PointCloudGeodesics::~PointCloudGeodesics() = default;
PointCloudGeodesics::PointCloudGeodesics(PointCloudGeodesics&&) noexcept = default;
PointCloudGeodesics& PointCloudGeodesics::operator=(PointCloudGeodesics&&) noexcept = default;

PointCloudResult PointCloudGeodesics::compute(const std::vector<PointSource>& sources,
                                              const PointGeodesicOptions& options) const {
  const Impl& m = *impl_;
  if (std::isnan(options.max_distance)) throw InvalidInput("point cloud: max_distance is NaN");
  if (!(options.visibility_angle_deg >= 0 && options.visibility_angle_deg <= 180))
    throw InvalidInput("point cloud: the visibility angle must lie in [0, 180] degrees");
  if (!(options.elliptic_visibility_angle_deg >= 0 && options.elliptic_visibility_angle_deg <= 180))
    throw InvalidInput("point cloud: the elliptic visibility angle must lie in [0, 180] degrees");
  if (!(options.hinge_area >= 0) || std::isnan(options.hinge_area))
    throw InvalidInput("point cloud: hinge_area must be >= 0");
  if (!(options.steep_link_slope >= 0)) throw InvalidInput("point cloud: steep_link_slope must be >= 0");
  if (!(options.gap_link_slope >= 0)) throw InvalidInput("point cloud: gap_link_slope must be >= 0");
  const bool on_triangles = options.method == PointMethod::gsp;
  if (options.method == PointMethod::graph_gsp && options.strategy != Strategy::speed_limiter)
    throw InvalidInput("point cloud: graph_gsp runs the speed limiter only (PointMethod::gsp takes every strategy)");
  if (!(options.f > 0) || !std::isfinite(options.f)) throw InvalidInput("point cloud: f must be positive and finite");
  if (on_triangles && !m.triangles)
    throw InvalidInput("point cloud: PointMethod::gsp needs the local triangles (PointCloudOptions::local_triangles)");
  std::vector<detail::Seed> seeds;
  std::vector<detail::TriangleSource> triangle_sources;
  const unsigned k = std::max(1u, m.options.neighbours.k);
  std::vector<Index> idx(k);
  std::vector<double> d2(k);
  for (std::size_t s = 0; s < sources.size(); ++s) {
    const PointSource& src = sources[s];
    const Index label = static_cast<Index>(s);
    if (!std::isfinite(src.offset)) throw InvalidInput("point cloud: source " + std::to_string(s) + " has a non-finite offset");
    if (src.kind == PointSource::Kind::point) {
      if (src.point >= m.unique_of.size())
        throw InvalidInput("point cloud: source point " + std::to_string(src.point) + " does not exist (" +
                           std::to_string(m.unique_of.size()) + " points)");
      seeds.push_back({m.unique_of[src.point], src.offset, {0, 0, 0}, label});
      triangle_sources.push_back({Source::at_vertex(m.unique_of[src.point], src.offset), label});
      continue;
    }
    if (!is_finite(src.position)) throw InvalidInput("point cloud: source " + std::to_string(s) + " is not finite");
    if (m.position.empty()) throw InvalidInput("point cloud: a position source needs a non-empty cloud");
    const Vec3 x = src.position - m.origin;
    const std::size_t got = m.tree->knn(x, options.seeding == PositionSeeding::snap ? 1 : k, idx.data(), d2.data());
    Source on_surface;
    if (on_triangles && options.seeding == PositionSeeding::neighbours &&
        m.triangles->closest_point(x, idx.data(), got, on_surface)) {
      on_surface.offset = src.offset;
      triangle_sources.push_back({on_surface, label});
      continue;
    }
    for (std::size_t a = 0; a < got; ++a) {
      const Index u = idx[a];
      // Snapped, or no triangle near: the nearest points as sources, each at its straight
      // distance from the position.
      const double straight = options.seeding == PositionSeeding::snap ? 0.0 : std::sqrt(d2[a]);
      triangle_sources.push_back({Source::at_vertex(u, src.offset + straight), label});
      if (options.seeding == PositionSeeding::snap) seeds.push_back({u, src.offset, {0, 0, 0}, label});
      else seeds.push_back({u, src.offset, m.tangent_offset(u, x), label});
    }
  }

  const auto t0 = std::chrono::steady_clock::now();
  detail::PointState state;
  state.reset(m.position.size());
  PointCloudResult r;
  const detail::Domain domain{m.graph, m.position, m.frames, m.stats.mean_link_length};
  if (on_triangles) {
    GeodesicOptions core;
    core.strategy = options.strategy;
    core.f = options.f;
    core.max_distance = options.max_distance;
    core.want_face_distances = false;
    core.threads = 1;   // compute() may itself run on many threads at once
    m.triangles->propagate(triangle_sources, m.graph, core, state, r.stats);
  }
  else if (options.method == PointMethod::dijkstra)
    detail::propagate_dijkstra(domain, seeds, options.max_distance, state, r.stats);
  else
    detail::propagate_gsp(domain, seeds, options, state, r.stats);

  const std::size_t n = m.unique_of.size();
  r.distance.resize(n);
  r.source.resize(n);
  if (options.want_virtual_sources) r.virtual_sources.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Index u = m.unique_of[i];
    const bool in_range = std::isfinite(state.distance[u]) && state.distance[u] <= options.max_distance;
    r.distance[i] = in_range ? state.distance[u] : std::numeric_limits<double>::infinity();
    r.source[i] = in_range ? state.label[u] : kInvalidIndex;
    if (in_range) ++r.stats.points_reached;
    if (options.want_virtual_sources && in_range) {
      const Vec3 s = state.sx[u] * m.frames.t1[u] + state.sy[u] * m.frames.t2[u];
      r.virtual_sources[i] = {m.origin + m.position[u] + s, state.sigma[u], state.label[u]};
    }
  }
  r.stats.seconds = seconds_since(t0);
  return r;
}

std::size_t PointCloudGeodesics::num_points() const { return impl_->unique_of.size(); }
const PointCloudStats& PointCloudGeodesics::stats() const { return impl_->stats; }
const NeighbourGraph& PointCloudGeodesics::graph() const { return impl_->graph; }
const std::vector<Index>& PointCloudGeodesics::unique_index() const { return impl_->unique_of; }

Index PointCloudGeodesics::nearest_point(Vec3 position) const {
  const Impl& m = *impl_;
  if (m.position.empty() || !is_finite(position)) return kInvalidIndex;
  Index u = 0;
  double d2 = 0;
  if (m.tree->knn(position - m.origin, 1, &u, &d2) == 0) return kInvalidIndex;
  return m.representative[u];
}

std::vector<Index> PointCloudGeodesics::component_ids() const {
  std::vector<Index> out(impl_->unique_of.size());
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = impl_->components.id[impl_->unique_of[i]];
  return out;
}

std::vector<Triangle> PointCloudGeodesics::local_triangles() const {
  std::vector<Triangle> out;
  if (!impl_->triangles) return out;
  out = impl_->triangles->triangles();
  for (Triangle& t : out)
    for (Index& v : t) v = impl_->representative[v];
  return out;
}

std::vector<Vec3> PointCloudGeodesics::normals() const {
  std::vector<Vec3> out(impl_->unique_of.size());
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = impl_->frames.normal[impl_->unique_of[i]];
  return out;
}

std::vector<double> distance_matrix(const PointCloudGeodesics& cloud, const std::vector<Index>& rows,
                                    const std::vector<Index>& cols, const PointGeodesicOptions& options,
                                    unsigned threads) {
  for (const std::vector<Index>* list : {&rows, &cols})
    for (Index i : *list)
      if (i >= cloud.num_points()) throw InvalidInput("distance_matrix: point " + std::to_string(i) + " out of range");
  std::vector<double> matrix(rows.size() * cols.size());
  parallel_for(rows.size(), resolve_threads(threads, rows.size()), [&](std::size_t i) {
    const PointCloudResult r = cloud.compute({PointSource::at_point(rows[i])}, options);
    for (std::size_t j = 0; j < cols.size(); ++j) matrix[i * cols.size() + j] = r.distance[cols[j]];
  });
  return matrix;
}

PointCloudResult point_cloud_geodesic_distances(const TriangleMesh& cloud, const std::vector<PointSource>& sources,
                                                const PointGeodesicOptions& options,
                                                const PointCloudOptions& cloud_options) {
  return PointCloudGeodesics(cloud, cloud_options).compute(sources, options);
}

}  // namespace gsp::pointcloud
