#pragma once
// The solver's prepared state (GeodesicSolver::Impl) and the pieces its queries share; internal
// to libgsp. geodesic_solver.cpp builds it and runs full queries, local_query.cpp runs the
// bounded ones; query_seed.hpp and query_propagate.hpp hold the seeding and propagation both use.
#include "corner_values.hpp"
#include "face_frames.hpp"
#include "flip_replay.hpp"
#include "goal_directed.hpp"
#include "index_maps.hpp"
#include "intrinsic_geometry.hpp"
#include "parallel_ranges.hpp"
#include "prefetch_corners.hpp"
#include "queue_strategies.hpp"
#include "straight_line_bound.hpp"
#include "window_bounds.hpp"

#include <gsp/connectivity.hpp>
#include <gsp/geodesics.hpp>
#include <gsp/intrinsic/vertex_kinds.hpp>

#include <atomic>
#include <cmath>
#include <limits>
#include <memory>
#include <mutex>
#include <type_traits>
#include <utility>
#include <vector>

namespace gsp {

using detail::FaceRecord;
using detail::QueueEntry;

// A vertex source's exact value at its own vertex (a vertex in no usable face still gets it).
struct VertexSeed {
  Index vertex;   // layout order
  double value;   // model units
  Index label;
};

// One triangulation the propagation can run on: the input's faces, or their intrinsic
// Delaunay flip (same vertices, same surface, better-shaped triangles).
struct Triangulation {
  // The corners of each face: the flip's own; the input's are the mesh's (not copied).
  std::vector<Triangle> own_triangles;
  const std::vector<Triangle>* mesh_triangles = nullptr;
  const std::vector<Triangle>& triangles() const { return mesh_triangles ? *mesh_triangles : own_triangles; }
  std::vector<double> length;             // per halfedge, model units
  std::vector<Index> ring;                // radial links with direction bits (ring_links.hpp)
  std::vector<Index> corner_begin, corners;   // vertex -> its corners (3f + i), CSR
  bool needs_double = false;              // a face too thin for float lengths (Precision::automatic)
  bool delaunay = false;                  // intrinsic Delaunay (flipped, or the input needed no flip)
  // Per face, what carried windows ask (window_face_flags(), window_corners.hpp); empty where
  // no vertex bounds a window.
  std::vector<std::uint8_t> window_flags;

  mutable std::atomic<bool> float_started{false}, double_started{false};   // a full query began
  mutable std::once_flag float_once, double_once;
  mutable detail::RecordArray<float> records_float;
  mutable detail::RecordArray<double> records_double;

  // The per-face records every query starts from (lengths, flat and saddle corners, nothing
  // reached); `threads` fill (and fault in) one part each.
  template <class Real>
  detail::RecordArray<Real> initial_records(double scale, const std::vector<std::uint8_t>& kind,
                                            unsigned threads = 1) const {
    const Real inf = std::numeric_limits<Real>::infinity();
    const std::vector<Triangle>& tris = triangles();
    detail::RecordArray<Real> r(tris.size());   // uninitialised: written once below
    detail::for_ranges(threads, tris.size(), [&](std::size_t begin, std::size_t end, unsigned) {
      for (std::size_t f = begin; f < end; ++f) {
        const Triangle& t = tris[f];
        Index tag = detail::kNoSource;
        for (Index i = 0; i < 3; ++i) {
          const std::uint8_t k = kind[t[i]];
          if (k == detail::kFlatVertex || k == detail::kConvexVertex) tag |= detail::kFlatCorner0 << i;
          if (k == detail::kSaddleVertex || k == detail::kConvexVertex) tag |= detail::kSaddleCorner0 << i;
        }
        r[f] = {0, 0, inf, inf, {Real(scale * length[3 * f]), Real(scale * length[3 * f + 1]),
                                 Real(scale * length[3 * f + 2])}, tag};
      }
    });
    return r;
  }

