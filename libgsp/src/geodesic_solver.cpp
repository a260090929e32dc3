#include "intrinsic_delaunay.hpp"
#include "query_steps.hpp"
#include "side_by_side.hpp"
#include "solver_impl.hpp"
#include "straight_line_bound.hpp"
#include "validate_options.hpp"
#include "vertex_relaxation.hpp"
#include "virtual_source.hpp"

#include <gsp/connectivity.hpp>
#include <gsp/errors.hpp>
#include <gsp/geodesics.hpp>
#include <gsp/intrinsic/bridge_vertices.hpp>
#include <gsp/topology.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

namespace gsp {


void GeodesicSolver::Impl::build_lengths(const std::vector<double>& edge_lengths) {
  skipped_face.assign(mesh().num_faces(), false);
  for (std::size_t f = 0; f < mesh().num_faces(); ++f) {
    const Triangle& t = mesh().triangles[f];
    skipped_face[f] = repeats_vertex(t);
  }
  input.mesh_triangles = &mesh().triangles;
  if (edge_lengths.empty()) {
    input.length = detail::halfedge_lengths(mesh());
  } else {
    // Given in input face order; the layout moves whole faces (corners keep their order).
    input.length.resize(edge_lengths.size());
    for (std::size_t f = 0; f < mesh().num_faces(); ++f)
      for (int i = 0; i < 3; ++i) input.length[3 * f + i] = edge_lengths[3 * std::size_t(maps.face_to_input(Index(f))) + i];
  }
  detail::snap_zero_lengths(input.length);
  input.needs_double = detail::needs_double_lengths(input.length, skipped_face);
  mean_edge = detail::mean_edge_length(input.length, skipped_face);
}

void GeodesicSolver::Impl::build_links(const Connectivity& conn) {
  const std::size_t nh = conn.num_halfedges();
  if (nh > detail::kRingIndexMask) throw InvalidInput("mesh too large: more than 2^29 - 1 halfedges");
  // A halfedge of a skipped face, a loop or a zero-length edge is a ring of its own; the
  // others link to the next member of their radial ring that is not in a skipped face
  // (itself on a boundary). One pass in halfedge order, no per-edge lists.
  std::vector<Index> plain(nh);
  for (Index h = 0; h < nh; ++h) {
    const Index e = conn.halfedge_edge[h];
    Index next = h;
    if (e != kInvalidIndex && !skipped_face[face_of(h)] && !detail::zero_length_edge(input.length, conn.edge_halfedge[e])) {
      next = conn.radial_next[h];
      while (next != h && skipped_face[face_of(next)]) next = conn.radial_next[next];
    }
    plain[h] = next;
  }
  input.set_direction_bits(std::move(plain));
}

void GeodesicSolver::Impl::build_delaunay(bool two_threads) {
  detail::IntrinsicTriangulation t;
  t.triangles = input.triangles();
  t.length = input.length;
  t.skipped = skipped_face;
  t.positions = &mesh().positions;   // picks each patch's winding (intrinsic_delaunay.hpp)
  t.ring.resize(input.ring.size());
  for (std::size_t h = 0; h < t.ring.size(); ++h) t.ring[h] = input.ring[h] & detail::kRingIndexMask;
  // A generous cap: Delaunay flipping ends after finitely many flips, but float-stored slivers
  // can make near-ties flip back and forth; the result is good long before the cap.
  flips = detail::make_intrinsic_delaunay(t, 20 * t.length.size());
  if (flips == 0 && t.reoriented == 0) return;   // a soup needing no flips still gets one winding
  delaunay = std::make_unique<Triangulation>();
  delaunay->own_triangles = std::move(t.triangles);
  delaunay->length = std::move(t.length);
  // Three tables from the flipped faces, two of them apart from the third.
  Triangulation& d = *delaunay;
  auto lengths_and_corners = [&] {
    detail::snap_zero_lengths(d.length);
    d.needs_double = detail::needs_double_lengths(d.length, skipped_face);
    d.build_corners(mesh().num_vertices());
  };
  auto links = [&] { d.set_direction_bits(std::move(t.ring)); };
  if (two_threads) {
    detail::side_by_side(lengths_and_corners, links);
  } else {
    lengths_and_corners();
    links();
  }
}

void GeodesicSolver::Impl::find_coincident_vertices(const Connectivity& conn) {
  // Union the ends of every zero-length edge of a face that takes part.
  std::vector<Index> parent;   // over the vertices met, by a map to local ids
  std::vector<Index> local(mesh().num_vertices(), kInvalidIndex), vertex;
  auto id = [&](Index v) {
    if (local[v] == kInvalidIndex) local[v] = Index(vertex.size()), vertex.push_back(v), parent.push_back(local[v]);
    return local[v];
  };
  auto find = [&](Index x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for (Index e = 0; e < conn.num_edges(); ++e) {
    const Index h = conn.edge_halfedge[e];
    if (skipped_face[face_of(h)] || !detail::zero_length_edge(input.length, h)) continue;
    const Index a = id(from_vertex(mesh(), h)), b = id(to_vertex(mesh(), h));
    const Index ra = find(a), rb = find(b);
    if (ra != rb) parent[ra] = rb;
  }
  if (vertex.empty()) return;
  std::vector<std::vector<Index>> groups(vertex.size());
  for (Index i = 0; i < Index(vertex.size()); ++i) groups[find(i)].push_back(vertex[i]);
  for (const auto& g : groups) {
    if (g.size() < 2) continue;
    coincident.insert(coincident.end(), g.begin(), g.end());
    coincident_begin.push_back(Index(coincident.size()));
  }
}

void GeodesicSolver::Impl::analyse_vertices(Connectivity& conn) {
  bridge_vertices = intrinsic::bridge_vertices(mesh(), conn, skipped_face);
  find_coincident_vertices(conn);
  // Plus the ends of edges with > 2 faces and the coincident vertices: no single angle sum.
  std::vector<Index> nonmanifold = bridge_vertices;
  nonmanifold.insert(nonmanifold.end(), coincident.begin(), coincident.end());
  for (Index e = 0; e < conn.num_edges(); ++e)
    if (conn.ring_size(conn.edge_halfedge[e]) > 2) {
      nonmanifold.push_back(from_vertex(mesh(), conn.edge_halfedge[e]));
      nonmanifold.push_back(to_vertex(mesh(), conn.edge_halfedge[e]));
    }
  // The connectivity's vertex corners are the input triangulation's; the rest goes before the
  // Delaunay triangulation is complete (the run's peak of memory).
  input.corner_begin = std::move(conn.vertex_corner_begin);
  input.corners = std::move(conn.vertex_corners);
  conn = Connectivity();
  std::vector<std::uint8_t> boundary_halfedge(input.ring.size());
  for (std::size_t h = 0; h < boundary_halfedge.size(); ++h)
    boundary_halfedge[h] = (input.ring[h] & detail::kRingIndexMask) == h;
  vertex_kind = intrinsic::vertex_kinds(mesh(), boundary_halfedge, skipped_face, nonmanifold,
                                        custom_lengths ? &input.length : nullptr);
}

GeodesicSolver::GeodesicSolver(const TriangleMesh& input, const SolverOptions& options)
    : impl_(std::make_unique<Impl>()) {
  impl_->build(input, nullptr, options);
}

GeodesicSolver::GeodesicSolver(std::shared_ptr<const TriangleMesh> input, const SolverOptions& options)
    : impl_(std::make_unique<Impl>()) {
  if (!input) throw InvalidInput("GeodesicSolver: no mesh (null pointer)");
  const TriangleMesh& mesh = *input;
  impl_->build(mesh, std::move(input), options);
}

void GeodesicSolver::Impl::build(const TriangleMesh& input, std::shared_ptr<const TriangleMesh> shared,
                                 const SolverOptions& options) {
  using Clock = std::chrono::steady_clock;
  validate(input);
  if (!options.edge_lengths.empty()) detail::validate_halfedge_lengths(input, options.edge_lengths);
  auto t0 = Clock::now();
  custom_lengths = !options.edge_lengths.empty();
  heuristic = options.heuristic;
  if (options.optimize_layout) {
    Layout layout = compute_cache_layout(input);
    mesh_store = std::make_shared<const TriangleMesh>(apply_layout(input, layout));
    maps = detail::IndexMaps(std::move(layout));
  } else {
    mesh_store = shared ? std::move(shared) : std::make_shared<const TriangleMesh>(input);
  }
  const auto t1 = Clock::now();
  auto lap = [last = t1]() mutable {
    const auto now = Clock::now();
    const double s = std::chrono::duration<double>(now - last).count();
    last = now;
    return s;
  };
  // On a big mesh two threads: the connectivity beside the lengths, then the vertices'
  // analysis beside the Delaunay flips (each pair reads the same tables and writes apart).
  const bool two = options.threads != 1 && (options.threads >= 2 || (mesh().num_faces() >= kParallelMinFaces &&
                                                                       std::thread::hardware_concurrency() >= 2 &&
                                                                       !detail::inside_parallel_region()));
  Connectivity conn;
  if (!two) {
    conn = build_connectivity(mesh());
    timings.connectivity = lap();
    build_lengths(options.edge_lengths);
  } else {
    detail::side_by_side([&] { build_lengths(options.edge_lengths); },
                         [&] {
                           conn = build_connectivity(mesh());
                           timings.connectivity = lap();
                         });
  }
  build_links(conn);
  timings.input_tables = lap();
  if (!two || !options.intrinsic_delaunay) {
    analyse_vertices(conn);
    timings.vertex_analysis = lap();
    if (options.intrinsic_delaunay) build_delaunay(false);
    timings.delaunay = lap();
  } else {
    detail::side_by_side(
        [&] {
          const auto start = Clock::now();
          analyse_vertices(conn);
          timings.vertex_analysis = std::chrono::duration<double>(Clock::now() - start).count();
        },
        [&] {
          build_delaunay(true);   // its last tables on two threads too (the analysis ends first)
          timings.delaunay = lap();
        });
  }
  const auto t2 = Clock::now();
  timings.layout = std::chrono::duration<double>(t1 - t0).count();
  timings.build = std::chrono::duration<double>(t2 - t1).count();
}

GeodesicSolver::~GeodesicSolver() = default;
GeodesicSolver::GeodesicSolver(GeodesicSolver&&) noexcept = default;
GeodesicSolver& GeodesicSolver::operator=(GeodesicSolver&&) noexcept = default;

std::size_t GeodesicSolver::num_vertices() const { return impl_->mesh().num_vertices(); }
std::size_t GeodesicSolver::num_faces() const { return impl_->mesh().num_faces(); }
Index GeodesicSolver::face_memory_rank(Index face) const { return impl_->maps.face_to_layout(face); }
const SolverTimings& GeodesicSolver::timings() const { return impl_->timings; }
std::size_t GeodesicSolver::intrinsic_flips() const { return impl_->flips; }

bool GeodesicSolver::needs_double() const {
  return (impl_->delaunay ? *impl_->delaunay : impl_->input).needs_double;
}

Precision GeodesicSolver::resolved_precision(Precision requested, bool input_faces) const {
  return impl_->precision_on(input_faces || !impl_->delaunay ? impl_->input : *impl_->delaunay, requested);
}

std::size_t GeodesicSolver::state_bytes(Precision precision) const {
  // Per face one record (source, distances, edge lengths); per halfedge one radial link.
  const std::size_t nf = impl_->mesh().num_faces();
  const std::size_t record =
      resolved_precision(precision) == Precision::single ? sizeof(FaceRecord<float>) : sizeof(FaceRecord<double>);
  return nf * record + impl_->input.ring.size() * sizeof(Index);
}

GeodesicResult GeodesicSolver::compute(const std::vector<Source>& sources,
                                       const GeodesicOptions& options) const {
  detail::validate_options(options, detail::QueryKind::full, impl_->custom_lengths, impl_->mesh().num_vertices());
  // The intrinsic Delaunay faces are not the input's: a point given in an input face and the
  // per-face virtual sources need the input faces.
  bool vertex_sources_only = true;
  for (const Source& s : sources) vertex_sources_only &= s.kind == Source::Kind::vertex;
  const bool use_delaunay = impl_->delaunay && vertex_sources_only && !options.want_face_sources;
  const Triangulation& tri = use_delaunay ? *impl_->delaunay : impl_->input;
  if (impl_->precision_on(tri, options.precision) == Precision::single) return impl_->run<float>(tri, sources, options);
  return impl_->run<double>(tri, sources, options);
}

template <class Real>
GeodesicResult GeodesicSolver::Impl::run(const Triangulation& tri, const std::vector<Source>& sources,
                                         const GeodesicOptions& options) const {
  const std::size_t nf = mesh().num_faces(), nv = mesh().num_vertices();
  const double scale = 1.0 / mean_edge;
  std::vector<FaceRecord<Real>> state = take_state<Real>(tri);   // this query's copy

  GeodesicResult result;
  result.stats.mean_edge_length = mean_edge;
  result.stats.double_precision = std::is_same_v<Real, double>;
  std::vector<QueueEntry<Real>> queue;
  queue.reserve(std::max<std::size_t>(64, nf / 4));
  std::optional<detail::TargetSet<Real>> goal;   // only for runs with targets
  if (!options.targets.empty()) {
    std::vector<Index> targets(options.targets.size());
    for (std::size_t i = 0; i < targets.size(); ++i) targets[i] = maps.vertex_to_layout(options.targets[i]);
    goal.emplace(state.data(), tri.triangles(), mesh().positions, tri.corner_begin, tri.corners, targets, scale,
                 options.goal_directed);
  }

  std::vector<VertexSeed> vertex_seeds;
  seed<Real>(tri, sources, state.data(), queue, vertex_seeds, goal ? &*goal : nullptr, nullptr);
  result.stats.enqueued = queue.size();
  propagate<Real>(tri, options, state.data(), queue, goal ? &*goal : nullptr, result.stats, nullptr, nullptr);

  // Per-vertex: the smallest sigma + |corner - virtual source| over the incident reached faces,
  // taken in the propagation's precision (the conversion to model units is monotonic, so the
  // minimum and its label are those of the converted values). Per block of faces two passes:
  // the corner distances, branch-free so the compiler vectorises them (an unreached face has
  // sigma = +inf and gives +inf), then the minima, also without branches: which face wins a
  // vertex is a coin toss the branch predictor loses.
  const Real inf = std::numeric_limits<Real>::infinity();
  std::vector<Real> vmin(nv, inf);
  std::vector<Index> vlabel(nv, kInvalidIndex);
  std::size_t faces_reached = 0;
  constexpr std::size_t kBlock = 256;
  Real corner[3 * kBlock];
  for (std::size_t begin = 0; begin < nf; begin += kBlock) {
    const std::size_t end = std::min(nf, begin + kBlock);
    corner_distances(&state[begin], end - begin, corner);
    for (std::size_t fi = begin; fi < end; ++fi) {
      const bool reached = state[fi].reached();
      faces_reached += reached;
      const Index label = reached ? state[fi].source() : kInvalidIndex;
      const Triangle& t = tri.triangles()[fi];
      for (Index i = 0; i < 3; ++i) {
        const Real d = corner[3 * (fi - begin) + i];
        const bool better = d < vmin[t[i]];
        vmin[t[i]] = better ? d : vmin[t[i]];
        vlabel[t[i]] = better ? label : vlabel[t[i]];
      }
    }
  }
  // A targeted run stops once its targets are final: a resumed propagation would not.
  const bool relax = !goal && options.vertex_relaxation;
  if (relax) {
    // The vertex sources are where the edge paths start.
    for (const VertexSeed& vs : vertex_seeds)
      if (Real(vs.value * scale) < vmin[vs.vertex])
        vmin[vs.vertex] = Real(vs.value * scale), vlabel[vs.vertex] = vs.label;
    relax_vertices<Real>(tri, options, state.data(), queue, vmin, vlabel, result.stats);
  }
  // Last on the values: nothing below the straight line (straight_line_bound.hpp), in layout
  // order (positions and values read in sequence).
  if (options.straight_line_bound && !custom_lengths)
    result.stats.raised_to_line = detail::raise_to_straight_line<Real>(
        nv, nullptr, mesh().positions, vmin.data(), vlabel.data(), mean_edge, true,
        detail::source_points(mesh(), maps, sources));
  result.stats.faces_reached = faces_reached;
  // A vertex source's own value is exact and wins ties against the faces; of several sources
  // at one vertex the smallest value, the first source on ties.
  std::vector<VertexSeed> seeds = vertex_seeds;
  std::stable_sort(seeds.begin(), seeds.end(), [](const VertexSeed& a, const VertexSeed& b) {
    return a.vertex != b.vertex ? a.vertex < b.vertex : a.value < b.value;
  });
  seeds.erase(std::unique(seeds.begin(), seeds.end(),
                          [](const VertexSeed& a, const VertexSeed& b) { return a.vertex == b.vertex; }),
              seeds.end());
  // Results in the input's order, gathered (sequential writes, reads in layout order), then the
  // few vertex sources on top.
  const double cutoff = options.max_distance;
  const double inf_d = std::numeric_limits<double>::infinity();
  result.vertex_distance.resize(nv);
  result.vertex_source.resize(nv);
  for (std::size_t in = 0; in < nv; ++in) {
    const Index v = maps.vertex_to_layout(Index(in));
    const double d = double(vmin[v]) * mean_edge;
    const bool keep = d <= cutoff;
    result.vertex_distance[in] = keep ? d : inf_d;
    result.vertex_source[in] = keep ? vlabel[v] : kInvalidIndex;
  }
  for (const VertexSeed& vs : seeds) {
    // Exact (model units) unless a face or an edge found the vertex closer; after relaxation
    // vmin holds the seed itself rounded to the propagation's precision.
    if (!(vs.value <= double(vmin[vs.vertex]) * mean_edge * (relax ? 1 + 1e-6 : 1.0))) continue;
    const Index in = maps.vertex_to_input(vs.vertex);
    const bool keep = vs.value <= cutoff;
    result.vertex_distance[in] = keep ? vs.value : inf_d;
    result.vertex_source[in] = keep ? vs.label : kInvalidIndex;
  }
  if (options.want_face_distances) {
    // On the flipped triangulation an input face's value comes from its corners' distances
    // (before the cutoff, the vertex sources included), by layout index.
    std::vector<double> vdist;
    if (&tri != &input) {
      vdist.resize(nv);
      for (std::size_t v = 0; v < nv; ++v) vdist[v] = double(vmin[v]) * mean_edge;
      for (const VertexSeed& vs : seeds)
        if (vs.value <= vdist[vs.vertex]) vdist[vs.vertex] = vs.value, vlabel[vs.vertex] = vs.label;
    }
    result.face_distance.resize(nf);
    result.face_source.resize(nf);
    for (std::size_t in = 0; in < nf; ++in) {
      const Index fi = maps.face_to_layout(Index(in));
      double d = std::numeric_limits<double>::infinity();
      Index label = kInvalidIndex;
      if (&tri == &input) {
        const FaceRecord<Real>& st = state[fi];
        if (st.reached()) d = double(st.dT) * mean_edge, label = st.source();
      } else {
        // The propagation ran on other faces: an input face gets the mean of its corners'
        // distances and the label of its nearest corner.
        const Triangle& t = mesh().triangles[fi];
        int best = 0;
        for (int i = 1; i < 3; ++i)
          if (vdist[t[i]] < vdist[t[best]]) best = i;
        const double mean = (vdist[t[0]] + vdist[t[1]] + vdist[t[2]]) / 3;
        if (std::isfinite(mean) && mean <= cutoff) d = mean, label = vlabel[t[best]];
      }
      result.face_distance[in] = d;
      result.face_source[in] = label;
    }
  }
  if (options.want_face_sources) {
    result.face_sources.resize(nf);
    for (std::size_t fi = 0; fi < nf; ++fi) {
      const FaceRecord<Real>& st = state[fi];
      if (!st.reached()) continue;
      VirtualSource& vs = result.face_sources[maps.face_to_input(Index(fi))];
      vs.position = detail::canonical_to_3d(mesh(), Index(fi), double(st.sx) * mean_edge, double(st.sy) * mean_edge);
      vs.sigma = double(st.sigma) * mean_edge;
      vs.source = st.source();
    }
  }
  return_state(std::move(state));
  return result;
}

GeodesicResult geodesic_distances(const TriangleMesh& mesh, const std::vector<Source>& sources,
                                  const GeodesicOptions& options, const SolverOptions& solver_options) {
  return GeodesicSolver(mesh, solver_options).compute(sources, options);
}

}  // namespace gsp
