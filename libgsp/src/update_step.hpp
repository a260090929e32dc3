#pragma once
// The GSP update step (paper Section 4.1, in canonical face coordinates: see face_record.hpp):
// UpdateStep, which the queue strategies (queue_strategies.hpp, Section 4.2) drive, and the
// straight-line test it asks (StraightLineTest).
// Internal header: templated on the scalar type, instantiated for float and double in
// geodesic_solver.cpp. The hot loop allocates nothing and calls nothing virtual.
#include "face_record.hpp"
#include "probe_table.hpp"
#include "ring_links.hpp"
#include "window_bounds.hpp"
#include "window_corners.hpp"

#include <gsp/geodesics.hpp>
#include <gsp/intrinsic/corner_rules.hpp>
#include <gsp/intrinsic/vertex_kinds.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <type_traits>
#include <limits>
#include <vector>

namespace gsp::detail {

// A lean-queue entry: the halfedge of the face to propagate from, and that face's d_T when
// queued, so entries overtaken by a later update of the face are recognised and skipped.
template <class Real>
struct QueueEntry {
  Index halfedge;
  Real dT;
};

// The largest distance from a face's centroid to a corner: two thirds of the longest median.
template <class Real>
inline Real centroid_radius(const Real (&len)[3]) {
  const Real a2 = len[0] * len[0], b2 = len[1] * len[1], c2 = len[2] * len[2];
  const Real m = std::max({2 * (b2 + c2) - a2, 2 * (a2 + c2) - b2, 2 * (a2 + b2) - c2});
  return std::sqrt(std::max(m, Real(0))) / 3;
}

// An update step for a face owned by another thread: everything the owner needs to run it.
template <class Real>
struct RemoteStep {
  Index g, link;
  Real hx, hy, e1h, sigma;
  Index source;
  bool h_dir;
};

// The same from a face with window flags (carried windows): the sending face's window in its
// edge frame comes along. Apart from the plain steps so that those stay 32 bytes.
template <class Real>
struct WindowedStep {
  RemoteStep<Real> step;
  WindowSides sides;
};

// One thread's messages to another.
template <class Real>
struct Mailbox {
  std::vector<RemoteStep<Real>> steps;
  std::vector<WindowedStep<Real>> windowed;
  bool empty() const { return steps.empty() && windowed.empty(); }
  void append(const Mailbox& m) {
    steps.insert(steps.end(), m.steps.begin(), m.steps.end());
    windowed.insert(windowed.end(), m.windowed.begin(), m.windowed.end());
  }
  void clear() { steps.clear(), windowed.clear(); }
  void swap(Mailbox& m) { steps.swap(m.steps), windowed.swap(m.windowed); }
};

// What the update step needs to keep its straight updates above the straight line in 3D
// (UpdateStep::try_update): the propagation's triangles (layout vertex indices) and the
// vertices and sources of straight_line_bound.hpp's scaled_positions / scaled_sources. All
// null: no test (caller-supplied lengths whose distances 3D does not bound: no line scale).
struct StraightLineTest {
  const Triangle* triangles = nullptr;
  const float* positions = nullptr;   // x, y, z per vertex
  const float* sources = nullptr;     // x, y, z, offset per source label
};

// Partitioned: a parallel run's step, owning every threads-th stripe of faces (partition());
// the sequential step compiles without the ownership test.
template <class Real, bool Partitioned = false>
class UpdateStep {
 public:
  UpdateStep(FaceRecord<Real>* faces, const Index* ring, const ProbeTable<Real>& probe, Real expand_limit,
             PropagationStats& stats, const StraightLineTest& line = {})
      : faces_(faces), ring_(ring), probe_(probe), limit_(expand_limit), line_(line), stats_(stats) {}

  // Bounded queries collect the faces they reach for the first time (to list and reset them
  // without scanning the mesh); one predictable branch per accepted update.
  // every_update: every accepted update instead (a face may be listed more than once).
  void collect_reached(std::vector<Index>* faces, bool every_update = false) {
    reached_ = faces, every_update_ = every_update;
  }

