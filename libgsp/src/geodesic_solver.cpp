#include "propagation.hpp"
#include "virtual_source.hpp"

#include <gsp/connectivity.hpp>
#include <gsp/errors.hpp>
#include <gsp/geodesics.hpp>
#include <gsp/topology.hpp>

#include <cmath>
#include <mutex>
#include <string>

namespace gsp {

using detail::FaceState;
using detail::HalfedgeGeometry;
using detail::QueueEntry;

struct GeodesicSolver::Impl {
  Layout layout;
  TriangleMesh mesh;               // reordered by the layout
  std::vector<Index> ring;         // radial links with direction bits (see propagation.hpp)
  std::vector<bool> skipped_face;  // faces that repeat a vertex: not part of the propagation
  Connectivity conn;
  double mean_edge = 1;
  VisibilityHeuristic heuristic;

  mutable std::once_flag float_once, double_once;
  mutable std::vector<HalfedgeGeometry<float>> geo_float;
  mutable std::vector<HalfedgeGeometry<double>> geo_double;

  template <class Real>
  const std::vector<HalfedgeGeometry<Real>>& geometry() const {
    if constexpr (std::is_same_v<Real, float>) {
      std::call_once(float_once, [&] {
        geo_float = detail::build_halfedge_geometry<float>(mesh, 1.0 / mean_edge, heuristic);
      });
      return geo_float;
    } else {
      std::call_once(double_once, [&] {
        geo_double = detail::build_halfedge_geometry<double>(mesh, 1.0 / mean_edge, heuristic);
      });
      return geo_double;
    }
  }