  // A query's starting state. The first full query of a precision builds it directly; from
  // the second on, a kept copy of the records is copied (a copy is cheaper than a build, and
  // a one-shot run never holds the records twice: 32 bytes per face less at its peak).
  template <class Real>
  void fill_state(detail::RecordArray<Real>& state, double scale, const std::vector<std::uint8_t>& kind,
                  unsigned threads = 1) const {
    constexpr bool single = std::is_same_v<Real, float>;
    std::atomic<bool>& started = single ? float_started : double_started;
    if (!started.exchange(true)) {
      state = initial_records<Real>(scale, kind, threads);
      return;
    }
    const auto& records = [&]() -> const detail::RecordArray<Real>& {
      if constexpr (single) {
        std::call_once(float_once, [&] { records_float = initial_records<float>(scale, kind); });
        return records_float;
      } else {
        std::call_once(double_once, [&] { records_double = initial_records<double>(scale, kind); });
        return records_double;
      }
    }();
    state.resize(records.size());
    detail::for_ranges(threads, records.size(), [&](std::size_t begin, std::size_t end, unsigned) {
      std::copy(records.begin() + std::ptrdiff_t(begin), records.begin() + std::ptrdiff_t(end),
                state.begin() + std::ptrdiff_t(begin));
    });
  }

  // Takes the plain radial links (halfedge indices) and adds the direction bits in place.
  // threads > 1: the links in ranges on that many threads, written apart from the plain ones
  // (a copy of the table while it runs, where one thread rewrites it in place).
  void set_direction_bits(std::vector<Index>&& plain_ring, unsigned threads = 1) {
    const std::vector<Triangle>& tris = triangles();
    auto dir = [&](Index h) { return tris[face_of(h)][corner_of(h)] < tris[face_of(h)][corner_of(next_halfedge(h))]; };
    auto link = [&](Index h, Index g, Index back) { return detail::ring_link(h, g, g != h && back == h, dir); };
    if (detail::ranges_used(threads, plain_ring.size()) > 1) {
      const std::vector<Index> plain = std::move(plain_ring);
      ring.resize(plain.size());
      detail::for_ranges(threads, plain.size(), [&](std::size_t begin, std::size_t end, unsigned) {
        for (Index h = Index(begin); h < Index(end); ++h) {
          if (h + detail::kHalfedgesAhead < end) {   // the partner's link and corners ahead
            const Index g = plain[h + detail::kHalfedgesAhead];
            __builtin_prefetch(plain.data() + g);
            __builtin_prefetch(tris.data() + face_of(g));
          }
          ring[h] = link(h, plain[h], plain[plain[h]]);
        }
      });
      return;
    }
    ring = std::move(plain_ring);
    // Links before h already carry bits: masked, every entry reads as its plain index.
    for (Index h = 0; h < Index(ring.size()); ++h) {
      if (h + detail::kHalfedgesAhead < Index(ring.size())) {
        const Index ahead = ring[h + detail::kHalfedgesAhead] & detail::kRingIndexMask;
        __builtin_prefetch(ring.data() + ahead);
        __builtin_prefetch(tris.data() + face_of(ahead));
      }
      const Index g = ring[h] & detail::kRingIndexMask;
      ring[h] = link(h, g, ring[g] & detail::kRingIndexMask);
    }
  }