  // Carried windows (window_bounds.hpp; docs/gsp-core.md, rule 10): `records` per face (this
  // query's), `flags` per face (window_face_flags(), window_corners.hpp); either null: none.
  void carry_windows(WindowRecord<Real>* records, const std::uint8_t* flags) {
    windows_ = records && flags ? records : nullptr;
    window_flags_ = records && flags ? flags : nullptr;
  }

  Real key(const QueueEntry<Real>& e) const { return e.dT; }
  bool is_stale(const QueueEntry<Real>& e) const { return faces_[face_of(e.halfedge)].dT < e.dT; }

  // Starts loading the record an entry will update first (the face across its edge): on
  // meshes whose state outgrows the L2 cache that load is the step's main stall.
  // Always inlined: out of line, GCC's pure-function analysis sees a const function without
  // side effects and drops the call, prefetches and all (it did, once the body grew a line:
  // the queries on 2.2M faces 25-45% slower).
  [[gnu::always_inline]] void prefetch(const QueueEntry<Real>& e) const {
    const Index f = face_of(ring_[e.halfedge] & kRingIndexMask);
    __builtin_prefetch(&faces_[f]);
    if (line_.triangles) __builtin_prefetch(&line_.triangles[f]);
  }

  // Propagates the virtual source of the entry's face over its halfedge into every other face
  // of the edge's radial ring; push(entry) receives the entries of each improved face.
  template <class Push>
  void expand(const QueueEntry<Real>& entry, Push&& push) {
    const Index h = entry.halfedge;
    const FaceRecord<Real>& u = faces_[face_of(h)];
    if (u.dT < entry.dT) {
      ++stats_.stale_skipped;
      return;
    }
    // The source in h's edge frame: U lies on the +y side, so a source "behind" h has y >= 0.
    // (Halfedge 0's edge frame is the canonical frame: nothing to compute.)
    Real hx = u.sx, hy = u.sy, e1h = u.len[0];
    if (corner_of(h) != 0 || !(e1h > 0)) {
      const EdgeView<Real> vu = edge_view(u.len, corner_of(h));
      canonical_frame(u.len, corner_of(h), vu).to_edge(u.sx, u.sy, hx, hy);
      e1h = vu.e1;
    }
    // Two instances of the walk: with carried windows and without. A face without window flags
    // has no window to send, and the faces across its edges none to take from it (the crossed
    // edge's ends and its plane are the sending face's too): the step as it was.
    // The windowed one is kept out of line: inlined beside the plain one it cost the plain
    // walk registers (on 2.2M faces 25-45% of its time, though only 4% more instructions).
    if (windows_ && window_flags_[face_of(h)])
      walk_windowed(h, hx, hy, e1h, u.sigma, u.source(), sides_in_edge_frame(h, u), push);
    else
      walk_ring<false>(h, hx, hy, e1h, u.sigma, u.source(), WindowSides::none(), push);
  }

  template <class Push>
  [[gnu::noinline]] void walk_windowed(Index h, Real hx, Real hy, Real e1h, Real sigma, Index source,
                                       const WindowSides& sides, Push&& push) {
    walk_ring<true>(h, hx, hy, e1h, sigma, source, sides, push);
  }

  // The steps from halfedge h (the source in its edge frame) into every other face of its
  // radial ring.
  template <bool Windows, class Push>
  void walk_ring(Index h, Real hx, Real hy, Real e1h, Real sigma, Index source, const WindowSides& sides,
                 Push&& push) {
    std::uint64_t steps = 0;
    Index link = ring_[h];
    const bool h_dir = (link & kRingSelfDir) != 0;
    for (Index g = link & kRingIndexMask; g != h;) {
      ++steps;
      step_into<Windows>(g, link, h_dir, hx, hy, e1h, sigma, source, sides, push);
      if (link & kRingPair) break;
      link = ring_[g];
      g = link & kRingIndexMask;
    }
    stats_.update_steps += steps;
  }

  // The step into the face of halfedge g; a face another thread owns gets it as a message
  // (parallel runs only).
  template <bool Windows, class Push>
  void step_into(Index g, Index link, bool h_dir, Real hx, Real hy, Real e1h, Real sigma, Index source,
                 const WindowSides& sides, Push&& push) {
    if constexpr (Partitioned) {
      const Index owner = owner_of(face_of(g));
      if (owner != own_) {
        const RemoteStep<Real> m{g, link, hx, hy, e1h, sigma, source, h_dir};
        if constexpr (Windows) (*outbox_)[owner].windowed.push_back({m, sides});
        else (*outbox_)[owner].steps.push_back(m);
        return;
      }
    }
    try_update<Windows>(g, link, h_dir, hx, hy, e1h, sigma, source, sides, push);
  }

