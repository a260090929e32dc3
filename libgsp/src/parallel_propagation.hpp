#pragma once
// Parallel propagation on CPU threads (paper Sections 4.2 and 5.7, done by ownership instead of
// atomics): the faces, in the cache layout's order, are cut into one contiguous block per
// thread; each thread runs the speed limiter on the faces it owns and sends the update steps
// that cross into another block to that block's owner as messages (RemoteStep: the unfolded
// source, everything the owner needs to run the step itself). Every face record is written by
// one thread only, so no record needs an atomic; the layout keeps the blocks compact, so few
// steps cross. Label-correcting like the sequential strategies: the fixed point is the same up
// to GSP's order effects (a different order can let a different virtual source win a face).
//
// Idle threads sleep on a condition variable (no spinning); the run ends when every thread is
// idle with an empty inbox. Internal header of libgsp.
#include "propagation.hpp"

#include <atomic>
#include <condition_variable>
#include <mutex>
#include <thread>
#include <vector>

namespace gsp::detail {

// True on the threads of a parallel run and of compute_many's pool: a query started there runs
// on one thread (the caller already uses the cores).
bool& inside_parallel_region();

template <class Real>
void run_parallel_speed_limiter(FaceRecord<Real>* faces, std::size_t num_faces, const Index* ring,
                                const ProbeTable<Real>& probe, Real expand_limit, std::vector<QueueEntry<Real>>& seeds,
                                Real f, unsigned threads, PropagationStats& stats) {
  const Index chunk = Index((num_faces + threads - 1) / threads);
  struct Shared {
    std::mutex m;
    std::condition_variable cv;
    std::vector<std::vector<RemoteStep<Real>>> inbox;
    std::vector<std::atomic<bool>> mail;
    unsigned idle = 0;
    bool done = false;
    explicit Shared(unsigned n) : inbox(n), mail(n) {}
  } shared(threads);
  std::vector<PropagationStats> local_stats(threads);

  auto worker = [&](unsigned me) {
    inside_parallel_region() = true;
    PropagationStats& st = local_stats[me];
    UpdateStep<Real, true> step(faces, ring, probe, expand_limit, st);
    std::vector<std::vector<RemoteStep<Real>>> outbox(threads);
    step.partition(Index(me) * chunk, std::min<Index>(Index(num_faces), Index(me + 1) * chunk), chunk, &outbox);
    std::vector<QueueEntry<Real>> a, b;
    for (const QueueEntry<Real>& e : seeds)
      if (face_of(e.halfedge) / chunk == me) a.push_back(e);
    Real limit = min_key(a) + f;
    auto push = [&](const QueueEntry<Real>& n) {
      ++st.enqueued;
      if (n.dT < limit) a.push_back(n); else b.push_back(n);
    };
    auto flush = [&] {
      bool sent = false;
      for (unsigned k = 0; k < threads; ++k) {
        if (outbox[k].empty()) continue;
        std::lock_guard<std::mutex> lock(shared.m);
        auto& in = shared.inbox[k];
        in.insert(in.end(), outbox[k].begin(), outbox[k].end());
        shared.mail[k].store(true, std::memory_order_release);
        outbox[k].clear();
        sent = true;
      }
      if (sent) shared.cv.notify_all();
    };
    std::vector<RemoteStep<Real>> mail;
    auto take_mail = [&] {
      {
        std::lock_guard<std::mutex> lock(shared.m);
        mail.swap(shared.inbox[me]);
        shared.mail[me].store(false, std::memory_order_relaxed);
      }
      for (const RemoteStep<Real>& m : mail) step.apply(m, push);
      mail.clear();
    };
    for (;;) {
      while (!a.empty()) {
        ++st.iterations;
        for (std::size_t i = 0; i < a.size(); ++i) {
          const QueueEntry<Real> e = a[i];   // push() may grow `a`
          step.expand(e, push);
          if ((i & 1023) == 1023) {   // keep the neighbours fed and read what they sent
            flush();
            if (shared.mail[me].load(std::memory_order_acquire)) take_mail();
          }
        }
        a.clear();
        std::swap(a, b);
        // The next round's limit, at least past the nearest queued entry (messages can arrive
        // far ahead of this thread's own front).
        limit = std::max(limit + f, min_key(a) + f);
      }
      flush();
      std::unique_lock<std::mutex> lock(shared.m);
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
      lock.unlock();
      take_mail();
      // Entries the mail produced: start a round at the nearest.
      limit = min_key(a.empty() ? b : a) + f;
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
    stats.iterations = std::max(stats.iterations, s.iterations);
  }
}

}  // namespace gsp::detail
