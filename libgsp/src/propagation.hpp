#pragma once
// The GSP update step (paper Section 4.1) and the queue strategies that drive it (Section 4.2).
// Internal header: templated on the scalar type, instantiated for float and double in
// geodesic_solver.cpp. The hot loop allocates nothing and calls nothing virtual.
#include "intrinsic_geometry.hpp"

#include <gsp/geodesics.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <vector>

namespace gsp::detail {

// Radial links: ring[h] = next halfedge g on h's undirected edge in the low 30 bits,
// bit 31 = g runs from its smaller to its larger vertex index, bit 30 = the same for h.
// Two halfedges run the same way (inconsistent orientation) iff their bits are equal.
inline constexpr Index kRingIndexMask = 0x3fffffffu;
inline constexpr Index kRingNextDir = 0x80000000u;
inline constexpr Index kRingSelfDir = 0x40000000u;

template <class Real>
struct FaceState {
  Real d2[3];     // squared distance of each corner to the virtual source, in the face's unfolding
  Real sigma;     // path length behind the virtual source
  Real dT;        // distance of the centroid (the key of every comparison)
  Index source;   // which input source this face's path comes from
};

// A lean-queue entry: the halfedge of the face to propagate from (bit 31: the virtual source lies
// beyond this edge, on the side of the face we move into), and that face's d_T when queued, so
// that entries overtaken by a later update are recognised as stale and skipped.
template <class Real>
struct QueueEntry {
  Index code;
  Real dT;
};

inline constexpr Index kSideBit = 0x80000000u;

template <class Real>
class UpdateStep {
 public:
  UpdateStep(const HalfedgeGeometry<Real>* geometry, const Index* ring, FaceState<Real>* state,
             Real expand_limit, PropagationStats& stats)
      : geo_(geometry), ring_(ring), state_(state), limit_(expand_limit), stats_(stats) {}

  bool is_stale(const QueueEntry<Real>& e) const {
    return state_[face_of(e.code & ~kSideBit)].dT < e.dT;
  }

  // Propagates the virtual source of the entry's face over its halfedge into every other face
  // of the edge's radial ring; push(entry) receives the entries of each improved face.
  template <class Push>
  void expand(const QueueEntry<Real>& entry, Push&& push) {
    const Index h = entry.code & ~kSideBit;
    const bool beyond = (entry.code & kSideBit) != 0;
    const FaceState<Real>& su = state_[face_of(h)];
    if (su.dT < entry.dT) {
      ++stats_.stale_skipped;
      return;
    }
    const Index ci = corner_of(h);
    const Real d_from = su.d2[ci];
    const Real d_to = su.d2[ci == 2 ? 0 : ci + 1];
    const Real sigma = su.sigma;
    const Index source = su.source;

    Index link = ring_[h];
    const bool h_dir = (link & kRingSelfDir) != 0;
    for (Index g = link & kRingIndexMask; g != h; link = ring_[g], g = link & kRingIndexMask) {
      ++stats_.update_steps;
      // A = from(g). Consistently oriented neighbours run the edge the other way, so A = to(h).
      const bool same_dir = ((link & kRingNextDir) != 0) == h_dir;
      const Real dA = same_dir ? d_from : d_to;
      const Real dB = same_dir ? d_to : d_from;
      const HalfedgeGeometry<Real>& G = geo_[g];
      const Real e1 = G.e1;
      const Real sx = (e1 * e1 + dA - dB) * G.inv_2e1;
      const Real sy = std::sqrt(std::max(Real(0), dA - sx * sx));   // source at (sx, -sy)
      const Real cx = (G.px + e1) * Real(1.0 / 3.0);
      const Real cy = G.py * Real(1.0 / 3.0);

      int kind;   // 0: straight through, 1: new virtual source at A, 2: at B
      if (!beyond) {
        // Does the segment probe -> source cross AB? Division-free form of the paper's
        // t = Qx + alpha (Sx - Qx), scaled by (qy + sy) >= 0.
        const Real t = G.qx * sy + sx * G.qy;
        kind = t < 0 ? 1 : (t > e1 * (G.qy + sy) ? 2 : 0);
      } else {
        // The source lies on T's side of the edge: no straight path crosses it; bend at the
        // end that gives the shorter path source -> corner -> centroid.
        const Real l1 = std::sqrt(cx * cx + cy * cy) + std::sqrt(dA);
        const Real l2 = std::sqrt((cx - e1) * (cx - e1) + cy * cy) + std::sqrt(dB);
        kind = l1 <= l2 ? 1 : 2;
      }

      Real new_sigma, new_dT, nA, nB, nP;
      if (kind == 0) {
        new_sigma = sigma;
        const Real dx = cx - sx, dy = cy + sy;
        new_dT = sigma + std::sqrt(dx * dx + dy * dy);
        nA = dA;
        nB = dB;
        const Real px = G.px - sx, py = G.py + sy;
        nP = px * px + py * py;
      } else if (kind == 1) {
        new_sigma = sigma + std::sqrt(dA);
        new_dT = new_sigma + std::sqrt(cx * cx + cy * cy);
        nA = 0;
        nB = e1 * e1;
        nP = G.px * G.px + G.py * G.py;
      } else {
        new_sigma = sigma + std::sqrt(dB);
        new_dT = new_sigma + std::sqrt((cx - e1) * (cx - e1) + cy * cy);
        nA = e1 * e1;
        nB = 0;
        nP = (G.px - e1) * (G.px - e1) + G.py * G.py;
      }

      const Index T = face_of(g);
      FaceState<Real>& st = state_[T];
      // Only a clearly shorter path counts: an improvement lost in rounding would bounce
      // between faces forever.
      if (!(new_dT + new_dT * kRelativeImprovement < st.dT)) continue;
      ++stats_.face_updates;
      const Index cj = corner_of(g);
      const Index cb = cj == 2 ? 0 : cj + 1;
      const Index cp = cb == 2 ? 0 : cb + 1;
      st.d2[cj] = nA;
      st.d2[cb] = nB;
      st.d2[cp] = nP;
      st.sigma = new_sigma;
      st.dT = new_dT;
      st.source = source;
      if (!(new_dT <= limit_)) continue;   // max-distance: stored, not expanded

      // Side bits for the two outgoing edges (only a straight update can leave the source
      // beyond one of them; a source at A or B lies on the lines of both).
      Index bit_bp = 0, bit_pa = 0;
      if (kind == 0) {
        bit_bp = ((G.px - e1) * sy + G.py * (sx - e1) > 0) ? kSideBit : 0;
        bit_pa = (G.px * sy + G.py * sx < 0) ? kSideBit : 0;
      }
      const Index base = g - cj;
      push(QueueEntry<Real>{(base + cb) | bit_bp, new_dT});
      push(QueueEntry<Real>{(base + cp) | bit_pa, new_dT});
    }
  }

