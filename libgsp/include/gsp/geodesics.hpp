#pragma once
// Geodesic distances by Geodesic Source Propagation (GSP): virtual sources carried from face to
// face in an intrinsic parametrization (paper Sections 3 and 4.1), driven by a dual FIFO queue
// (Section 4.2) over a cache-coherent layout (Section 4.3).
//
//   auto result = gsp::geodesic_distances(mesh, {gsp::Source::at_vertex(0)});
//   result.vertex_distance[v]   // in the input's vertex order, +inf where unreachable
//
// For many queries on one mesh, build a GeodesicSolver once and call compute() repeatedly.
#include <gsp/heuristic.hpp>
#include <gsp/layout.hpp>
#include <gsp/mesh.hpp>
#include <gsp/surface_point.hpp>

#include <array>
#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

namespace gsp {

// A point source: a surface point (a vertex, or a point inside a face whose barycentric weights
// must be >= 0 and sum to 1 within 1e-6: gsp::are_barycentric) and an initial distance `offset`
// added to everything the source reaches. Built on gsp::SurfacePoint so that a source is any
// surface point plus its offset: s.kind, s.element (input order), s.barycentric are the point's.
struct Source : SurfacePoint {
  double offset = 0;

  static Source at_vertex(Index v, double offset = 0) { return {SurfacePoint::at_vertex(v), offset}; }
  static Source in_face(Index f, std::array<double, 3> bary, double offset = 0) {
    return {SurfacePoint::in_face(f, bary), offset};
  }
  static Source at(const SurfacePoint& p, double offset = 0) { return {p, offset}; }
};

// How the wavefront is scheduled (paper Section 4.2). All give the same distances up to the
// label-correcting fix point; they differ in speed.
enum class Strategy : std::uint8_t {
  // Default: enqueue in the current queue while d_T < f * i (lean queue); turns into
  // speed_limiter_postpone where a run stops being linear (queue_strategies.hpp, docs/gsp-core.md).
  speed_limiter,
  // The speed limiter that also postpones: an entry deferred to the next round and still
  // beyond that round's limit is deferred again, not expanded. Linear where the speed limiter
  // is not (midpoint-subdivided scans); docs/gsp-core.md, "Strategies".
  speed_limiter_postpone,
  static_postpone,   // skip (postpone) entries with d_T > f * i
  dynamic_postpone,  // skip entries with d_T > min_prev + f
  hybrid_postpone,   // skip entries with d_T > max(min_prev + f0, d_{i-1} + f1)
  bfs,               // topological order (for comparison)
  priority_queue,    // Dijkstra order on d_T, a binary heap (for comparison)
};

// `automatic` (the default) is single precision unless the triangulation the query runs on has
// a face whose shape float lengths cannot hold (GeodesicSolver::needs_double): CAD needles and
// caps, whose unfolding in float is off by more than the face itself (docs/gsp-core.md).
enum class Precision : std::uint8_t { single, double_precision, automatic };

// Meshes with fewer faces run a query on one thread unless GeodesicOptions::threads says
// otherwise: below it the threads' start-up and the messages cost more than they save.
inline constexpr std::size_t kParallelMinFaces = 200000;

struct GeodesicOptions {
  Strategy strategy = Strategy::speed_limiter;
  Precision precision = Precision::automatic;
  double f = 1.0;        // speed limiter / static / dynamic postpone step, in mean edge lengths
  double f0 = 1.0;       // hybrid postpone
  double f1 = 0.1;       // hybrid postpone
  // Stop expanding faces none of whose points can be within this distance (model units: the
  // centroid's distance minus the centroid's largest distance to a corner exceeds it): the
  // cost then follows the neighbourhood, not the mesh, and every face holding a point within
  // max_distance is reached. Vertices farther than this are reported as +inf.
  double max_distance = std::numeric_limits<double>::infinity();
  bool want_face_sources = false;   // fill GeodesicResult::face_sources
  // With want_face_sources: run on the intrinsic Delaunay faces (where the solver has them)
  // and give each input face the source that best fits its corners' values, chosen among the
  // flipped faces it overlaps and their neighbours (docs/gsp-core.md, "Fitted face sources").
  // Readings (distance_at) then come close to the vertex values, and no source reads below the
  // straight line from its own anywhere on its face (docs/gsp-core.md: at random points
  // inside the faces of the corpus, malign MRE 1.19 -> 0.48% with distance_at). Without it the sources are the input faces' own run: a
  // propagation, each face's source its own winner and carried on to its neighbours, which
  // walking a path back and partitioning into regions (CVT) rely on; the fitted ones need not
  // chain up from face to face. Ignored for targeted runs (GeodesicOptions::targets: they stop
  // before most vertices are final, nothing to fit to).
  bool fitted_face_sources = false;
  // Fill GeodesicResult::face_distance / face_source. A caller that needs per-vertex results
  // only saves two arrays in face order (about 10% of a query on a large mesh).
  bool want_face_distances = true;
  // Threads for one full query: 0 = automatic (all hardware threads for meshes of at least
  // kParallelMinFaces faces, whatever the number of sources; one otherwise and inside an
  // already parallel caller such as compute_many), 1 = sequential. The propagation
  // (speed_limiter, speed_limiter_postpone and hybrid_postpone strategies) deals stripes of
  // faces to the threads, which walk the front in step; steps between stripes travel as
  // messages; the query's other passes split into ranges. The result equals the sequential
  // one up to GSP's order effects (docs/performance.md). Runs with targets and bounded
  // queries (compute_local) stay on one thread.
  unsigned threads = 0;
  // Targets (input vertex indices): when given, the propagation runs in a heap (the
  // priority_queue strategy, whatever `strategy` says) and stops as soon as no queued face can
  // still shorten a target's distance; the targets' distances are then final, the rest of the
  // result covers only what was touched. With `goal_directed` (A*) the heap key is d_T plus a
  // lower bound of the remaining distance (straight line from the face to the nearest target),
  // so the front grows towards the targets instead of in every direction (paper Fig. 12a,b).
  std::vector<Index> targets;
  bool goal_directed = false;       // A*; needs targets
  // Vertices as pseudo-sources (docs/gsp-core.md): after the propagation, vertex distances are
  // relaxed along the input's edges, and vertices lowered by more than 1% seed their fans for
  // another round, so no vertex ends farther than the shortest path along the mesh edges. Off:
  // the paper's per-face virtual sources alone. Full and bounded (compute_local) queries; runs
  // with targets (A*) do not relax: they stop as soon as the targets are final.
  bool vertex_relaxation = true;
  // The straight-line bound (docs/gsp-core.md): no distance is shorter than the segment from
  // the nearest source (plus its offset); vertex values below it are raised to it, last.
  // With SolverOptions::edge_lengths only where SolverOptions::edge_lengths_line_scale says how
  // 3D bounds them (scaled by it).
  bool straight_line_bound = true;
  // The same bound inside the update step (docs/gsp-core.md, rule 8): a straight update that
  // would put a face's new corner below the segment from its source bends instead, so the
  // wrong value is not passed on. Off only to measure what it changes (gsp-bench's
  // gsp-no-line-test). With SolverOptions::edge_lengths as the bound above.
  bool straight_line_test = true;
  // Carried windows (docs/gsp-core.md, rule 10): a face remembers the rim vertices of planar
  // regions its source's line passed, and a straight update whose line passes one on its
  // hidden side bends there (a source carried round a hole in a CAD plate no longer cuts
  // across it). Only on meshes with such vertices (none with SolverOptions::edge_lengths); off
  // only to measure what it changes (gsp-bench's gsp-no-windows).
  bool carried_windows = true;
};

// The virtual source a face ended up with: the geodesic to any point p of the face is the
// straight segment (in the face's plane, unfolded) from p to `position`, then `sigma` more.
struct VirtualSource {
  Vec3 position;                  // 3D point in the plane of the face (may lie outside the face)
  double sigma = std::numeric_limits<double>::infinity();
  Index source = kInvalidIndex;   // index into the sources list; kInvalidIndex if unreached
  bool reached() const { return source != kInvalidIndex; }
};

struct PropagationStats {
  std::uint64_t update_steps = 0;    // update-step evaluations (one per face pair tried)
  std::uint64_t face_updates = 0;    // accepted updates (a face got a shorter path)
  std::uint64_t enqueued = 0;
  std::uint64_t stale_skipped = 0;   // entries whose face was updated after they were queued
  std::uint64_t postponed = 0;       // entries moved to the next round
  std::uint64_t iterations = 0;      // dual-queue rounds (heap pops for priority_queue)
  std::uint64_t faces_reached = 0;
  double mean_edge_length = 0;
  // Vertices as pseudo-sources (docs/gsp-core.md): lowerings of a vertex's distance along an
  // input edge after the propagation, the vertices lowered by more than 1% that then seeded
  // their fans, and the propagation rounds this took.
  std::uint64_t relaxed_vertices = 0;
  std::uint64_t pseudo_sources = 0;
  std::uint64_t relaxation_rounds = 0;
  // Straight updates that would have put a face's corner below the straight line from its
  // source (in 3D) and bent instead (docs/gsp-core.md, rule 8; not with caller-supplied lengths).
  std::uint64_t straight_line_bends = 0;
  // Straight updates whose line had passed a vertex bounding its source's window (a rim vertex
  // of a planar region, carried along) on the hidden side and bent there instead (docs/gsp-core.md,
  // rule 10).
  std::uint64_t window_bends = 0;
  // Vertices whose value was below the straight line from the nearest source by more than
  // 1e-6 and were raised to it (GeodesicOptions::straight_line_bound): the safety net after
  // the propagation, which rule 8 leaves almost nothing to do.
  std::uint64_t raised_to_line = 0;
  bool double_precision = false;     // the precision the query ran in (Precision::automatic decides)
  bool switched_to_postpone = false; // the speed limiter turned into speed_limiter_postpone (see Strategy)
};

struct GeodesicResult {
  std::vector<double> vertex_distance;     // per input vertex; +inf where unreachable
  std::vector<Index> vertex_source;        // per input vertex: nearest source, kInvalidIndex if none
  // Per input face: distance at its centroid and source index (geodesic Voronoi label); +inf /
  // kInvalidIndex if unreached. When the run used the intrinsic Delaunay faces, the mean of
  // the corner distances and the nearest corner's label; with fitted_face_sources, the fitted
  // source's distance at the centroid and its label.
  std::vector<double> face_distance;
  std::vector<Index> face_source;
  std::vector<VirtualSource> face_sources; // per input face, when options.want_face_sources
  PropagationStats stats;

