#pragma once
// The queue strategies that drive the update step (paper Section 4.2; update_step.hpp): the
// speed limiter with its adaptive switch to postponing (the shared driver,
// gsp/intrinsic/speed_limiter.hpp), the ping-pong postponing schemes and a binary heap.
// Internal header, templated on the scalar type like UpdateStep.
#include "update_step.hpp"

#include <gsp/geodesics.hpp>
#include <gsp/intrinsic/speed_limiter.hpp>

#include <algorithm>
#include <limits>
#include <queue>
#include <utility>
#include <vector>

namespace gsp::detail {

template <class Real>
Real min_key(const std::vector<QueueEntry<Real>>& q) {
  Real m = std::numeric_limits<Real>::infinity();
  for (const auto& e : q) m = std::min(m, e.dT);
  return m;
}

// The speed limiter and its adaptive switch to postponing: the shared driver
// (gsp/intrinsic/speed_limiter.hpp), counted into the query's statistics.
template <class Real>
void run_speed_limiter(UpdateStep<Real>& step, std::vector<QueueEntry<Real>>& a, Real f, PropagationStats& stats,
                       bool postpone = false, bool adaptive = false) {
  intrinsic::SpeedLimiterCounters counters;
  intrinsic::run_speed_limiter(step, a, f, counters, postpone, adaptive);
  stats.iterations += counters.iterations;
  stats.enqueued += counters.enqueued;
  stats.stale_skipped += counters.stale_skipped;
  stats.postponed += counters.postponed;
  stats.switched_to_postpone = stats.switched_to_postpone || counters.switched_to_postpone;
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