 private:
  static constexpr Real kRelativeImprovement = std::numeric_limits<Real>::epsilon() * 4;
  const HalfedgeGeometry<Real>* geo_;
  const Index* ring_;
  FaceState<Real>* state_;
  Real limit_;
  PropagationStats& stats_;
};

// ---- Strategies -----------------------------------------------------------------------------

template <class Real>
Real min_key(const std::vector<QueueEntry<Real>>& q) {
  Real m = std::numeric_limits<Real>::infinity();
  for (const auto& e : q) m = std::min(m, e.dT);
  return m;
}

// Speed limiter with a lean queue: the current queue grows while it is walked; an improved
// face stays in this round while its distance is below the round's limit.
template <class Real>
void run_speed_limiter(UpdateStep<Real>& step, std::vector<QueueEntry<Real>>& a, Real f,
                       PropagationStats& stats) {
  std::vector<QueueEntry<Real>> b;
  b.reserve(a.capacity());
  Real limit = min_key(a) + f;
  while (!a.empty()) {
    ++stats.iterations;
    for (std::size_t i = 0; i < a.size(); ++i) {
      const QueueEntry<Real> e = a[i];
      step.expand(e, [&](const QueueEntry<Real>& n) {
        ++stats.enqueued;
        if (n.dT < limit) a.push_back(n); else b.push_back(n);
      });
    }
    a.clear();
    std::swap(a, b);
    limit += f;
  }
}

enum class Postpone { none, fixed, dynamic, hybrid };

// The ping-pong schemes: every new entry goes to the next round; entries beyond the round's
// threshold d_i are postponed (moved on untouched).
template <class Real>
void run_postpone(UpdateStep<Real>& step, std::vector<QueueEntry<Real>>& a, Postpone kind, Real f,
                  Real f0, Real f1, PropagationStats& stats) {
  std::vector<QueueEntry<Real>> b;
  b.reserve(a.capacity());
  const Real inf = std::numeric_limits<Real>::infinity();
  Real min_next = min_key(a);
  Real d = kind == Postpone::none ? inf : (kind == Postpone::hybrid ? min_next + f0 : min_next + f);
  while (!a.empty()) {
    ++stats.iterations;
    min_next = inf;
    for (const QueueEntry<Real>& e : a) {
      if (step.is_stale(e)) {
        ++stats.stale_skipped;
        continue;
      }
      if (e.dT > d) {
        ++stats.postponed;
        b.push_back(e);
        min_next = std::min(min_next, e.dT);
        continue;
      }
      step.expand(e, [&](const QueueEntry<Real>& n) {
        ++stats.enqueued;
        b.push_back(n);
        min_next = std::min(min_next, n.dT);
      });
    }
    a.clear();
    std::swap(a, b);
    switch (kind) {
      case Postpone::none: break;
      // A fixed band skips ahead when nothing lies in it (e.g. sources with large offsets).
      case Postpone::fixed: d = std::max(d + f, min_next); break;
      case Postpone::dynamic: d = min_next + f; break;
      case Postpone::hybrid: d = std::max(min_next + f0, d + f1); break;
    }
  }
}

template <class Real>
void run_priority_queue(UpdateStep<Real>& step, std::vector<QueueEntry<Real>>& seeds,
                        PropagationStats& stats) {
  auto later = [](const QueueEntry<Real>& x, const QueueEntry<Real>& y) { return x.dT > y.dT; };
  std::priority_queue<QueueEntry<Real>, std::vector<QueueEntry<Real>>, decltype(later)> heap(
      later, std::move(seeds));
  while (!heap.empty()) {
    const QueueEntry<Real> e = heap.top();
    heap.pop();
    ++stats.iterations;
    step.expand(e, [&](const QueueEntry<Real>& n) {
      ++stats.enqueued;
      heap.push(n);
    });
  }
}

}  // namespace gsp::detail