  // Distance at the surface point (face, barycentric): the lower of the face's virtual source
  // (paper Fig. 7c) and the paths through the face's corners (corner_paths). Needs
  // want_face_sources. +inf if neither reached the face.
  double distance_at(const TriangleMesh& mesh, Index face, std::array<double, 3> bary) const;
};

// min over the corners c of `face` of d[c] + |p - c|: the shortest of the paths to the point p
// of the face that reach a corner and go on straight inside the face (d: distances by vertex,
// +inf where unknown). Each is the length of a path on the surface, so it bounds a distance
// from above wherever d does; on a long sliver one virtual source can be right for one end
// and far too long at the other (docs/gsp-core.md, "Fitted face sources").
double corner_paths(const TriangleMesh& mesh, Index face, Vec3 p, const std::vector<double>& d);

// The part of a field a bounded query (GeodesicSolver::compute_local) reached: only the
// vertices within max_distance and the faces the front touched, in input indices. Its size
// follows the neighbourhood, not the mesh.
struct LocalField {
  std::vector<Index> vertices;            // input vertices with distance <= max_distance
  std::vector<double> vertex_distance;    // parallel to `vertices`
  std::vector<Index> vertex_source;       // parallel to `vertices`: the nearest source
  std::vector<Index> faces;               // input faces reached that can hold a point within max_distance
  std::vector<double> face_distance;      // parallel to `faces`: distance at the centroid
  std::vector<Index> face_source;         // parallel to `faces`
  std::vector<VirtualSource> face_sources;   // parallel to `faces`, when want_face_sources
  PropagationStats stats;
};

// Scratch state of bounded queries: the per-face records and per-vertex minima, put back
// only where a query touched them, so a query costs its neighbourhood. Made by
// GeodesicSolver::make_workspace(), used by one thread at a time, with that solver only.
class LocalWorkspace {
 public:
  LocalWorkspace();
  ~LocalWorkspace();
  LocalWorkspace(LocalWorkspace&&) noexcept;
  LocalWorkspace& operator=(LocalWorkspace&&) noexcept;
  struct State;