  void build_corners(std::size_t num_vertices) {
    corner_begin.assign(num_vertices + 1, 0);
    const std::vector<Triangle>& tris = triangles();
    for (std::size_t f = 0; f < tris.size(); ++f) {
      detail::prefetch_corners(tris, corner_begin, f);   // v + 1: the same line or the next
      for (Index v : tris[f]) ++corner_begin[v + 1];
    }
    for (std::size_t v = 0; v < num_vertices; ++v) corner_begin[v + 1] += corner_begin[v];
    corners.resize(3 * tris.size());
    std::vector<Index> fill(corner_begin.begin(), corner_begin.end() - 1);
    for (Index f = 0; f < Index(tris.size()); ++f) {
      detail::prefetch_corners(tris, fill, f);
      for (Index i = 0; i < 3; ++i) corners[fill[tris[f][i]]++] = 3 * f + i;
    }
  }
};

struct GeodesicSolver::Impl {
  detail::IndexMaps maps;          // input <-> memory order
  // In memory order: a laid-out copy, or the caller's mesh itself when it keeps its order.
  std::shared_ptr<const TriangleMesh> mesh_store;
  bool owns_mesh = false;          // mesh_store holds a mesh no caller sees (release_mesh may move it)
  const TriangleMesh& mesh() const { return *mesh_store; }
  Triangulation input;             // the (reordered) input faces
  std::unique_ptr<Triangulation> delaunay;   // their intrinsic Delaunay flip, if it changed anything
  // With `delaunay`: its flips, to find a point of an input face on it (flip_replay.hpp);
  // made by flip_replay() at the first query that needs it.
  mutable std::once_flag replay_once;
  mutable std::unique_ptr<detail::FlipReplay> replay;
  const detail::FlipReplay& flip_replay() const;
  // With `delaunay`: where each input face lies on it (face_frames.hpp); made by face_frames()
  // at the first query that asks for fitted per-face sources (up to four 56-byte frames per
  // face a flip rewrote).
  mutable std::once_flag frames_once;
  mutable std::unique_ptr<detail::FaceFrames> frames;
  const detail::FaceFrames& face_frames() const;
  std::size_t flips = 0;
  std::vector<bool> skipped_face;  // faces that repeat a vertex or copy another: not part of the propagation
  std::size_t duplicate_faces = 0;  // of them, copies (intrinsic::skip_duplicate_faces)
  // Each copy and the face kept for it, input face indices: the gather gives a copy its
  // original's values (found once here, not per query).
  std::vector<std::pair<Index, Index>> face_copies;
  // Vertices whose incident faces form several edge-connected fans (bow-ties, welded soups):
  // a wavefront reaching such a vertex continues into its other fans from the vertex itself.
  std::vector<Index> bridge_vertices;
  // Vertices joined by zero-length edges (distinct vertices at one point: CAD exports, compound
  // models): one point of the surface. A zero-length edge has no direction, so no face frame
  // can be unfolded across it (the two faces' frames would be rotated arbitrarily against each
  // other: distances down to 0 far from the source); it carries no propagation, and each group
  // passes the front on like a bridge vertex. CSR: group g is coincident[coincident_begin[g]..).
  std::vector<Index> coincident_begin{0}, coincident;
  std::vector<std::uint8_t> vertex_kind;   // per vertex: flat, saddle or neither (intrinsic_geometry.hpp)
  // Vertices that bound carried windows (window_corners.hpp); 0: the queries carry none. The
  // per-vertex marks (window_corner) go once the triangulations' window_flags are made.
  std::size_t window_corner_count = 0;
  std::vector<std::uint8_t> window_corner;
  double mean_edge = 1;
  bool custom_lengths = false;     // SolverOptions::edge_lengths given
  // How 3D bounds the lengths: 1 for 3D lengths, SolverOptions::edge_lengths_line_scale for
  // caller-supplied ones (0: not at all, no straight-line bound or test).
  double line_scale = 1;
  // The vertices in 3D times line_scale, for the straight-line bound (straight_line_bound.hpp);
  // empty when line_scale is 1 (mesh().positions serve) or 0.
  std::vector<Vec3> scaled_vertex_positions;
  const std::vector<Vec3>& line_bound_positions() const {
    return scaled_vertex_positions.empty() ? mesh().positions : scaled_vertex_positions;
  }
  // The same for the update step's straight-line test (mean edges from line_centre, floats);
  // empty when line_scale is 0.
  std::vector<float> line_positions;
  Vec3 line_centre;
  VisibilityHeuristic heuristic;
  SolverTimings timings;

  // The state buffer of the last finished full query, kept for the next one: refilling a
  // buffer whose pages are mapped costs a copy; a fresh one also costs a page fault per 4 KiB
  // (about 5% of a query on a large mesh). One per precision, so a pool of concurrent
  // queries (compute_many) keeps at most one extra buffer.
  struct SpareState {
    std::mutex mutex;
    detail::RecordArray<float> single;
    detail::RecordArray<double> twice;
  };
  mutable SpareState spare;
  template <class Real>
  detail::RecordArray<Real> take_state(const Triangulation& tri, unsigned threads = 1) const {
    detail::RecordArray<Real> state;
    {
      std::lock_guard<std::mutex> lock(spare.mutex);
      if constexpr (std::is_same_v<Real, float>) state.swap(spare.single); else state.swap(spare.twice);
    }
    tri.fill_state(state, 1.0 / mean_edge, vertex_kind, threads);
    return state;
  }
  template <class Real>
  void return_state(detail::RecordArray<Real>&& state) const {
    std::lock_guard<std::mutex> lock(spare.mutex);
    if constexpr (std::is_same_v<Real, float>) spare.single = std::move(state); else spare.twice = std::move(state);
  }

