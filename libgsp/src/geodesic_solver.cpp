#include "intrinsic_geometry.hpp"
#include "goal_directed.hpp"
#include "propagation.hpp"
#include "virtual_source.hpp"
#include "intrinsic_delaunay.hpp"

#include <gsp/connectivity.hpp>
#include <gsp/errors.hpp>
#include <gsp/geodesics.hpp>
#include <gsp/topology.hpp>

#include <chrono>
#include <cmath>
#include <mutex>
#include <optional>
#include <string>

namespace gsp {

using detail::FaceRecord;
using detail::QueueEntry;

// One triangulation the propagation can run on: the input's faces, or their intrinsic
// Delaunay flip (same vertices, same surface, better-shaped triangles).
struct Triangulation {
  std::vector<Triangle> triangles;
  std::vector<double> length;             // per halfedge, model units
  std::vector<Index> ring;                // radial links with direction bits (propagation.hpp)
  std::vector<Index> corner_begin, corners;   // vertex -> its corners (3f + i), CSR

  mutable std::once_flag float_once, double_once;
  mutable std::vector<FaceRecord<float>> records_float;
  mutable std::vector<FaceRecord<double>> records_double;

  // The per-face records every query starts from (lengths, flat corners, nothing reached),
  // built on first use per precision.
  template <class Real>
  const std::vector<FaceRecord<Real>>& records(double scale, const std::vector<std::uint8_t>& flat) const {
    auto build = [&] {
      const Real inf = std::numeric_limits<Real>::infinity();
      std::vector<FaceRecord<Real>> r(triangles.size());
      for (std::size_t f = 0; f < triangles.size(); ++f) {
        Index tag = detail::kNoSource;
        for (Index i = 0; i < 3; ++i)
          if (flat[triangles[f][i]]) tag |= detail::kFlatCorner0 << i;
        r[f] = {0, 0, inf, inf, {Real(scale * length[3 * f]), Real(scale * length[3 * f + 1]),
                                 Real(scale * length[3 * f + 2])}, tag};
      }
      return r;
    };
    if constexpr (std::is_same_v<Real, float>) {
      std::call_once(float_once, [&] { records_float = build(); });
      return records_float;
    } else {
      std::call_once(double_once, [&] { records_double = build(); });
      return records_double;
    }
  }

  void set_direction_bits(const std::vector<Index>& plain_ring) {
    auto dir = [&](Index h) {
      return triangles[face_of(h)][corner_of(h)] < triangles[face_of(h)][corner_of(next_halfedge(h))];
    };
    ring.resize(plain_ring.size());
    for (Index h = 0; h < Index(plain_ring.size()); ++h) {
      const Index g = plain_ring[h];
      ring[h] = g == h ? h : (g | (dir(g) ? detail::kRingNextDir : 0) | (dir(h) ? detail::kRingSelfDir : 0));
    }
  }

  void build_corners(std::size_t num_vertices) {
    corner_begin.assign(num_vertices + 1, 0);
    for (const Triangle& t : triangles)
      for (Index v : t) ++corner_begin[v + 1];
    for (std::size_t v = 0; v < num_vertices; ++v) corner_begin[v + 1] += corner_begin[v];
    corners.resize(3 * triangles.size());
    std::vector<Index> fill(corner_begin.begin(), corner_begin.end() - 1);
    for (Index c = 0; c < Index(corners.size()); ++c) corners[fill[triangles[face_of(c)][corner_of(c)]]++] = c;
  }
};

struct GeodesicSolver::Impl {
  Layout layout;
  TriangleMesh mesh;               // reordered by the layout
  Triangulation input;             // the (reordered) input faces
  std::unique_ptr<Triangulation> delaunay;   // their intrinsic Delaunay flip, if it changed anything
  std::size_t flips = 0;
  std::vector<bool> skipped_face;  // faces that repeat a vertex: not part of the propagation
  // Vertices whose incident faces form several edge-connected fans (bow-ties, welded soups):
  // a wavefront reaching such a vertex continues into its other fans from the vertex itself.
  std::vector<Index> bridge_vertices;
  std::vector<std::uint8_t> flat;  // per vertex: no geodesic can bend there (intrinsic_geometry.hpp)
  double mean_edge = 1;
  bool custom_lengths = false;     // SolverOptions::edge_lengths given: 3D says nothing about them
  VisibilityHeuristic heuristic;
  SolverTimings timings;

