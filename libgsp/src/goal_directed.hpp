#pragma once
// Targeted runs (paper Section 5.8, Fig. 12a,b), internal: the propagation in a heap that stops
// once no queued face can still shorten a target's distance, optionally in A* order. A separate
// driver around the unchanged UpdateStep, so untargeted runs pay nothing for it.
#include "update_step.hpp"

#include <gsp/connectivity.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>
#include <vector>

namespace gsp::detail {

// The targets of one run: which face corners are targets, the best distance of each so far,
// and (A*) per face a lower bound of the distance still to go.
template <class Real>
class TargetSet {
 public:
  // `targets` in the triangulation's vertex numbering; `positions` the vertices in 3D (model
  // units), `scale` turns model units into the propagation's normalised units.
  TargetSet(const FaceRecord<Real>* state, const std::vector<Triangle>& triangles, const std::vector<Vec3>& positions,
            const std::vector<Index>& corner_begin, const std::vector<Index>& corners,
            const std::vector<Index>& targets, double scale, bool astar)
      : state_(state), triangles_(triangles), positions_(positions), scale_(scale), astar_(astar) {
    slot_.assign(positions.size(), kInvalidIndex);
    corner_mask_.assign(triangles.size(), 0);
    for (Index v : targets) {
      if (slot_[v] != kInvalidIndex) continue;   // listed twice
      slot_[v] = Index(vertices_.size());
      vertices_.push_back(v);
      for (Index k = corner_begin[v]; k < corner_begin[v + 1]; ++k)
        corner_mask_[face_of(corners[k])] |= std::uint8_t(1u << corner_of(corners[k]));
    }
    best_.assign(vertices_.size(), std::numeric_limits<Real>::infinity());
    if (astar_) remaining_.assign(triangles.size(), Real(-1));
  }

  // The largest target distance so far (+inf while a target is unreached): a queued face whose
  // key is not below it cannot improve any target any more.
  Real bound() const { return worst_; }

  void vertex_value(Index v, Real d) {
    if (slot_[v] != kInvalidIndex) improve(slot_[v], d);
  }

  // Face f was seeded or improved: its target corners may have become closer.
  void face_updated(Index f) {
    const std::uint8_t mask = corner_mask_[f];
    if (!mask) return;
    const FaceRecord<Real>& r = state_[f];
    for (Index i = 0; i < 3; ++i) {
      if (!(mask & (1u << i))) continue;
      Real x = 0, y = 0;
      if (i == 1) x = r.len[0];
      if (i == 2) canonical_corner2(r.len, x, y);
      improve(slot_[triangles_[f][i]], r.sigma + std::sqrt((r.sx - x) * (r.sx - x) + (r.sy - y) * (r.sy - y)));
    }
  }

  // A* lower bound of the distance from face f on to the nearest target: the straight line from
  // the centroid c, less twice the face's radius r (any path through f leaves it at a point q
  // with d(q) >= d_T - r and |q - t| >= |c - t| - r). 0 without A*.
  Real remaining(Index f) {
    if (!astar_) return 0;
    Real& h = remaining_[f];
    if (h >= 0) return h;
    const Triangle& t = triangles_[f];
    const Vec3 a = positions_[t[0]], b = positions_[t[1]], c = positions_[t[2]];
    const Vec3 g = (1.0 / 3.0) * (a + b + c);
    const double radius = std::max({distance(a, g), distance(b, g), distance(c, g)});
    double nearest = std::numeric_limits<double>::infinity();
    for (Index v : vertices_) nearest = std::min(nearest, distance(g, positions_[v]));
    h = Real(std::max(0.0, (nearest - 2 * radius) * scale_));
    return h;
  }

 private:
  void improve(Index slot, Real d) {
    if (!(d < best_[slot])) return;
    best_[slot] = d;
    worst_ = Real(0);
    for (Real b : best_) worst_ = std::max(worst_, b);
  }

  const FaceRecord<Real>* state_;
  const std::vector<Triangle>& triangles_;
  const std::vector<Vec3>& positions_;
  double scale_;
  bool astar_;
  std::vector<Index> slot_;              // per vertex: its target slot, or kInvalidIndex
  std::vector<std::uint8_t> corner_mask_;   // per face: bit i = corner i is a target
  std::vector<Index> vertices_;
  std::vector<Real> best_;
  std::vector<Real> remaining_;          // A*: per face, cached lower bound (< 0: not yet)
  Real worst_ = std::numeric_limits<Real>::infinity();
};

// Heap on key = d_T + remaining(face), stopping when the smallest key reaches the targets'
// bound. Seeds and every improved face report to the target set first.
template <class Real>
void run_targeted(UpdateStep<Real>& step, std::vector<QueueEntry<Real>>& seeds, TargetSet<Real>& goal,
                  PropagationStats& stats) {
  struct Keyed {
    Real key;
    QueueEntry<Real> entry;
  };
  auto later = [](const Keyed& x, const Keyed& y) { return x.key > y.key; };
  std::priority_queue<Keyed, std::vector<Keyed>, decltype(later)> heap(later);
  auto push = [&](const QueueEntry<Real>& n) {
    const Index f = face_of(n.halfedge);
    goal.face_updated(f);
    heap.push({n.dT + goal.remaining(f), n});
  };
  for (const QueueEntry<Real>& e : seeds) push(e);
  seeds.clear();
  while (!heap.empty() && heap.top().key < goal.bound()) {
    const QueueEntry<Real> e = heap.top().entry;
    heap.pop();
    ++stats.iterations;
    step.expand(e, [&](const QueueEntry<Real>& n) {
      ++stats.enqueued;
      push(n);
    });
  }
}

}  // namespace gsp::detail