 private:
  friend class GeodesicSolver;
  std::unique_ptr<State> state_;
};

// Seconds spent preparing a solver (library code measures, apps report).
struct SolverTimings {
  double layout = 0;   // the layout (clustering or Z-order) + reordering
  double build = 0;    // connectivity, radial rings, per-halfedge tables, intrinsic Delaunay flips
  // The parts of `build`: connectivity (radial rings and vertex corners; on two threads the
  // input's lengths beside it), the input's triangulation (lengths, links), the vertices'
  // analysis (bridge and coincident vertices, flat / saddle kinds, after the flips the window
  // corners and the faces' window flags) and the intrinsic Delaunay
  // triangulation (winding and flips; on two threads the analysis beside it).
  double connectivity = 0, input_tables = 0, vertex_analysis = 0, delaunay = 0;
};

struct SolverOptions {
  bool optimize_layout = true;   // reorder for the cache (results keep input order)
  // With optimize_layout: the Z-order of the positions (spatial_layout: a sort, 5-7x cheaper)
  // instead of the clustering (compute_cache_layout). Propagation is as fast on big meshes,
  // about 5% slower on small ones; what a one-field run on a scattered file wants
  // (docs/layout.md, "Z-order for one field").
  bool spatial_layout = false;
  // With optimize_layout: the vertices kept in their order and only the faces sorted by their
  // smallest vertex (face_order_layout: one counting sort), for a file whose vertices are
  // coherent and whose faces are not (docs/layout.md, "Faces out of order"). Takes precedence
  // over spatial_layout.
  bool faces_only_layout = false;
  // Propagate on the intrinsic Delaunay triangulation of the mesh (edge flips that keep the
  // surface exactly; same vertices): slivers and fans of CAD meshes become well-shaped
  // triangles. Used for vertex sources and for points inside faces (found on the flipped
  // faces by replaying the flips); the per-face virtual sources (want_face_sources) and
  // bounded queries (compute_local) use the input faces. See docs/gsp-core.md.
  bool intrinsic_delaunay = true;
  VisibilityHeuristic heuristic = VisibilityHeuristic::published();
  // Intrinsic edge lengths to propagate on instead of the 3D ones (a Riemannian metric, see
  // gsp::anisotropic; any intrinsic geometry on this connectivity): per halfedge 3f+i of the
  // input faces, the length from corner i to corner i+1. Empty: from the positions. Each face
  // uses its own three lengths (a shared edge may have two). Checked by the constructor
  // (InvalidInput): 3 per face, finite, >= 0, triangle inequality per face within 1e-6 of the
  // longest edge. With lengths, compute() refuses want_face_sources and goal_directed (both 3D
  // constructions); distances, labels and targets work as usual.
  std::vector<double> edge_lengths;
  // With edge_lengths: a scale s > 0 such that no path is shorter in those lengths than s times
  // its 3D length (a metric whose tensors all dominate s^2 I: gsp::anisotropic passes the square
  // root of their smallest eigenvalue). The straight-line bound and the update step's test then
  // hold for them too, scaled: no distance below s |x - source| (+ offset). 0: the lengths are
  // not bounded by 3D (both off, as before). Ignored without edge_lengths (s = 1 there).
  double edge_lengths_line_scale = 0;
  // Threads of the preparation: 0 = automatic (two on meshes of kParallelMinFaces faces or
  // more, outside a parallel region: the lengths beside the connectivity, the vertices'
  // analysis beside the intrinsic Delaunay flips), 1 = one. The result is the same either way.
  unsigned threads = 0;
};

// Prepares a mesh once (layout, connectivity, intrinsic per-halfedge geometry) and answers
// any number of queries. Faces that repeat a vertex are left out of the propagation; zero-area
// faces and zero-length edges are propagated through without producing NaN.
class GeodesicSolver {
 public:
  explicit GeodesicSolver(const TriangleMesh& mesh, const SolverOptions& options = {});
  // The same, sharing the caller's mesh instead of copying it where no layout is applied (a
  // one-shot run on a coherent file: 48 bytes per vertex less). The mesh must not change
  // while the solver lives.
  explicit GeodesicSolver(std::shared_ptr<const TriangleMesh> mesh, const SolverOptions& options = {});
  // The same, taking the caller's mesh: a layout reorders it in place instead of copying it
  // (a one-shot run on a scattered file: 48 bytes per vertex less at the peak).
  // release_mesh() gives it back once the queries are done.
  explicit GeodesicSolver(TriangleMesh&& mesh, const SolverOptions& options = {});
  ~GeodesicSolver();
  GeodesicSolver(GeodesicSolver&&) noexcept;
  GeodesicSolver& operator=(GeodesicSolver&&) noexcept;