  void build_input(const Connectivity& conn, const std::vector<double>& edge_lengths);
  void find_bridge_vertices();
  void build_delaunay();
  template <class Real>
  GeodesicResult run(const Triangulation& tri, const std::vector<Source>& sources,
                     const GeodesicOptions& options) const;
};

void GeodesicSolver::Impl::build_input(const Connectivity& conn, const std::vector<double>& edge_lengths) {
  const std::size_t nh = conn.num_halfedges();
  if (nh > detail::kRingIndexMask) throw InvalidInput("mesh too large: more than 2^30 halfedges");
  skipped_face.assign(mesh.num_faces(), false);
  for (std::size_t f = 0; f < mesh.num_faces(); ++f) {
    const Triangle& t = mesh.triangles[f];
    skipped_face[f] = t[0] == t[1] || t[1] == t[2] || t[2] == t[0];
  }
  // Every halfedge starts as a ring of its own (boundary, skipped face, loop), then the
  // members of each radial ring are linked without the skipped faces' halfedges.
  std::vector<Index> plain(nh);
  for (Index h = 0; h < nh; ++h) plain[h] = h;
  std::vector<Index> members;
  for (Index e = 0; e < conn.num_edges(); ++e) {
    members.clear();
    const Index first = conn.edge_halfedge[e];
    Index h = first;
    do {
      if (!skipped_face[face_of(h)]) members.push_back(h);
      h = conn.radial_next[h];
    } while (h != first);
    for (std::size_t k = 0; k < members.size(); ++k) plain[members[k]] = members[(k + 1) % members.size()];
  }
  input.triangles = mesh.triangles;
  if (edge_lengths.empty()) {
    input.length = detail::halfedge_lengths(mesh);
  } else {
    // Given in input face order; the layout moves whole faces (corners keep their order).
    input.length.resize(edge_lengths.size());
    for (std::size_t f = 0; f < mesh.num_faces(); ++f)
      for (int i = 0; i < 3; ++i) input.length[3 * f + i] = edge_lengths[3 * std::size_t(layout.face_order[f]) + i];
  }
  input.set_direction_bits(plain);
  input.corner_begin = conn.vertex_corner_begin;
  input.corners = conn.vertex_corners;
}

void GeodesicSolver::Impl::build_delaunay() {
  detail::IntrinsicTriangulation t;
  t.triangles = input.triangles;
  t.length = input.length;
  t.skipped = skipped_face;
  t.ring.resize(input.ring.size());
  for (std::size_t h = 0; h < t.ring.size(); ++h) t.ring[h] = input.ring[h] & detail::kRingIndexMask;
  // A generous cap: Delaunay flipping ends after finitely many flips, but float-stored slivers
  // can make near-ties flip back and forth; the result is good long before the cap.
  flips = detail::make_intrinsic_delaunay(t, 20 * t.length.size());
  if (flips == 0) return;
  delaunay = std::make_unique<Triangulation>();
  delaunay->triangles = std::move(t.triangles);
  delaunay->length = std::move(t.length);
  delaunay->set_direction_bits(t.ring);
  delaunay->build_corners(mesh.num_vertices());
}

void GeodesicSolver::Impl::find_bridge_vertices() {
  // Union the faces around each vertex that share an edge through it; more than one group
  // makes the vertex a bridge.
  std::vector<Index> parent;
  std::vector<Index> faces;
  auto find = [&](Index x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for (Index v = 0; v < mesh.num_vertices(); ++v) {
    faces.clear();
    for (Index k = input.corner_begin[v]; k < input.corner_begin[v + 1]; ++k)
      if (!skipped_face[face_of(input.corners[k])]) faces.push_back(input.corners[k]);
    if (faces.size() < 2) continue;
    parent.resize(faces.size());
    for (Index i = 0; i < faces.size(); ++i) parent[i] = i;
    std::size_t groups = faces.size();
    for (Index i = 0; i < faces.size(); ++i) {
      const Index c = faces[i];
      for (Index h : {c, prev_halfedge(c)}) {   // the two edges of this face through v
        for (Index g = input.ring[h] & detail::kRingIndexMask; g != h; g = input.ring[g] & detail::kRingIndexMask) {
          const Index f = face_of(g);
          for (Index j = 0; j < faces.size(); ++j)
            if (face_of(faces[j]) == f) {
              const Index a = find(i), b = find(j);
              if (a != b) parent[a] = b, --groups;
            }
        }
      }
    }
    if (groups > 1) bridge_vertices.push_back(v);
  }
}

GeodesicSolver::GeodesicSolver(const TriangleMesh& input, const SolverOptions& options)
    : impl_(std::make_unique<Impl>()) {
  using Clock = std::chrono::steady_clock;
  validate(input);
  if (!options.edge_lengths.empty()) detail::validate_halfedge_lengths(input, options.edge_lengths);
  auto t0 = Clock::now();
  Impl& m = *impl_;
  m.custom_lengths = !options.edge_lengths.empty();
  m.heuristic = options.heuristic;
  m.layout = options.optimize_layout ? compute_cache_layout(input) : identity_layout(input);
  m.mesh = apply_layout(input, m.layout);
  auto t1 = Clock::now();
  const Connectivity conn = build_connectivity(m.mesh);
  m.build_input(conn, options.edge_lengths);
  m.mean_edge = detail::mean_edge_length(m.input.length, m.skipped_face);
  m.find_bridge_vertices();
  std::vector<Index> nonmanifold = m.bridge_vertices;   // plus the ends of edges with > 2 faces
  for (Index e = 0; e < conn.num_edges(); ++e)
    if (conn.ring_size(conn.edge_halfedge[e]) > 2) {
      nonmanifold.push_back(from_vertex(m.mesh, conn.edge_halfedge[e]));
      nonmanifold.push_back(to_vertex(m.mesh, conn.edge_halfedge[e]));
    }
  m.flat = detail::flat_vertices(m.mesh, m.input.ring, m.skipped_face, nonmanifold,
                                 m.custom_lengths ? &m.input.length : nullptr);
  if (options.intrinsic_delaunay) m.build_delaunay();
  (m.delaunay ? *m.delaunay : m.input).records<float>(1.0 / m.mean_edge, m.flat);
  auto t2 = Clock::now();
  m.timings.layout = std::chrono::duration<double>(t1 - t0).count();
  m.timings.build = std::chrono::duration<double>(t2 - t1).count();
}

GeodesicSolver::~GeodesicSolver() = default;
GeodesicSolver::GeodesicSolver(GeodesicSolver&&) noexcept = default;
GeodesicSolver& GeodesicSolver::operator=(GeodesicSolver&&) noexcept = default;

const Layout& GeodesicSolver::layout() const { return impl_->layout; }
const SolverTimings& GeodesicSolver::timings() const { return impl_->timings; }
std::size_t GeodesicSolver::intrinsic_flips() const { return impl_->flips; }

std::size_t GeodesicSolver::state_bytes(Precision precision) const {
  // Per face one record (source, distances, edge lengths); per halfedge one radial link.
  const std::size_t nf = impl_->mesh.num_faces();
  const std::size_t record = precision == Precision::single ? sizeof(FaceRecord<float>) : sizeof(FaceRecord<double>);
  return nf * record + impl_->input.ring.size() * sizeof(Index);
}

GeodesicResult GeodesicSolver::compute(const std::vector<Source>& sources,
                                       const GeodesicOptions& options) const {
  if (!(options.f > 0) || !(options.f0 > 0) || !(options.f1 > 0))
    throw InvalidInput("strategy parameters f, f0, f1 must be positive");
  if (std::isnan(options.max_distance) || options.max_distance < 0)
    throw InvalidInput("max_distance must be >= 0");
  if (options.goal_directed && options.targets.empty())
    throw InvalidInput("goal_directed (A*) needs at least one target");
  // Both are 3D constructions: a straight-line lower bound and a point in the face's plane.
  if (impl_->custom_lengths && options.goal_directed)
    throw InvalidInput("goal_directed (A*) bounds by 3D straight lines: not with SolverOptions::edge_lengths");
  if (impl_->custom_lengths && options.want_face_sources)
    throw InvalidInput("per-face virtual sources are 3D points: not with SolverOptions::edge_lengths");
  for (Index t : options.targets)
    if (t >= impl_->mesh.num_vertices())
      throw InvalidInput("target vertex " + std::to_string(t) + " does not exist (" +
                         std::to_string(impl_->mesh.num_vertices()) + " vertices)");
  // The intrinsic Delaunay faces are not the input's: a point given in an input face and the
  // per-face virtual sources need the input faces.
  bool vertex_sources_only = true;
  for (const Source& s : sources) vertex_sources_only &= s.kind == Source::Kind::vertex;
  const bool use_delaunay = impl_->delaunay && vertex_sources_only && !options.want_face_sources;
  const Triangulation& tri = use_delaunay ? *impl_->delaunay : impl_->input;
  if (options.precision == Precision::single) return impl_->run<float>(tri, sources, options);
  return impl_->run<double>(tri, sources, options);
}

namespace {

// Seeds face f with a source at barycentric point b of the face (canonical coordinates are
// exact for a point of the face itself); `offset` in normalised units.
template <class Real>
bool seed_face(const std::vector<double>& length, Index f, const double b[3], double scale, double offset,
               Index source, FaceRecord<Real>* faces) {
  double p[3][2];
  detail::canonical_corners(length, f, scale, p);
  const double sx = b[0] * p[0][0] + b[1] * p[1][0] + b[2] * p[2][0];
  const double sy = b[0] * p[0][1] + b[1] * p[1][1] + b[2] * p[2][1];
  const double gx = (p[0][0] + p[1][0] + p[2][0]) / 3, gy = (p[0][1] + p[1][1] + p[2][1]) / 3;
  const Real dT = Real(offset + std::hypot(gx - sx, gy - sy));
  FaceRecord<Real>& r = faces[f];
  if (!(dT < r.dT)) return false;
  r.sx = Real(sx), r.sy = Real(sy), r.sigma = Real(offset), r.dT = dT;
  r.tag = (r.tag & ~detail::kSourceMask) | source;
  return true;
}

const double kCornerWeights[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};

}  // namespace

// Distance of corner c's vertex through its face's virtual source (normalised units).
template <class Real>
Real corner_distance(const FaceRecord<Real>& r, Index corner) {
  Real x = 0, y = 0;
  if (corner == 1) x = r.len[0];
  if (corner == 2) detail::canonical_corner2(r.len, x, y);
  return r.sigma + std::sqrt((r.sx - x) * (r.sx - x) + (r.sy - y) * (r.sy - y));
}

template <class Real>
GeodesicResult GeodesicSolver::Impl::run(const Triangulation& tri, const std::vector<Source>& sources,
                                         const GeodesicOptions& options) const {
  const std::vector<double>& length = tri.length;
  const std::size_t nf = mesh.num_faces(), nv = mesh.num_vertices();
  const double scale = 1.0 / mean_edge;
  const Real inf = std::numeric_limits<Real>::infinity();
  if (sources.size() >= detail::kNoSource) throw InvalidInput("too many sources (at most 2^29 - 1)");
  std::vector<FaceRecord<Real>> state = tri.records<Real>(scale, flat);   // this query's copy

  GeodesicResult result;
  result.stats.mean_edge_length = mean_edge;
  std::vector<QueueEntry<Real>> queue;
  queue.reserve(std::max<std::size_t>(64, nf / 4));
  std::optional<detail::TargetSet<Real>> goal;   // only for runs with targets
  if (!options.targets.empty()) {
    std::vector<Index> targets(options.targets.size());
    for (std::size_t i = 0; i < targets.size(); ++i) targets[i] = layout.vertex_rank[options.targets[i]];
    goal.emplace(state.data(), tri.triangles, mesh.positions, tri.corner_begin, tri.corners, targets, scale,
                 options.goal_directed);
  }

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
        if (goal) goal->vertex_value(v, Real(src.offset * scale));
      }
      for (Index k = tri.corner_begin[v]; k < tri.corner_begin[v + 1]; ++k) {
        const Index c = tri.corners[k];
        const Index f = face_of(c);
        if (skipped_face[f]) continue;
        if (seed_face(length, f, kCornerWeights[corner_of(c)], scale, src.offset * scale, label, state.data()))
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
      const double w[3] = {b[0] / sum, b[1] / sum, b[2] / sum};
      if (seed_face(length, f, w, scale, src.offset * scale, label, state.data()))
        for (int i = 0; i < 3; ++i) queue.push_back({3 * f + i, state[f].dT});
    }
  }
  // A face seeded twice (two sources) left an entry behind for its first seed.
  result.stats.enqueued = queue.size();