  void build_ring();
  template <class Real>
  GeodesicResult run(const std::vector<Source>& sources, const GeodesicOptions& options) const;
};

void GeodesicSolver::Impl::build_ring() {
  const std::size_t nh = conn.num_halfedges();
  if (nh > detail::kRingIndexMask) throw InvalidInput("mesh too large: more than 2^30 halfedges");
  skipped_face.assign(mesh.num_faces(), false);
  for (std::size_t f = 0; f < mesh.num_faces(); ++f) {
    const Triangle& t = mesh.triangles[f];
    skipped_face[f] = t[0] == t[1] || t[1] == t[2] || t[2] == t[0];
  }
  auto dir_bit = [&](Index h) { return from_vertex(mesh, h) < to_vertex(mesh, h); };
  // Every halfedge starts as a ring of its own (boundary, skipped face, loop), then the
  // members of each radial ring are linked without the skipped faces' halfedges.
  ring.resize(nh);
  for (Index h = 0; h < nh; ++h) ring[h] = h;
  std::vector<Index> members;
  for (Index e = 0; e < conn.num_edges(); ++e) {
    members.clear();
    const Index first = conn.edge_halfedge[e];
    Index h = first;
    do {
      if (!skipped_face[face_of(h)]) members.push_back(h);
      h = conn.radial_next[h];
    } while (h != first);
    for (std::size_t k = 0; k < members.size(); ++k) {
      const Index a = members[k], b = members[(k + 1) % members.size()];
      ring[a] = b | (dir_bit(b) ? detail::kRingNextDir : 0) | (dir_bit(a) ? detail::kRingSelfDir : 0);
    }
  }
}

GeodesicSolver::GeodesicSolver(const TriangleMesh& input, const SolverOptions& options)
    : impl_(std::make_unique<Impl>()) {
  validate(input);
  impl_->heuristic = options.heuristic;
  impl_->layout = options.optimize_layout ? compute_cache_layout(input) : identity_layout(input);
  impl_->mesh = apply_layout(input, impl_->layout);
  impl_->conn = build_connectivity(impl_->mesh);
  impl_->mean_edge = detail::mean_edge_length(impl_->mesh);
  impl_->build_ring();
}

GeodesicSolver::~GeodesicSolver() = default;
GeodesicSolver::GeodesicSolver(GeodesicSolver&&) noexcept = default;
GeodesicSolver& GeodesicSolver::operator=(GeodesicSolver&&) noexcept = default;

const Layout& GeodesicSolver::layout() const { return impl_->layout; }

std::size_t GeodesicSolver::state_bytes(Precision precision) const {
  const std::size_t nf = impl_->mesh.num_faces();
  const bool single = precision == Precision::single;
  const std::size_t state = nf * (single ? sizeof(FaceState<float>) : sizeof(FaceState<double>));
  const std::size_t geometry =
      3 * nf * (single ? sizeof(HalfedgeGeometry<float>) : sizeof(HalfedgeGeometry<double>));
  return state + geometry + impl_->ring.size() * sizeof(Index);
}

GeodesicResult GeodesicSolver::compute(const std::vector<Source>& sources,
                                       const GeodesicOptions& options) const {
  if (!(options.f > 0) || !(options.f0 > 0) || !(options.f1 > 0))
    throw InvalidInput("strategy parameters f, f0, f1 must be positive");
  if (std::isnan(options.max_distance) || options.max_distance < 0)
    throw InvalidInput("max_distance must be >= 0");
  if (options.precision == Precision::single) return impl_->run<float>(sources, options);
  return impl_->run<double>(sources, options);
}

namespace {

// Seeds one face with the exact distances from a point in its plane.
template <class Real>
bool seed_face(const TriangleMesh& mesh, Index f, Vec3 p, double scale, double offset, Index source,
               FaceState<Real>* state) {
  const Triangle& t = mesh.triangles[f];
  const Vec3 c = (1.0 / 3.0) * (mesh.positions[t[0]] + mesh.positions[t[1]] + mesh.positions[t[2]]);
  const Real dT = Real(offset * scale + scale * distance(c, p));
  FaceState<Real>& st = state[f];
  if (!(dT < st.dT)) return false;
  for (int i = 0; i < 3; ++i) {
    const double d = scale * distance(mesh.positions[t[i]], p);
    st.d2[i] = Real(d * d);
  }
  st.sigma = Real(offset * scale);
  st.dT = dT;
  st.source = source;
  return true;
}

}  // namespace

template <class Real>
GeodesicResult GeodesicSolver::Impl::run(const std::vector<Source>& sources,
                                         const GeodesicOptions& options) const {
  const auto& geo = geometry<Real>();
  const std::size_t nf = mesh.num_faces(), nv = mesh.num_vertices();
  const double scale = 1.0 / mean_edge;
  const Real inf = std::numeric_limits<Real>::infinity();
  std::vector<FaceState<Real>> state(nf, FaceState<Real>{{inf, inf, inf}, inf, inf, kInvalidIndex});

  GeodesicResult result;
  result.stats.mean_edge_length = mean_edge;
  std::vector<QueueEntry<Real>> queue;
  queue.reserve(std::max<std::size_t>(64, nf / 4));

  // Exact vertex values for vertex sources (a vertex in no usable face still gets its offset).
  std::vector<double> source_vertex_value(nv, std::numeric_limits<double>::infinity());
  std::vector<Index> source_vertex_label(nv, kInvalidIndex);

  for (std::size_t s = 0; s < sources.size(); ++s) {
    const Source& src = sources[s];
    const Index label = static_cast<Index>(s);
    if (!std::isfinite(src.offset) || src.offset < 0)
      throw InvalidInput("source " + std::to_string(s) + ": offset must be finite and >= 0");
    if (src.kind == Source::Kind::vertex) {
      if (src.element >= nv)
        throw InvalidInput("source vertex " + std::to_string(src.element) + " does not exist (" +
                           std::to_string(nv) + " vertices)");
      const Index v = layout.vertex_rank[src.element];
      if (src.offset < source_vertex_value[v]) {
        source_vertex_value[v] = src.offset;
        source_vertex_label[v] = label;
      }
      for (Index k = conn.vertex_corner_begin[v]; k < conn.vertex_corner_begin[v + 1]; ++k) {
        const Index c = conn.vertex_corners[k];
        const Index f = face_of(c);
        if (skipped_face[f]) continue;
        if (seed_face(mesh, f, mesh.positions[v], scale, src.offset, label, state.data()))
          queue.push_back({next_halfedge(c), state[f].dT});   // the edge opposite v
      }
    } else {
      if (src.element >= nf)
        throw InvalidInput("source face " + std::to_string(src.element) + " does not exist (" +
                           std::to_string(nf) + " faces)");
      const auto& b = src.barycentric;
      const double sum = b[0] + b[1] + b[2];
      if (!(b[0] >= 0 && b[1] >= 0 && b[2] >= 0) || std::abs(sum - 1) > 1e-6)
        throw InvalidInput("source " + std::to_string(s) +
                           ": barycentric coordinates must be >= 0 and sum to 1");
      const Index f = layout.face_rank[src.element];
      if (skipped_face[f]) continue;   // a face repeating a vertex has no interior
      const Triangle& t = mesh.triangles[f];
      const Vec3 p = (b[0] / sum) * mesh.positions[t[0]] + (b[1] / sum) * mesh.positions[t[1]] +
                     (b[2] / sum) * mesh.positions[t[2]];
      if (seed_face(mesh, f, p, scale, src.offset, label, state.data()))
        for (int i = 0; i < 3; ++i) queue.push_back({3 * f + i, state[f].dT});
    }
  }
  // A face seeded twice (two sources) left an entry behind for its first seed.
  result.stats.enqueued = queue.size();

  const Real limit = std::isfinite(options.max_distance) ? Real(options.max_distance * scale) : inf;
  detail::UpdateStep<Real> step(geo.data(), ring.data(), state.data(), limit, result.stats);
  const Real f = Real(options.f), f0 = Real(options.f0), f1 = Real(options.f1);
  using detail::Postpone;
  switch (options.strategy) {
    case Strategy::speed_limiter: detail::run_speed_limiter(step, queue, f, result.stats); break;
    case Strategy::static_postpone:
      detail::run_postpone(step, queue, Postpone::fixed, f, f0, f1, result.stats);
      break;
    case Strategy::dynamic_postpone:
      detail::run_postpone(step, queue, Postpone::dynamic, f, f0, f1, result.stats);
      break;
    case Strategy::hybrid_postpone:
      detail::run_postpone(step, queue, Postpone::hybrid, f, f0, f1, result.stats);
      break;
    case Strategy::bfs: detail::run_postpone(step, queue, Postpone::none, f, f0, f1, result.stats); break;
    case Strategy::priority_queue: detail::run_priority_queue(step, queue, result.stats); break;
  }

  // Per-vertex: the smallest sigma + |corner - virtual source| over the incident reached faces.
  std::vector<double> vdist(source_vertex_value);
  std::vector<Index> vlabel(source_vertex_label);
  for (std::size_t fi = 0; fi < nf; ++fi) {
    const FaceState<Real>& st = state[fi];
    if (st.source == kInvalidIndex) continue;
    ++result.stats.faces_reached;
    const Triangle& t = mesh.triangles[fi];
    for (int i = 0; i < 3; ++i) {
      const double d = (double(st.sigma) + std::sqrt(double(st.d2[i]))) * mean_edge;
      if (d < vdist[t[i]]) {
        vdist[t[i]] = d;
        vlabel[t[i]] = st.source;
      }
    }
  }
  const double cutoff = options.max_distance;
  result.vertex_distance.resize(nv);
  result.vertex_source.resize(nv);
  for (std::size_t v = 0; v < nv; ++v) {
    const Index in = layout.vertex_order[v];
    const bool keep = vdist[v] <= cutoff;
    result.vertex_distance[in] = keep ? vdist[v] : std::numeric_limits<double>::infinity();
    result.vertex_source[in] = keep ? vlabel[v] : kInvalidIndex;
  }
  result.face_distance.resize(nf);
  result.face_source.resize(nf);
  for (std::size_t fi = 0; fi < nf; ++fi) {
    const Index in = layout.face_order[fi];
    const FaceState<Real>& st = state[fi];
    result.face_distance[in] = st.source == kInvalidIndex ? std::numeric_limits<double>::infinity()
                                                          : double(st.dT) * mean_edge;
    result.face_source[in] = st.source;
  }
  if (options.want_face_sources) {
    result.face_sources.resize(nf);
    for (std::size_t fi = 0; fi < nf; ++fi) {
      const FaceState<Real>& st = state[fi];
      if (st.source == kInvalidIndex) continue;
      const double d2[3] = {double(st.d2[0]), double(st.d2[1]), double(st.d2[2])};
      VirtualSource& vs = result.face_sources[layout.face_order[fi]];
      vs.position = detail::locate_virtual_source(mesh, Index(fi), d2, mean_edge);
      vs.sigma = double(st.sigma) * mean_edge;
      vs.source = st.source;
    }
  }
  return result;
}

GeodesicResult geodesic_distances(const TriangleMesh& mesh, const std::vector<Source>& sources,
                                  const GeodesicOptions& options, const SolverOptions& solver_options) {
  return GeodesicSolver(mesh, solver_options).compute(sources, options);
}

}  // namespace gsp