  // One update step: the source (hx, hy in the sending halfedge's edge frame, e1h that edge's
  // length, sigma, label) unfolded over ring link `link` into the face of halfedge g. Its
  // steps, each below: unfold, choose_path (the heuristic's probe and the corner rules), the
  // path's values, the carried window, the straight-line test, accept. `sides`: the sending
  // face's window (its edge frame), read only with carried windows.
  template <bool Windows, class Push>
  void try_update(Index g, Index link, bool h_dir, Real hx, Real hy, Real e1h, Real sigma, Index source,
                  const WindowSides& sides, Push&& push) {
    FaceRecord<Real>& t = faces_[face_of(g)];
    const Index cj = corner_of(g);
    const EdgeView<Real> v = edge_view(t.len, cj);
    const Unfolded u = unfold(v, link, h_dir, hx, hy, e1h);
    int probed = 0;   // what the probe alone said
    Real qx = 0, qy = 0;   // where it looked from
    const int kind = choose_path(t, cj, v, u, probed, qx, qy);
    WindowSides own;            // the window T keeps if it takes the straight path (Windows only)
    std::uint8_t flags = 0;     // T's window_face_flags()
    if constexpr (Windows) {
      own = WindowSides::none();
      flags = window_flags_[face_of(g)];
    }
    Path p = Windows ? bend_or_window(kind, sigma, v.e1, u, cj, flags, sides, link, h_dir, e1h)
                     : path_of(kind, sigma, v.e1, u);
    if (!improves(t, p.dT, p.sigma)) return;
    bool straight = kind == 0;
    // The sending face's window comes along only over an edge between coplanar faces: in a
    // planar region a bend at a hiding rim vertex is the true path; on curved surfaces GSP's
    // straight values below exact and bent ones above cancel.
    if (Windows && straight && (flags & (kWindowEdge0 << cj)) && sides.any()) {
      own = unfold_sides(sides, same_direction(link, h_dir), float(e1h));
      const int k = hidden_by(own, u.sx, u.sy, qx, qy, v.px + Real(kWindowLooseLambda) * (u.cx - v.px),
                              v.py + Real(kWindowLooseLambda) * (u.cy - v.py), v.e1);
      if (k >= 0 && well_shaped(t)) {
        // The source's line passed the window's bound on its hidden side: the path bends at
        // the bound (a virtual source at a vertex that is not T's own corner).
        const Real wx = Real(own.x[k]), wy = Real(own.y[k]);
        const Real s = sigma + std::sqrt((wx - u.sx) * (wx - u.sx) + (wy - u.sy) * (wy - u.sy));
        p = {s, s + std::sqrt((u.cx - wx) * (u.cx - wx) + (u.cy - wy) * (u.cy - wy)), wx, wy};
        if (!improves(t, p.dT, p.sigma)) return;
        ++stats_.window_bends;
        straight = false;
      }
    }
    // A straight path that reaches the face's new corner P shorter than the straight line in
    // 3D does not exist: its unfolding passed a vertex on a side no surface path takes. It
    // bends instead, where the probe said or else at the end of the shorter bend (A's and B's
    // values came with the sending face, tested there; docs/gsp-core.md, rule 8). Tested only
    // on a path the face takes: a bend is never shorter than the straight path, so where the
    // face refuses the straight one it refuses the bend too.
    if (straight && line_.sources && straight_below_line(g, cj, v, u, sigma, source)) {
      ++stats_.straight_line_bends;
      const int bend = probed != 0 ? probed : shorter_bend(u, v.e1);
      p = Windows ? bend_or_window(bend, sigma, v.e1, u, cj, flags, sides, link, h_dir, e1h)
                  : path_of(bend, sigma, v.e1, u);
      if (!improves(t, p.dT, p.sigma)) return;
      straight = false;
    }
    accept(g, t, cj, v, p, source, push);
    if constexpr (Windows)
      if (straight && flags) keep_window(g, t, cj, v, u, own, flags);
  }