  // `requested` with Precision::automatic resolved for a query on `tri`.
  static Precision precision_on(const Triangulation& tri, Precision requested) {
    if (requested != Precision::automatic) return requested;
    return tri.needs_double ? Precision::double_precision : Precision::single;
  }
  // `owned`: the caller's mesh, handed over (GeodesicSolver(TriangleMesh&&)); laid out in place.
  void build(const TriangleMesh& given, std::shared_ptr<const TriangleMesh> shared, const SolverOptions& options,
             TriangleMesh* owned = nullptr);
  // The input triangulation: skipped faces, lengths (and the mean edge) from the mesh alone,
  // then the radial links from the connectivity.
  void build_lengths(const std::vector<double>& edge_lengths);
  void build_links(const Connectivity& conn, unsigned threads);
  // Bridge and coincident vertices, vertex kinds; hands the vertex corners to the input
  // triangulation and releases the rest of `conn`.
  void analyse_vertices(Connectivity& conn, intrinsic::CornerAngleSums&& angle_sums);
  void build_delaunay(bool two_threads);
  detail::IntrinsicTriangulation unflipped() const;   // the input's tables as the flips start from them
  std::size_t flip_cap() const;
  template <class Real>
  GeodesicResult run(const Triangulation& tri, const std::vector<Source>& sources,
                     const GeodesicOptions& options) const;
  template <class Real>
  LocalField run_local(const std::vector<Source>& sources, const GeodesicOptions& options,
                       LocalWorkspace& workspace) const;

  // A full query's gather (query_gather.hpp): vertex_minima() takes each vertex's smallest
  // value over its reached faces (returns the number of faces reached); gather() writes the
  // result in the input's order, the vertex sources' exact values on top.
  template <class Real>
  std::size_t vertex_minima(const Triangulation& tri, const FaceRecord<Real>* state, std::vector<Real>& vmin,
                            std::vector<Index>& vlabel, unsigned threads = 1) const;
  template <class Real>
  void gather(const Triangulation& tri, const FaceRecord<Real>* state, const std::vector<VertexSeed>& vertex_seeds,
              bool relax, const GeodesicOptions& options, const std::vector<Real>& vmin, std::vector<Index>& vlabel,
              GeodesicResult& result, unsigned threads = 1,
              const std::vector<detail::SourcePoint>* points = nullptr) const;
  // After a run on the intrinsic Delaunay faces: each input face's virtual source fitted to
  // its corners' values (fitted_face_sources.hpp); result.vertex_distance / vertex_source
  // must be filled. `points`: the sources in 3D (source_points_for), for the straight-line
  // bound; none (empty) leaves it out.
  template <class Real>
  void fitted_face_sources(const FaceRecord<Real>* state, GeodesicResult& result, unsigned threads,
                           const std::vector<detail::SourcePoint>& points) const;

