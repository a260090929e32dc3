// Preparing a mesh once (GeodesicSolver's constructor): the layout or the caller's own order,
// the connectivity, the input triangulation's lengths and radial links, the vertices' analysis
// (bridge and coincident vertices, vertex kinds) and the intrinsic Delaunay triangulation; on
// big meshes pairs of these steps run side by side. Queries are in geodesic_solver.cpp.
#include "intrinsic_delaunay.hpp"
#include "parallel_propagation.hpp"
#include "parallel_ranges.hpp"
#include "prefetch_corners.hpp"
#include "side_by_side.hpp"
#include "solver_impl.hpp"
#include "straight_line_bound.hpp"
#include "window_corners.hpp"

#include <gsp/connectivity.hpp>
#include <gsp/errors.hpp>
#include <gsp/geodesics.hpp>
#include <gsp/intrinsic/bridge_vertices.hpp>
#include <gsp/intrinsic/coincident_vertices.hpp>
#include <gsp/intrinsic/edge_lengths.hpp>
#include <gsp/intrinsic/vertex_kinds.hpp>
#include <gsp/topology.hpp>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <memory>
#include <thread>
#include <vector>

namespace gsp {

void GeodesicSolver::Impl::build_lengths(const std::vector<double>& edge_lengths) {
  skipped_face = intrinsic::skipped_faces(mesh());
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

void GeodesicSolver::Impl::build_links(const Connectivity& conn, unsigned threads) {
  const std::size_t nh = conn.num_halfedges();
  if (nh > detail::kRingIndexMask) throw InvalidInput("mesh too large: more than 2^29 - 1 halfedges");
  // A halfedge of a skipped face, a loop or a zero-length edge is a ring of its own; the
  // others link to the next member of their radial ring that is not in a skipped face
  // (itself on a boundary). One pass in halfedge order (in ranges on `threads` threads), no
  // per-edge lists.
  std::vector<Index> plain(nh);
  detail::for_ranges(threads, nh, [&](std::size_t begin, std::size_t end, unsigned) {
    constexpr Index kAhead = detail::kHalfedgesAhead;
    for (Index h = Index(begin); h < Index(end); ++h) {
      // next_crossed reads the edge's first halfedge, then that halfedge's length: each a
      // cache miss where edges are numbered apart from faces (prefetch_corners.hpp).
      if (h + kAhead < Index(end)) {
        const Index e = conn.halfedge_edge[h + kAhead];
        if (e != kInvalidIndex) __builtin_prefetch(conn.edge_halfedge.data() + e);
        const Index e2 = conn.halfedge_edge[h + kAhead / 2];
        if (e2 != kInvalidIndex) __builtin_prefetch(input.length.data() + conn.edge_halfedge[e2]);
      }
      plain[h] = intrinsic::next_crossed(conn, skipped_face, input.length, h);
    }
  });
  input.set_direction_bits(std::move(plain), threads);
}

detail::IntrinsicTriangulation GeodesicSolver::Impl::unflipped() const {
  detail::IntrinsicTriangulation t;
  t.triangles = input.triangles();
  t.length = input.length;
  t.skipped = skipped_face;
  t.positions = &mesh().positions;   // picks each patch's winding (intrinsic_delaunay.hpp)
  t.ring.resize(input.ring.size());
  for (std::size_t h = 0; h < t.ring.size(); ++h) t.ring[h] = input.ring[h] & detail::kRingIndexMask;
  return t;
}

// A generous cap: Delaunay flipping ends after finitely many flips, but float-stored slivers
// can make near-ties flip back and forth; the result is good long before the cap.
std::size_t GeodesicSolver::Impl::flip_cap() const { return 20 * input.length.size(); }

const detail::FlipReplay& GeodesicSolver::Impl::flip_replay() const {
  // The flips again, logged this time: the same tables in, the same flips out (the flips are
  // sequential and deterministic). Done at the first face-point query only, so that vertex
  // queries pay nothing for it (2.2M vertices: 289,000 flips, 1.4 s once, 38 MB kept).
  std::call_once(replay_once, [&] {
    detail::IntrinsicTriangulation t = unflipped();
    std::vector<detail::FlipRecord> log;
    t.log = &log;
    detail::make_intrinsic_delaunay(t, flip_cap());
    replay = std::make_unique<detail::FlipReplay>(std::move(log), t.triangles.size());
  });
  return *replay;
}

const detail::FaceFrames& GeodesicSolver::Impl::face_frames() const {
  std::call_once(frames_once, [&] {
    frames = std::make_unique<detail::FaceFrames>(flip_replay(), mesh().triangles, delaunay->triangles(),
                                                  delaunay->length, skipped_face);
  });
  return *frames;
}

void GeodesicSolver::Impl::build_delaunay(bool two_threads) {
  detail::IntrinsicTriangulation t = unflipped();
  // On two threads the flips need not wait for the windings' volumes (an open patch's are two
  // passes over the positions); the same triangulation either way.
  flips = two_threads ? detail::make_intrinsic_delaunay_beside(t, flip_cap(), input.triangles(), [&] { return unflipped(); })
                      : detail::make_intrinsic_delaunay(t, flip_cap());
  if (flips == 0 && t.reoriented == 0) {   // a soup needing no flips still gets one winding
    input.delaunay = true;                   // the input is Delaunay as it is
    return;
  }
  delaunay = std::make_unique<Triangulation>();
  delaunay->delaunay = true;
  delaunay->own_triangles = std::move(t.triangles);
  delaunay->length = std::move(t.length);
  // Three tables from the flipped faces, two of them apart from the third.
  Triangulation& d = *delaunay;
  // A face no flip rewrote has the input's lengths (reordered at most), snapped already and, on
  // an input that needs no doubles, fine in float: only the flipped faces are looked at then.
  const std::vector<char> flipped = std::move(t.flipped);
  auto lengths_and_corners = [&] {
    detail::snap_zero_lengths(d.length, &flipped);
    d.needs_double = detail::needs_double_lengths(d.length, skipped_face, input.needs_double ? nullptr : &flipped);
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

void GeodesicSolver::Impl::analyse_vertices(Connectivity& conn, intrinsic::CornerAngleSums&& angle_sums) {
  bridge_vertices = intrinsic::bridge_vertices(mesh(), conn, skipped_face);
  intrinsic::CoincidentVertices groups = intrinsic::coincident_vertices(mesh(), conn, skipped_face, input.length);
  coincident = std::move(groups.vertices);
  coincident_begin = std::move(groups.begin);
  // intrinsic::vertex_kinds(mesh, conn, ...) in its steps: the vertices joining several fans
  // from the connectivity first, so that the connectivity goes before the angle sums (the
  // Delaunay flips beside them are the preparation's peak of memory).
  const std::vector<Index> nonmanifold =
      intrinsic::nonmanifold_vertices(mesh(), conn, bridge_vertices, coincident, &skipped_face);
  // The connectivity's vertex corners are the input triangulation's; the rest goes now.
  input.corner_begin = std::move(conn.vertex_corner_begin);
  input.corners = std::move(conn.vertex_corners);
  conn = Connectivity();
  // intrinsic::boundary_halfedges, read off the radial links (build_links: next_crossed).
  std::vector<std::uint8_t> boundary_halfedge(input.ring.size());
  for (std::size_t h = 0; h < boundary_halfedge.size(); ++h)
    boundary_halfedge[h] = (input.ring[h] & detail::kRingIndexMask) == h;
  // With rule 4's crease limit (3D creases: a caller's metric has none), read off the links.
  vertex_kind = intrinsic::vertex_kinds(mesh(), angle_sums, boundary_halfedge, skipped_face, nonmanifold,
                                        custom_lengths ? nullptr : &input.ring);
  // Carried windows (3D lengths only: a caller's metric need not be flat where 3D is planar):
  // the vertices that bound them; the faces' flags follow once the flips are done.
  if (!custom_lengths)
    window_corner = detail::window_corners(
        mesh(), input.ring,
        detail::window_candidates(mesh(), vertex_kind, angle_sums.angle, boundary_halfedge, skipped_face, nonmanifold),
        skipped_face);
  angle_sums = {};
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

GeodesicSolver::GeodesicSolver(TriangleMesh&& input, const SolverOptions& options)
    : impl_(std::make_unique<Impl>()) {
  impl_->build(input, nullptr, options, &input);
}

TriangleMesh GeodesicSolver::release_mesh() && {
  if (!impl_) throw InvalidInput("GeodesicSolver: used after release_mesh()");
  std::unique_ptr<Impl> impl = std::move(impl_);
  std::shared_ptr<const TriangleMesh> store = std::move(impl->mesh_store);
  const bool owned = impl->owns_mesh && store.use_count() == 1;
  Layout layout = std::move(impl->maps).release();
  impl.reset();   // everything else freed before the mesh is put back in order
  // An owned mesh was made non-const (make_shared<TriangleMesh>), so it may be moved out.
  TriangleMesh mesh = owned ? std::move(const_cast<TriangleMesh&>(*store)) : TriangleMesh(*store);
  store.reset();
  if (!layout.vertex_rank.empty()) apply_layout_in_place(mesh, inverse_layout(std::move(layout)));
  return mesh;
}

void GeodesicSolver::Impl::build(const TriangleMesh& given, std::shared_ptr<const TriangleMesh> shared,
                                 const SolverOptions& options, TriangleMesh* owned) {
  using Clock = std::chrono::steady_clock;
  validate(given);
  if (!options.edge_lengths.empty()) detail::validate_halfedge_lengths(given, options.edge_lengths);
  auto t0 = Clock::now();
  custom_lengths = !options.edge_lengths.empty();
  if (custom_lengths && !(options.edge_lengths_line_scale >= 0 && std::isfinite(options.edge_lengths_line_scale)))
    throw InvalidInput("edge_lengths_line_scale must be finite and >= 0");
  line_scale = custom_lengths ? options.edge_lengths_line_scale : 1.0;
  heuristic = options.heuristic;
  if (options.optimize_layout) {
    Layout layout = options.faces_only_layout ? face_order_layout(given)
                    : options.spatial_layout  ? gsp::spatial_layout(given)
                                              : compute_cache_layout(given);
    if (owned) {
      apply_layout_in_place(*owned, layout);
      mesh_store = std::make_shared<TriangleMesh>(std::move(*owned));
    } else {
      mesh_store = std::make_shared<TriangleMesh>(apply_layout(given, layout));
    }
    maps = detail::IndexMaps(std::move(layout));
    owns_mesh = true;
  } else if (owned) {
    mesh_store = std::make_shared<TriangleMesh>(std::move(*owned));
    owns_mesh = true;
  } else if (shared) {
    mesh_store = std::move(shared);
  } else {
    mesh_store = std::make_shared<TriangleMesh>(given);
    owns_mesh = true;
  }
  const auto t1 = Clock::now();
  auto lap = [last = t1]() mutable {
    const auto now = Clock::now();
    const double s = std::chrono::duration<double>(now - last).count();
    last = now;
    return s;
  };
  // On a big mesh two threads: the connectivity beside the lengths and as many of the corner
  // angle sums as fit (the vertices' analysis needs no connectivity for them), then the rest
  // of the analysis beside the Delaunay flips (each pair reads the same tables and writes apart).
  const bool two = options.threads != 1 && (options.threads >= 2 || (mesh().num_faces() >= kParallelMinFaces &&
                                                                       std::thread::hardware_concurrency() >= 2 &&
                                                                       !detail::inside_parallel_region()));
  Connectivity conn;
  intrinsic::CornerAngleSums angle_sums;
  const std::vector<double>* angle_lengths = custom_lengths ? &this->input.length : nullptr;
  // Faces whose corner angles are summed: on two threads the first pair sums them until the
  // connectivity is done and the analysis adds the rest (the same sums whatever the split);
  // on one, the analysis sums them all.
  std::size_t angles_done = 0;
  angle_sums.angle.assign(mesh().num_vertices(), 0.0);
  angle_sums.used.assign(mesh().num_vertices(), 0);
  if (!custom_lengths) angle_sums.normal.assign(mesh().num_faces(), {0, 0, 0});   // the crease rule's
  if (!two) {
    conn = build_connectivity(mesh());
    timings.connectivity = lap();
    build_lengths(options.edge_lengths);
  } else {
    std::atomic<bool> connected{false};
    detail::side_by_side(
        [&] {
          build_lengths(options.edge_lengths);
          constexpr std::size_t kChunk = 8192;
          while (angles_done < mesh().num_faces() && !connected.load(std::memory_order_relaxed)) {
            const std::size_t end = std::min(angles_done + kChunk, mesh().num_faces());
            intrinsic::add_corner_angles(mesh(), skipped_face, angle_lengths, angle_sums, angles_done, end);
            angles_done = end;
          }
        },
        [&] {
          conn = build_connectivity(mesh());
          timings.connectivity = lap();
          connected.store(true, std::memory_order_relaxed);
        });
  }
  // Doubled faces (intrinsic::skip_duplicate_faces) take no part: found on the connectivity's
  // non-manifold edges, so only now. Where there are any (rare), the mean edge and the angle
  // sums begin again without them (the same sums on one thread and two).
  if (!conn.nonmanifold_edges.empty() && (duplicate_faces = intrinsic::skip_duplicate_faces(mesh(), conn, skipped_face))) {
    mean_edge = detail::mean_edge_length(input.length, skipped_face);
    angles_done = 0;
    angle_sums.angle.assign(mesh().num_vertices(), 0.0);
    angle_sums.used.assign(mesh().num_vertices(), 0);
    if (!custom_lengths) angle_sums.normal.assign(mesh().num_faces(), {0, 0, 0});
  }
  auto finish_angles = [&] {
    intrinsic::add_corner_angles(mesh(), skipped_face, angle_lengths, angle_sums, angles_done, mesh().num_faces());
  };
  build_links(conn, two ? 2 : 1);
  timings.input_tables = lap();
  if (!two || !options.intrinsic_delaunay) {
    finish_angles();
    analyse_vertices(conn, std::move(angle_sums));
    timings.vertex_analysis = lap();
    if (options.intrinsic_delaunay) build_delaunay(false);
    timings.delaunay = lap();
  } else {
    detail::side_by_side(
        [&] {
          const auto start = Clock::now();
          finish_angles();
          analyse_vertices(conn, std::move(angle_sums));
          timings.vertex_analysis = std::chrono::duration<double>(Clock::now() - start).count();
        },
        [&] {
          build_delaunay(true);   // its last tables on two threads too (the analysis ends first)
          timings.delaunay = lap();
        });
  }
  // Carried windows: what each face of the triangulations asks (after the flips), from the
  // window corners the vertex analysis found; timed with it (--stats' build_phases).
  if (!window_corner.empty()) {
    const auto start = Clock::now();
    window_corner_count = std::size_t(std::count(window_corner.begin(), window_corner.end(), std::uint8_t(1)));
    for (Triangulation* t : {&input, delaunay.get()})
      if (t)
        t->window_flags = detail::window_face_flags(t->triangles(), t->ring, t->corner_begin, t->corners,
                                                    mesh().positions, window_corner, skipped_face);
    window_corner = {};
    timings.vertex_analysis += std::chrono::duration<double>(Clock::now() - start).count();
  }
  for (Index f = 0; duplicate_faces && f < Index(mesh().num_faces()); ++f) {
    if (!skipped_face[f]) continue;
    std::array<double, 3> b{1, 0, 0};
    const Index g = intrinsic::kept_copy(mesh().triangles, input.corner_begin, input.corners, skipped_face, f, b);
    if (g != f) face_copies.push_back({maps.face_to_input(f), maps.face_to_input(g)});
  }
  if (line_scale > 0) {
    if (line_scale != 1) {
      scaled_vertex_positions.resize(mesh().num_vertices());
      for (std::size_t v = 0; v < scaled_vertex_positions.size(); ++v)
        scaled_vertex_positions[v] = line_scale * mesh().positions[v];
    }
    line_centre = bounding_box(line_bound_positions()).center();
    line_positions = detail::scaled_positions(line_bound_positions(), 1.0 / mean_edge, line_centre);
  }
  const auto t2 = Clock::now();
  timings.layout = std::chrono::duration<double>(t1 - t0).count();
  timings.build = std::chrono::duration<double>(t2 - t1).count();
}

}  // namespace gsp