  // A step sent by another thread's expand() (RemoteStep; counted there), applied by the
  // face's owner.
  template <class Push>
  void apply(const RemoteStep<Real>& m, Push&& push) {
    try_update<false>(m.g, m.link, m.h_dir, m.hx, m.hy, m.e1h, m.sigma, m.source, WindowSides::none(), push);
  }
  template <class Push>
  [[gnu::noinline]] void apply(const WindowedStep<Real>& w, Push&& push) {
    const RemoteStep<Real>& m = w.step;
    try_update<true>(m.g, m.link, m.h_dir, m.hx, m.hy, m.e1h, m.sigma, m.source, w.sides, push);
  }

  // Parallel runs: the faces come in stripes of 2^stripe_shift consecutive faces, dealt to the
  // threads in turn; this step owns the stripes of thread `me`, steps into other faces go to
  // outbox[owner] instead.
  void partition(Index me, Index threads, unsigned stripe_shift, std::vector<Mailbox<Real>>* outbox) {
    own_ = me, threads_ = threads, stripe_shift_ = stripe_shift, outbox_ = outbox;
  }
  // Whether face record t takes a path of centroid distance dT and sigma. Only a clearly
  // shorter path counts: an improvement lost in rounding would bounce between faces forever.
  static bool improves(const FaceRecord<Real>& t, Real dT, Real sigma) {
    if constexpr (!Partitioned) {
      (void)sigma;
      return dT + dT * kRelativeImprovement < t.dT;
    } else {
      // Parallel runs: paths within rounding of each other reach a face in any order, and on
      // several threads a bend past a vertex almost on the straight line could come first and
      // bend everything behind it. So here a path takes a face when it is shorter on a coarse
      // scale (the value's float bits less the last kTieBits), and on the same step of that
      // scale when less lies behind its virtual source (fewer bends). One strict order on
      // (coarse value, sigma): every accepted update lowers it, so the run ends. One thread
      // keeps its first-come rule. Why these choices, with the measurements:
      // docs/performance.md, "Threads", ties.
      const auto coarse_new = coarse(dT), coarse_old = coarse(t.dT);
      return coarse_new < coarse_old || (coarse_new == coarse_old && sigma < t.sigma);
    }
  }

  // Whether `value` (mean edges) at the corner opposite halfedge g (corner cj of its face) is
  // below the straight line from source `label` in 3D, beyond single precision's reach: the
  // positions are floats (1e-3 mean edges absolute, 1e-4 relative to spare).
  bool below_straight_line(Index g, Index cj, Real value, Index label) const {
    const Index p = line_.triangles[face_of(g)][cj == 0 ? 2 : cj - 1];
    const float* x = line_.positions + 3 * std::size_t(p);
    const float* s = line_.sources + 4 * std::size_t(label);
    const float dx = x[0] - s[0], dy = x[1] - s[1], dz = x[2] - s[2];
    const float reach = (float(value) + 1e-3f) * 1.0001f - s[3];
    return reach < 0 || reach * reach < dx * dx + dy * dy + dz * dz;
  }

  Index owner_of(Index face) const {
    const Index stripe = face >> stripe_shift_;
    return threads_ == 2 ? (stripe & 1) : stripe % threads_;
  }

 private:
  // The sending face's source unfolded into g's edge frame (sx, sy; A = corner cj at the
  // origin, B at (e1, 0), the face T on +y) and T's centroid there (cx, cy).
  struct Unfolded {
    Real sx, sy, cx, cy;
  };
  // A path into T: the new virtual source (ex, ey in g's edge frame) with sigma behind it,
  // and T's centroid distance dT.
  struct Path {
    Real sigma, dT, ex, ey;
  };

  // Whether the sending and the receiving face walk their shared edge the same way (they
  // disagree in orientation).
  static bool same_direction(Index link, bool h_dir) { return ((link & kRingNextDir) != 0) == h_dir; }

  // Unfold into g's frame (T on +y): y flips; x is measured from the other end unless the
  // two faces disagree in orientation and walk the edge the same way.
  static Unfolded unfold(const EdgeView<Real>& v, Index link, bool h_dir, Real hx, Real hy,
                                                Real e1h) {
    const bool same_dir = same_direction(link, h_dir);
    // sy <= 0: the source lies on U's side, as it should
    return {same_dir ? hx : e1h - hx, -hy, (v.px + v.e1) * Real(1.0 / 3.0), v.py * Real(1.0 / 3.0)};
  }