  // Throws InvalidInput for a source that names a missing vertex/face or bad barycentrics.
  GeodesicResult compute(const std::vector<Source>& sources, const GeodesicOptions& options = {}) const;

  // A bounded query: the same propagation as compute() (on the input faces, whatever the
  // intrinsic Delaunay option says), but the result lists only what it reached and the cost
  // is that of the neighbourhood, not of the mesh (for sampling, local Voronoi updates...).
  // Meant for a finite max_distance; targets are not supported (InvalidInput).
  LocalWorkspace make_workspace() const;
  LocalField compute_local(const std::vector<Source>& sources, const GeodesicOptions& options,
                           LocalWorkspace& workspace) const;

  std::size_t num_vertices() const;
  std::size_t num_faces() const;
  // An input face's place in the solver's memory order: work on many faces at once (a batch
  // of candidate points) sorted by it sweeps the solver's state forward instead of jumping at
  // random. Not needed for any result.
  Index face_memory_rank(Index face) const;
  const SolverTimings& timings() const;
  std::size_t intrinsic_flips() const;   // edges flipped to make the intrinsic Delaunay triangulation
  // Vertices that bound carried windows (saddles on a planar region's rim; docs/gsp-core.md,
  // rule 10); 0: the queries carry none.
  std::size_t window_corners() const;
  // Faces left out as copies of another face's three vertices (an STL's doubled triangles:
  // intrinsic::skip_duplicate_faces); their vertices get the values of the face kept.
  std::size_t duplicate_faces() const;
  // Whether input face f takes part in the propagations: false for a face naming a vertex
  // twice and for a doubled face's copy (gsp/intrinsic/edge_lengths.hpp). Sampling draws only
  // on the faces that do: a point on a copy is never reached.
  bool face_takes_part(Index face) const;
  std::size_t state_bytes(Precision precision) const;   // propagation state beyond the mesh
  // True where a face of the triangulation vertex-source queries run on is too thin for
  // single-precision lengths (Precision::automatic then runs in double).
  bool needs_double() const;
  // The precision a query with `requested` runs in: automatic resolved for vertex sources
  // (face-point sources use the input faces: see compute()).
  Precision resolved_precision(Precision requested, bool input_faces = false) const;

  // Ends the solver and returns its mesh in the caller's order: the one it took (moved out,
  // put back in order after everything else the solver held is freed) or a copy of the one it
  // shares or copied. The solver is left like a moved-from one: destroy it or assign to it.
  TriangleMesh release_mesh() &&;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// One-off convenience: prepare and compute.
GeodesicResult geodesic_distances(const TriangleMesh& mesh, const std::vector<Source>& sources,
                                  const GeodesicOptions& options = {},
                                  const SolverOptions& solver_options = {});

}  // namespace gsp
