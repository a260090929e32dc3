#pragma once
// The speed limiter (paper Section 4.2) as a driver over any propagation (internal layer
// shared by the core's faces and the point cloud's points; not a stable API). One copy, so
// a fix to the strategy reaches every propagation.
//
// A lean dual queue: the current queue grows while it is walked; an improved element stays in
// this round while its key is below the round's limit, and the limit grows by f per round.
// With `postpone`, an entry deferred to a later round that is still beyond that round's limit
// is deferred again instead of expanded. With `adaptive`, the plain limiter turns into the
// postponing one when more than kSwitchAheadFraction of the entries it has expanded (at least
// kSwitchMinExpanded) were deferred ones still beyond the limit: the second front the
// postponing variant removes. docs/gsp-core.md ("Strategies") has the measurements.
//
// The Step type provides, for its Entry type:
//   Real key(const Entry&) const;                       // the entry's distance when queued
//   bool is_stale(const Entry&) const;                  // overtaken by a later update
//   void prefetch(const Entry&) const;                  // a hint; may do nothing
//   template <class Push> void expand(const Entry&, Push&& push);   // push(Entry) per update
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <thread>
#include <vector>

namespace gsp::intrinsic {

inline constexpr double kSwitchAheadFraction = 0.35;
inline constexpr std::uint64_t kSwitchMinExpanded = 65536;
inline constexpr std::size_t kPrefetchDistance = 8;
// Between rounds, after about this many expansions (~0.1 ms), the query offers its core to a
// thread waiting for one (std::this_thread::yield: a system call that returns at once when
// none waits; no cost measured on the corpus or at 2.2M vertices). Why: with every core busy
// with queries, the kernel lets a thread that wakes up (a Python thread starting the next
// query, or taking the GIL to return one) wait out a scheduler slice, milliseconds; 4 queries
// on 4 Python threads then ran nearly one after another. docs/python.md ("Threads").
inline constexpr std::uint64_t kYieldEveryExpanded = 1024;

struct SpeedLimiterCounters {
  std::uint64_t iterations = 0;      // rounds
  std::uint64_t enqueued = 0;
  std::uint64_t stale_skipped = 0;
  std::uint64_t postponed = 0;
  bool switched_to_postpone = false;
};

template <class Real, class Entry, class Step>
Real min_key(const Step& step, const std::vector<Entry>& q) {
  Real m = std::numeric_limits<Real>::infinity();
  for (const Entry& e : q) m = std::min(m, step.key(e));
  return m;
}

template <class Real, class Entry, class Step>
void run_speed_limiter(Step& step, std::vector<Entry>& a, Real f, SpeedLimiterCounters& counters,
                       bool postpone = false, bool adaptive = false) {
  std::uint64_t ahead = 0, expanded = 0, next_yield = kYieldEveryExpanded;
  std::vector<Entry> b;
  b.reserve(a.capacity());
  const Real inf = std::numeric_limits<Real>::infinity();
  Real limit = min_key<Real>(step, a) + f;
  Real min_next = inf;   // the smallest key deferred to the next round
  while (!a.empty()) {
    ++counters.iterations;
    for (std::size_t i = 0; i < a.size(); ++i) {
      const Entry e = a[i];   // a may grow (and move) while e is expanded
      if (i + kPrefetchDistance < a.size()) step.prefetch(a[i + kPrefetchDistance]);
      const Real k = step.key(e);
      // Deferred from an earlier round and still beyond the limit: deferred again. Expanded
      // anyway (the paper's rule), such entries form a second front that runs one ring per
      // round ahead of the limit whatever f is, and every element it reaches is updated again
      // when the true front comes.
      if (postpone && !(k < limit)) {
        if (step.is_stale(e)) {
          ++counters.stale_skipped;
          continue;
        }
        ++counters.postponed;
        b.push_back(e);
        min_next = std::min(min_next, k);
        continue;
      }
      ahead += !(k < limit);   // deferred, still beyond the limit, expanded anyway
      ++expanded;
      step.expand(e, [&](const Entry& n) {
        ++counters.enqueued;
        const Real nk = step.key(n);
        if (nk < limit) {
          a.push_back(n);
        } else {
          b.push_back(n);
          min_next = std::min(min_next, nk);
        }
      });
    }
    a.clear();
    std::swap(a, b);
    if (expanded >= next_yield) {
      next_yield = expanded + kYieldEveryExpanded;
      std::this_thread::yield();
    }
    if (adaptive && !postpone && expanded >= kSwitchMinExpanded && double(ahead) > kSwitchAheadFraction * double(expanded))
      postpone = counters.switched_to_postpone = true;
    // Skips ahead where nothing lies in the next band (large gaps, source offsets).
    const Real base = postpone ? std::max(limit, min_next) : limit;
    Real next = base + f;
    // A step below the keys' resolution (f lost in rounding: --step 1e-300, or 1e-6 in float
    // past 16 mean edges) leaves the limit where it is, and a postponing round then defers the
    // same entries for ever (gsp-geodesic hung): the limit moves at least one representable
    // value past the round's base.
    if (!(next > base)) next = std::nextafter(base, inf);
    limit = next;
    min_next = inf;
  }
}

}  // namespace gsp::intrinsic