  // The bend at the end giving the shorter path source -> corner -> centroid (the paper's
  // l1, l2): 1 at A, 2 at B.
  static int shorter_bend(const Unfolded& u, Real e1) {
    const Real l1 = std::sqrt(u.cx * u.cx + u.cy * u.cy) + std::sqrt(u.sx * u.sx + u.sy * u.sy);
    const Real l2 = std::sqrt((u.cx - e1) * (u.cx - e1) + u.cy * u.cy) +
                    std::sqrt((u.sx - e1) * (u.sx - e1) + u.sy * u.sy);
    return l1 <= l2 ? 1 : 2;
  }

  // Which path the source takes into T: 0 straight through AB, 1 a new virtual source at A,
  // 2 at B. The heuristic's probe decides (probed: its answer), then the corner rules
  // (gsp/intrinsic/corner_rules.hpp) have the last word at A and B.
  int choose_path(const FaceRecord<Real>& t, Index cj, const EdgeView<Real>& v,
                                         const Unfolded& u, int& probed, Real& probe_x, Real& probe_y) const {
    const Real sx = u.sx, sy = u.sy, cx = u.cx, cy = u.cy, e1 = v.e1;
    if (!(sy <= 0)) {
      // The source lies on T's side of the edge (the paper's same-side case): no straight
      // path crosses AB; bend at the end giving the shorter path source -> corner -> centroid.
      // (Even at a flat vertex: carrying the source on would let it circle round a vertex
      // and pick up rounding drift; the face gets the straight path through another edge.)
      return shorter_bend(u, e1);
    }
    // The heuristic's probe Q between the opposite corner P (lambda 0) and the centroid
    // (lambda 1); a zero-length edge is seen through its single point.
    Real qx = -1, qy = 0;
    if (e1 > 0) {
      const Real lambda = probe_.blend(t.len, e1, v.py);
      qx = v.px + lambda * (cx - v.px);
      qy = v.py + lambda * (cy - v.py);
    }
    probe_x = qx, probe_y = qy;
    // Does the segment Q -> S cross AB? Division-free form of the paper's
    // t = Qx + alpha (Sx - Qx), scaled by (qy - sy) >= 0.
    const Real tq = qx * -sy + sx * qy;
    const Real span = qy - sy;   // >= 0
    int kind = tq < 0 ? 1 : (tq > e1 * span ? 2 : 0);
    // Where the segment from the probe at lambda (between P and the centroid) to S crosses
    // AB's line: 0 within AB, 1 before A, 2 beyond B (the same test as above). The corner
    // rules ask it where a corner's kind has the last word.
    auto crossing = [&](Real lambda) {
      const Real rx = v.px + lambda * (cx - v.px), ry = v.py + lambda * (cy - v.py);
      const Real tr = rx * -sy + sx * ry;
      return tr < 0 ? 1 : (tr > e1 * (ry - sy) ? 2 : 0);
    };
    probed = kind;
    if (kind != 0) {
      const Index end = kind == 1 ? cj : (cj == 2 ? 0 : cj + 1);
      auto within_flat_miss = [&] { return (kind == 1 ? -tq : tq - e1 * span) <= kFlatMiss * span; };
      kind = intrinsic::reconsider_bend(kind, t.corner_kind(end), probe_.saddle_loose, within_flat_miss, crossing);
    }
    if (kind == 0 && e1 > 0)
      kind = intrinsic::straight_past_saddles(t.saddle_corner(cj), t.saddle_corner(cj == 2 ? 0 : cj + 1), crossing);
    return kind;
  }

  // The path of `kind` (choose_path) from the source, sigma behind it, to T's centroid.
  static Path path_of(int kind, Real sigma, Real e1, const Unfolded& u) {
    const Real sx = u.sx, sy = u.sy, cx = u.cx, cy = u.cy;
    if (kind == 0) return {sigma, sigma + std::sqrt((cx - sx) * (cx - sx) + (cy - sy) * (cy - sy)), sx, sy};
    if (kind == 1) {
      const Real s = sigma + std::sqrt(sx * sx + sy * sy);
      return {s, s + std::sqrt(cx * cx + cy * cy), Real(0), Real(0)};
    }
    const Real s = sigma + std::sqrt((sx - e1) * (sx - e1) + sy * sy);
    return {s, s + std::sqrt((cx - e1) * (cx - e1) + cy * cy), e1, Real(0)};
  }

