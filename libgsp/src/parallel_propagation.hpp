#pragma once
// Parallel propagation on CPU threads (paper Sections 4.2 and 5.7, done by ownership instead of
// atomics): the faces, in the cache layout's order, are cut into stripes dealt to the threads
// in turn; each thread runs the speed limiter on the faces it owns and sends the update steps
// that cross into another thread's stripe to its owner as messages (RemoteStep: the unfolded
// source, everything the owner needs to run the step itself). Every face record is written by
// one thread only, so no record needs an atomic; the layout keeps the stripes compact, so few
// steps cross. The threads keep their rounds within one of each other. Label-correcting like
// the sequential strategies: the fixed point is the same up to GSP's order effects (a
// different order can let a different virtual source win a face; ties: UpdateStep).
//
// A thread waiting for the others to finish a round spins on their progress (yielding) and
// reads its mail meanwhile; a thread with no work sleeps on a condition variable. The run ends
// when every thread is idle with an empty inbox. Internal header of libgsp.
#include "update_step.hpp"

#include <gsp/intrinsic/speed_limiter.hpp>

#include <atomic>
#include <condition_variable>
#include <mutex>
#include <thread>
#include <vector>

namespace gsp::detail {

// True on the threads of a parallel run and of compute_many's pool: a query started there runs
// on one thread (the caller already uses the cores).
bool& inside_parallel_region();

// Faces per ownership stripe: 2^stripe_shift(). Stripes of a coherent layout are compact
// patches; dealt in turn, every thread owns patches all over the mesh, so a front from one
// source reaches every thread's faces after a few rings, and a front a few hundred faces long
// crosses enough patches to share its work evenly. Smaller stripes send more steps as messages;
// 2^10 to 2^14 faces ran equally fast at 2.2M vertices (docs/performance.md). Small meshes
// (forced threads) get at least 64 stripes per thread.
inline unsigned stripe_shift(std::size_t num_faces, unsigned threads) {
  unsigned shift = 6;
  while (shift < 12 && (std::size_t(64) * threads << (shift + 1)) <= num_faces) ++shift;
  return shift;
}

template <class Real>
void run_parallel_speed_limiter(FaceRecord<Real>* faces, std::size_t num_faces, const Index* ring,
                                const ProbeTable<Real>& probe,
                                Real expand_limit, std::vector<QueueEntry<Real>>& seeds, Real f, unsigned threads,
                                PropagationStats& stats, bool postpone = false, bool adaptive = false,
                                const StraightLineTest& line = {}, WindowRecord<Real>* windows = nullptr,
                                const std::uint8_t* window_flags = nullptr) {
  const Real inf = std::numeric_limits<Real>::infinity();
  const unsigned shift = stripe_shift(num_faces, threads);
  struct Shared {
    std::mutex m;
    std::condition_variable cv;
    std::vector<Mailbox<Real>> inbox;
    std::vector<std::atomic<bool>> mail;
    // The limit of the last round each thread has finished (infinity while idle): a thread
    // starts its next round only when every other one has finished the round before the one
    // it has just finished (one round of slack: a strict barrier left the second thread
    // waiting), so the threads walk the front in step, as one sequential run would, instead of
    // one racing ahead on distances the other is about to lower.
    std::vector<std::atomic<Real>> finished;
    // The adaptive switch to postponing (gsp/intrinsic/speed_limiter.hpp), taken by all threads
    // once one of them sees the second front.
    std::atomic<bool> postpone{false};
    std::atomic<std::uint64_t> ahead{0}, expanded{0};   // the switch's counts over all threads
    unsigned idle = 0;
    bool done = false;
    explicit Shared(unsigned n) : inbox(n), mail(n), finished(n) {
      for (auto& x : finished) x.store(-std::numeric_limits<Real>::infinity());   // until each thread starts
    }
  } shared(threads);
  shared.postpone.store(postpone);
  std::vector<PropagationStats> local_stats(threads);

  auto worker = [&](unsigned me) {
    inside_parallel_region() = true;
    PropagationStats& st = local_stats[me];
    UpdateStep<Real, true> step(faces, ring, probe, expand_limit, st, line);
    std::vector<Mailbox<Real>> outbox(threads);
    step.partition(Index(me), Index(threads), shift, &outbox);
    step.carry_windows(windows, window_flags);   // each thread writes its own faces' windows
    std::vector<QueueEntry<Real>> a, b;
    for (const QueueEntry<Real>& e : seeds)
      if (step.owner_of(face_of(e.halfedge)) == me) a.push_back(e);
    // A thread without seeds starts with the limit below everything, so the first mail it
    // reads waits in `b` and sets its first round's limit. (With min_key of nothing, +inf,
    // it walked all it was sent in one unlimited round: label-correcting without the
    // limiter, 9-113 update steps per face from a point inside a face on two threads.)
    Real limit = a.empty() ? -inf : min_key(a) + f;
    shared.finished[me].store(limit - f, std::memory_order_release);
    auto push = [&](const QueueEntry<Real>& n) {
      ++st.enqueued;
      if (n.dT < limit) a.push_back(n); else b.push_back(n);
    };
    auto flush = [&] {
      bool sent = false;
      for (unsigned k = 0; k < threads; ++k) {
        if (outbox[k].empty()) continue;
        std::lock_guard<std::mutex> lock(shared.m);
        shared.inbox[k].append(outbox[k]);
        shared.mail[k].store(true, std::memory_order_release);
        outbox[k].clear();
        sent = true;
      }
      if (sent) shared.cv.notify_all();
    };
    Mailbox<Real> mail;
    auto take_mail = [&] {
      {
        std::lock_guard<std::mutex> lock(shared.m);
        mail.swap(shared.inbox[me]);
        shared.mail[me].store(false, std::memory_order_relaxed);
      }
      for (const RemoteStep<Real>& m : mail.steps) step.apply(m, push);
      for (const WindowedStep<Real>& m : mail.windowed) step.apply(m, push);
      mail.clear();
    };
    auto has_mail = [&] { return shared.mail[me].load(std::memory_order_acquire); };
    std::uint64_t ahead = 0, expanded = 0;   // this round's share of the switch's counts
    // Every other thread is idle or has finished its rounds up to `upto`.
    auto others_finished = [&](Real upto) {
      for (unsigned k = 0; k < threads; ++k)
        if (k != me && shared.finished[k].load(std::memory_order_acquire) < upto) return false;
      return true;
    };
    for (;;) {
      // The round: `a` grows while it is walked, and with the mail's entries below the limit.
      const bool postponing = shared.postpone.load(std::memory_order_relaxed);
      do {
        for (std::size_t i = 0; i < a.size(); ++i) {
          if (i + intrinsic::kPrefetchDistance < a.size()) step.prefetch(a[i + intrinsic::kPrefetchDistance]);
          const QueueEntry<Real> e = a[i];   // push() may grow `a`
          if (postponing && !(e.dT < limit)) {   // deferred and still beyond the limit: deferred again
            if (step.is_stale(e)) {
              ++st.stale_skipped;
            } else {
              ++st.postponed;
              b.push_back(e);
            }
            continue;
          }
          ahead += !(e.dT < limit);
          ++expanded;
          step.expand(e, push);
          if ((i & 255) == 255) {   // keep the neighbours fed and read what they sent
            flush();
            if (has_mail()) take_mail();
          }
        }
        a.clear();
        flush();
        if (has_mail()) take_mail();
        // Wait for the others to finish this round, reading their mail meanwhile (it may
        // belong to this round).
        shared.finished[me].store(limit, std::memory_order_release);
        for (unsigned spins = 0; a.empty() && !b.empty() && !others_finished(limit - f); ++spins) {
          if (has_mail()) take_mail();
          else if (spins % 64 == 63) std::this_thread::yield();
        }
      } while (!a.empty());
      ++st.iterations;
      if (adaptive && !postponing) {
        const std::uint64_t all_ahead = shared.ahead += ahead, all_expanded = shared.expanded += expanded;
        ahead = expanded = 0;
        if (all_expanded >= intrinsic::kSwitchMinExpanded &&
            double(all_ahead) > intrinsic::kSwitchAheadFraction * double(all_expanded))
          shared.postpone.store(true, std::memory_order_relaxed);
      }
      if (!b.empty()) {
        // The next round: every deferred entry, the limit at least past the nearest of them
        // (messages can arrive far ahead of this thread's own front).
        limit = std::max(limit, min_key(b)) + f;
        std::swap(a, b);
        continue;
      }
      // Nothing left here: idle until mail comes or every thread is idle.
      std::unique_lock<std::mutex> lock(shared.m);
      shared.finished[me].store(inf, std::memory_order_release);
      if (shared.inbox[me].empty()) {
        ++shared.idle;
        bool all_empty = true;
        for (const auto& in : shared.inbox) all_empty &= in.empty();
        if (shared.idle == threads && all_empty) {
          shared.done = true;
          shared.cv.notify_all();
          return;
        }
        shared.cv.wait(lock, [&] { return shared.done || !shared.inbox[me].empty(); });
        if (shared.done) return;
        --shared.idle;
      }
      // Back in the walk: the others hold their next round while the mail is read and the
      // round it starts at is known.
      shared.finished[me].store(-inf, std::memory_order_release);
      lock.unlock();
      limit = -inf;   // the mail goes to `b`; the round starts at the nearest of it
      take_mail();
      limit = min_key(b) + f;
      shared.finished[me].store(limit - f, std::memory_order_release);
      for (std::size_t i = 0; i < b.size();)
        if (b[i].dT < limit) a.push_back(b[i]), b[i] = b.back(), b.pop_back(); else ++i;
    }
  };
  {
    std::vector<std::thread> pool;
    for (unsigned k = 1; k < threads; ++k) pool.emplace_back(worker, k);
    const bool outer = inside_parallel_region();
    worker(0);
    inside_parallel_region() = outer;
    for (std::thread& t : pool) t.join();
  }
  seeds.clear();
  for (const PropagationStats& s : local_stats) {
    stats.update_steps += s.update_steps;
    stats.face_updates += s.face_updates;
    stats.enqueued += s.enqueued;
    stats.stale_skipped += s.stale_skipped;
    stats.postponed += s.postponed;
    stats.straight_line_bends += s.straight_line_bends;
    stats.window_bends += s.window_bends;
    stats.iterations = std::max(stats.iterations, s.iterations);
  }
  stats.switched_to_postpone = stats.switched_to_postpone || (shared.postpone.load() && !postpone);
}

}  // namespace gsp::detail