  const Real limit = std::isfinite(options.max_distance) ? Real(options.max_distance * scale) : inf;
  detail::UpdateStep<Real> step(state.data(), tri.ring.data(), detail::ProbeTable<Real>(heuristic), limit,
                                result.stats);
  const Real f = Real(options.f), f0 = Real(options.f0), f1 = Real(options.f1);
  auto propagate = [&] {
    using detail::Postpone;
    if (goal) return detail::run_targeted(step, queue, *goal, result.stats);
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
      case Strategy::bfs:
        detail::run_postpone(step, queue, Postpone::none, f, f0, f1, result.stats);
        break;
      case Strategy::priority_queue: detail::run_priority_queue(step, queue, result.stats); break;
    }
  };
  propagate();

  // Bridges: a vertex joining fans that share no edge passes the front on as a virtual source
  // at the vertex. Each round only lowers distances, so this ends; manifold meshes skip it.
  for (bool changed = !bridge_vertices.empty(); changed;) {
    changed = false;
    for (Index v : bridge_vertices) {
      Real best = inf;
      Index label = kInvalidIndex;
      for (Index k = tri.corner_begin[v]; k < tri.corner_begin[v + 1]; ++k) {
        const Index c = tri.corners[k];
        const FaceRecord<Real>& st = state[face_of(c)];
        if (!st.reached()) continue;
        const Real d = corner_distance(st, corner_of(c));
        if (d < best) best = d, label = st.source();
      }
      if (!(best <= limit)) continue;
      for (Index k = tri.corner_begin[v]; k < tri.corner_begin[v + 1]; ++k) {
        const Index c = tri.corners[k];
        const Index fc = face_of(c);
        if (skipped_face[fc]) continue;
        const FaceRecord<Real> before = state[fc];
        if (seed_face(length, fc, kCornerWeights[corner_of(c)], scale, double(best), label, state.data()) &&
            state[fc].dT + state[fc].dT * std::numeric_limits<Real>::epsilon() * 4 < before.dT) {
          queue.push_back({next_halfedge(c), state[fc].dT});
          changed = true;
        } else {
          state[fc] = before;
        }
      }
    }
    if (changed) propagate();
  }

  // Per-vertex: the smallest sigma + |corner - virtual source| over the incident reached faces.
  std::vector<double> vdist(source_vertex_value);
  std::vector<Index> vlabel(source_vertex_label);
  for (std::size_t fi = 0; fi < nf; ++fi) {
    const FaceRecord<Real>& st = state[fi];
    if (!st.reached()) continue;
    ++result.stats.faces_reached;
    const Triangle& t = tri.triangles[fi];
    for (Index i = 0; i < 3; ++i) {
      const double d = double(corner_distance(st, i)) * mean_edge;
      if (d < vdist[t[i]]) {
        vdist[t[i]] = d;
        vlabel[t[i]] = st.source();
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
  if (&tri == &input) {
    for (std::size_t fi = 0; fi < nf; ++fi) {
      const Index in = layout.face_order[fi];
      const FaceRecord<Real>& st = state[fi];
      result.face_distance[in] = st.reached() ? double(st.dT) * mean_edge : std::numeric_limits<double>::infinity();
      result.face_source[in] = st.reached() ? st.source() : kInvalidIndex;
    }
  } else {
    // The propagation ran on other faces: an input face gets the mean of its corners'
    // distances and the label of its nearest corner.
    for (std::size_t fi = 0; fi < nf; ++fi) {
      const Triangle& t = mesh.triangles[fi];
      const Index in = layout.face_order[fi];
      int best = 0;
      for (int i = 1; i < 3; ++i)
        if (vdist[t[i]] < vdist[t[best]]) best = i;
      const double mean = (vdist[t[0]] + vdist[t[1]] + vdist[t[2]]) / 3;
      const bool reached = std::isfinite(mean) && mean <= cutoff;
      result.face_distance[in] = reached ? mean : std::numeric_limits<double>::infinity();
      result.face_source[in] = reached ? vlabel[t[best]] : kInvalidIndex;
    }
  }
  if (options.want_face_sources) {
    result.face_sources.resize(nf);
    for (std::size_t fi = 0; fi < nf; ++fi) {
      const FaceRecord<Real>& st = state[fi];
      if (!st.reached()) continue;
      VirtualSource& vs = result.face_sources[layout.face_order[fi]];
      vs.position = detail::canonical_to_3d(mesh, Index(fi), double(st.sx) * mean_edge, double(st.sy) * mean_edge);
      vs.sigma = double(st.sigma) * mean_edge;
      vs.source = st.source();
    }
  }
  return result;
}

GeodesicResult geodesic_distances(const TriangleMesh& mesh, const std::vector<Source>& sources,
                                  const GeodesicOptions& options, const SolverOptions& solver_options) {
  return GeodesicSolver(mesh, solver_options).compute(sources, options);
}

}  // namespace gsp