  // A bend at T's end A (kind 1) or B (kind 2) with carried windows (rule 10): where the
  // sending face's window hides that end (the line from the source to it passes a bound on its
  // hidden side: the source seen round a hole, one face at a time, though not from the end),
  // sigma + |S - end| is no surface path's length, and the path bends at the bound instead,
  // as a hidden straight step does (a virtual source at a vertex that is not T's own corner).
  // Over edges between coplanar faces only, like the window itself. Any other kind: path_of.
  Path bend_or_window(int kind, Real sigma, Real e1, const Unfolded& u, Index cj, std::uint8_t flags,
                      const WindowSides& sides, Index link, bool h_dir, Real e1h) {
    if (kind == 0 || !(flags & (kWindowEdge0 << cj)) || !sides.any()) return path_of(kind, sigma, e1, u);
    const WindowSides own = unfold_sides(sides, same_direction(link, h_dir), float(e1h));
    const Real ex = kind == 1 ? Real(0) : e1;
    const int k = hidden_by(own, u.sx, u.sy, ex, Real(0), ex, Real(0), e1);
    if (k < 0) return path_of(kind, sigma, e1, u);
    ++stats_.window_bends;
    const Real wx = Real(own.x[k]), wy = Real(own.y[k]);
    const Real s = sigma + std::sqrt((wx - u.sx) * (wx - u.sx) + (wy - u.sy) * (wy - u.sy));
    return {s, s + std::sqrt((u.cx - wx) * (u.cx - wx) + (u.cy - wy) * (u.cy - wy)), wx, wy};
  }

  // The straight-line test (StraightLineTest): whether the straight path reaches T's new
  // corner P below the straight line from its source in 3D.
  bool straight_below_line(Index g, Index cj, const EdgeView<Real>& v, const Unfolded& u,
                                                  Real sigma, Index source) const {
    const Real dx = u.sx - v.px, dy = u.sy - v.py;
    return below_straight_line(g, cj, sigma + std::sqrt(dx * dx + dy * dy), source);
  }

  // Face U's window (sending over halfedge h) in h's edge frame; none where U was seeded since
  // it was written.
  WindowSides sides_in_edge_frame(Index h, const FaceRecord<Real>& u) const {
    const WindowRecord<Real>& w = windows_[face_of(h)];
    if (!w.holds(u.dT)) return WindowSides::none();
    if (corner_of(h) == 0 && u.len[0] > 0) return w.sides;   // the canonical frame is h's
    const EdgeView<Real> vu = edge_view(u.len, corner_of(h));
    const CanonicalFrame<Real> fr = canonical_frame(u.len, corner_of(h), vu);
    WindowSides e = w.sides;
    for (int k = 0; k < 2; ++k) {
      if (!w.sides.has(k)) continue;
      Real x, y;
      fr.to_edge(Real(w.sides.x[k]), Real(w.sides.y[k]), x, y);
      e.x[k] = float(x), e.y[k] = float(y);
    }
    return e;
  }

  // Whether a window may bend a step into face record t: not a sliver (kWindowMaxAspect: a
  // window bend taken for a long sliver near one end bends all of it).
  static bool well_shaped(const FaceRecord<Real>& t) {
    const Real a = t.len[0], b = t.len[1], c = t.len[2];
    const Real lmax = std::max({a, b, c}), half = (a + b + c) / 2;
    const Real area = std::sqrt(std::max(half * (half - a) * (half - b) * (half - c), Real(0)));
    return area > 0 && lmax * lmax < Real(2 * kWindowMaxAspect) * area;
  }