  // The steps every query shares (query_seed.hpp, query_propagate.hpp). seed(): seeds the
  // faces of the sources (checked before: validate_sources.hpp); vertex sources also give
  // their vertex's exact value (vertex_seeds, one per vertex in vertex order). Faces
  // seeded are appended to `seeded` when given. propagate(): the chosen strategy, then the
  // bridge vertices' rounds; faces reached for the first time are appended to `reached`
  // when given.
  template <class Real>
  void seed(const Triangulation& tri, const std::vector<Source>& sources, FaceRecord<Real>* state,
            std::vector<QueueEntry<Real>>& queue, std::vector<VertexSeed>& vertex_seeds,
            detail::TargetSet<Real>* goal, std::vector<Index>* seeded) const;
  // After the first propagation and gather: vertices lowered along the input's edges seed their
  // fans as pseudo-sources and the propagation resumes, until no edge lowers a vertex by more
  // than kPseudoSourceGain (vertex_relaxation.hpp). Later rounds look only at the faces the
  // resumed propagation changed and the edges at their corners.
  template <class Real>
  void relax_vertices(const Triangulation& tri, const GeodesicOptions& options, FaceRecord<Real>* state,
                      std::vector<QueueEntry<Real>>& queue, std::vector<Real>& vmin, std::vector<Index>& vlabel,
                      PropagationStats& stats, const float* line_sources, detail::WindowRecord<Real>* windows,
                      unsigned threads = 1) const;
  // Seeds the fans of `vertices` with a virtual source at the vertex, sigma = d[v] *
  // to_normalised; the faces that took it go to `changed` (and the queue), every face offered
  // one to `touched` when given.
  template <class Real, class Value>
  void seed_pseudo_sources(const Triangulation& tri, const std::vector<Index>& vertices, const std::vector<Value>& d,
                           double to_normalised, const std::vector<Index>& label, FaceRecord<Real>* state,
                           std::vector<QueueEntry<Real>>& queue, std::vector<Index>& changed,
                           std::vector<Index>* touched) const;
  // The same for a bounded query (local_query.cpp), in model units on the workspace's vertex
  // values: starts from the vertices the query reached, lists every vertex and face it adds.
  struct LocalValues {
    std::vector<double>& vdist;
    std::vector<Index>& vlabel;
    std::vector<Index>& vertices;       // vertices with a value (to report and reset)
    std::vector<Index>& faces;          // faces reached (to report and reset)
    std::vector<std::uint8_t>& face_mark;
    std::vector<Index>& seeded;         // faces to reset
    // Lowers vertex v to d (label) if that is lower, listing it the first time it gets a value.
    void touch(Index v, double d, Index label) const {
      if (vdist[v] == std::numeric_limits<double>::infinity()) vertices.push_back(v);
      if (d < vdist[v]) vdist[v] = d, vlabel[v] = label;
    }
  };
  // A bounded query's gather (query_gather.hpp): gather_reached() lists the faces the
  // propagation reached and gives their corners and the vertex sources their values;
  // gather_local() writes the sparse result (what lies within max_distance) in input indices.
  template <class Real>
  void gather_reached(const FaceRecord<Real>* state, const std::vector<VertexSeed>& vertex_seeds,
                      LocalValues values) const;
  template <class Real>
  void gather_local(const FaceRecord<Real>* state, const LocalValues& values, const GeodesicOptions& options,
                    LocalField& result) const;
  template <class Real>
  void relax_local(const GeodesicOptions& options, FaceRecord<Real>* state, std::vector<QueueEntry<Real>>& queue,
                   LocalValues values, PropagationStats& stats, const float* line_sources,
                   detail::WindowRecord<Real>* windows) const;
  // line_sources: the query's sources for the update step's straight-line test
  // (line_sources_for(); null: no test). windows: the query's carried windows, one per face
  // (window_records(); null: none).
  template <class Real>
  void propagate(const Triangulation& tri, const GeodesicOptions& options, FaceRecord<Real>* state,
                 std::vector<QueueEntry<Real>>& queue, detail::TargetSet<Real>* goal, PropagationStats& stats,
                 std::vector<Index>* seeded, std::vector<Index>* reached, const float* line_sources,
                 detail::WindowRecord<Real>* windows, bool every_update = false) const;
  // A query's sources in 3D (straight_line_bound.hpp), for the bound and the update step's
  // test: empty with caller-supplied lengths or with both switched off.
  std::vector<detail::SourcePoint> source_points_for(const std::vector<Source>& sources,
                                                     const GeodesicOptions& options) const;
  // The same as the update step's test reads them; empty where the test is off.
  std::vector<float> line_sources_for(const std::vector<detail::SourcePoint>& points,
                                      const GeodesicOptions& options) const;
  // A query's carried windows (window_bounds.hpp), one per face, none written yet; none where
  // the query has none: no vertex bounds a window, or GeodesicOptions::carried_windows is off.
  template <class Real>
  detail::WindowStore<Real> window_records(const GeodesicOptions& options) const {
    if (window_corner_count == 0 || !options.carried_windows) return {};
    return detail::WindowStore<Real>(mesh().num_faces());
  }
};

// Seeds face f with a source at barycentric point b of the face (canonical coordinates are
// exact for a point of the face itself); `offset` in normalised units.
template <class Real>
inline bool seed_face(const std::vector<double>& length, Index f, const double b[3], double scale, double offset,
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

inline const double kCornerWeights[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};

}  // namespace gsp