  // After T (halfedge g, corner cj, window_face_flags() `flags`) took a straight path: its
  // window. It keeps the sending face's (`own`, in g's edge frame) and adds the crossed edge's
  // ends that bound windows. Written only where there is one: a record whose stamp is not the
  // face's dT (a bend or a seed since) reads as none.
  void keep_window(Index g, const FaceRecord<Real>& t, Index cj, const EdgeView<Real>& v, const Unfolded& u,
                   WindowSides s, std::uint8_t flags) {
    const Real sx = u.sx, sy = u.sy, e1 = v.e1;
    const Real near = Real(kWindowNearSource) * e1;
    const Index cb = cj == 2 ? 0 : cj + 1;
    if ((flags & (kWindowCorner0 << cj)) && sx * sx + sy * sy > near * near) {   // A at the origin: B's side seen
      const int k = side_towards(Real(0), Real(0), sx, sy, e1, Real(0));
      if (k >= 0) tighten(s, k, Real(0), Real(0), sx, sy);
    }
    if ((flags & (kWindowCorner0 << cb)) && (e1 - sx) * (e1 - sx) + sy * sy > near * near) {   // B: A's side
      const int k = side_towards(e1, Real(0), sx, sy, Real(0), Real(0));
      if (k >= 0) tighten(s, k, e1, Real(0), sx, sy);
    }
    if (!(cj == 0 && e1 > 0)) {
      const CanonicalFrame<Real> fr = canonical_frame(t.len, cj, v);
      for (int k = 0; k < 2; ++k) {
        if (!s.has(k)) continue;
        Real x, y;
        fr.to_canonical(Real(s.x[k]), Real(s.y[k]), x, y);
        s.x[k] = float(x), s.y[k] = float(y);
      }
    }
    if (!s.any()) return;
    WindowRecord<Real>& w = windows_[face_of(g)];
    w.sides = s;
    w.stamp = t.dT;
    w.written = true;
  }

  // T takes path p: its record gets the new virtual source (in T's canonical frame), and T's
  // other two edges are queued unless T lies wholly beyond the distance limit.
  template <class Push>
  void accept(Index g, FaceRecord<Real>& t, Index cj, const EdgeView<Real>& v, const Path& p,
                                     Index source, Push&& push) {
    ++stats_.face_updates;
    if (reached_ && (every_update_ || t.dT == std::numeric_limits<Real>::infinity())) reached_->push_back(face_of(g));
    if (cj == 0 && v.e1 > 0)
      t.sx = p.ex, t.sy = p.ey;   // halfedge 0's edge frame is the canonical frame
    else
      canonical_frame(t.len, cj, v).to_canonical(p.ex, p.ey, t.sx, t.sy);
    t.sigma = p.sigma;
    t.dT = p.dT;
    t.tag = (t.tag & ~kSourceMask) | source;
    // Max-distance: a face none of whose points can be within the limit is stored, not
    // expanded (its centroid is farther than the limit by more than its own radius).
    if (!(p.dT <= limit_) && !(p.dT - centroid_radius(t.len) <= limit_)) return;
    push(QueueEntry<Real>{next_halfedge(g), p.dT});
    push(QueueEntry<Real>{prev_halfedge(g), p.dT});
  }

  static constexpr Real kRelativeImprovement = std::numeric_limits<Real>::epsilon() * 4;
  static constexpr unsigned kTieBits = 8;
  // A non-negative value's float bits without the last kTieBits: ordered as the values are.
  static auto coarse(Real x) {
    using Bits = std::conditional_t<sizeof(Real) == 4, std::uint32_t, std::uint64_t>;
    Bits bits;
    std::memcpy(&bits, &x, sizeof bits);
    return bits >> kTieBits;
  }
  // Past a flat corner a source goes straight on within this many mean edge lengths (the
  // records' lengths are in mean edges; gsp/intrinsic/corner_rules.hpp).
  static constexpr Real kFlatMiss = Real(intrinsic::kFlatMiss);
  FaceRecord<Real>* faces_;
  const Index* ring_;
  ProbeTable<Real> probe_;
  Real limit_;
  StraightLineTest line_;
  std::vector<Index>* reached_ = nullptr;
  bool every_update_ = false;
  Index own_ = 0, threads_ = 1;
  unsigned stripe_shift_ = 31;
  std::vector<Mailbox<Real>>* outbox_ = nullptr;
  WindowRecord<Real>* windows_ = nullptr;        // carried windows: null when off
  const std::uint8_t* window_flags_ = nullptr;
  PropagationStats& stats_;
};

}  // namespace gsp::detail
