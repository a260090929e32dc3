#pragma once
// Wall-clock timings of the phases of a run, for the "timings" object of --stats, and the
// process's peak resident memory at the end of each phase, for its "memory" object.
//
// The contract's phases are read, build, layout, compute and write; apps may add their own.
// A phase timed twice accumulates. steady_clock: immune to clock changes during a run.
//
//   gsp::cli::PhaseTimer timer;
//   auto mesh = timer.time("read", [&] { return gsp::io::read_mesh(path); });
//   { auto scope = timer.scope("compute"); run(); }   // timed until scope ends
//   stats["timings"] = timer.to_json();               // {"read": 0.01, "compute": 1.2, "total": ...}
#include <gsp/cli/json.hpp>

#include <chrono>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace gsp::cli {

class PhaseTimer {
 public:
  using Clock = std::chrono::steady_clock;

  PhaseTimer() : start_(Clock::now()) {}

  // Adds `seconds` to phase `name` (created on first use, in first-use order) and notes the
  // peak resident memory so far as the phase's.
  void add(const std::string& name, double seconds);
  // Seconds spent in `name` so far (0 if never timed).
  double seconds(const std::string& name) const;
  // Seconds since the timer was made.
  double elapsed() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }

  // Times the scope it lives in; movable so that scope() can return it.
  class Scope {
   public:
    Scope(PhaseTimer& timer, std::string name) : timer_(&timer), name_(std::move(name)), t0_(Clock::now()) {}
    Scope(Scope&& other) noexcept : timer_(other.timer_), name_(std::move(other.name_)), t0_(other.t0_) {
      other.timer_ = nullptr;
    }
    Scope(const Scope&) = delete;
    Scope& operator=(const Scope&) = delete;
    Scope& operator=(Scope&&) = delete;
    ~Scope() { stop(); }
    // Ends the phase early; later calls do nothing.
    void stop() {
      if (!timer_) return;
      timer_->add(name_, std::chrono::duration<double>(Clock::now() - t0_).count());
      timer_ = nullptr;
    }

   private:
    PhaseTimer* timer_;
    std::string name_;
    Clock::time_point t0_;
  };

  [[nodiscard]] Scope scope(std::string name) { return Scope(*this, std::move(name)); }

  // Runs f() as phase `name` and returns what it returns (the time counts even if f throws).
  template <class F>
  decltype(auto) time(std::string name, F&& f) {
    Scope s(*this, std::move(name));
    return std::forward<F>(f)();
  }

  // {"phase": seconds, ..., "total": seconds since construction}.
  Json to_json() const;
  // Into `memory` (other members kept): "peak_bytes", the run's peak so far, and "peak_after":
  // {"phase": the peak when it ended}; with vertices > 0 also "peak_bytes_per_vertex" and
  // "peak_after_per_vertex".
  void write_memory(Json& memory, std::size_t vertices) const;

 private:
  struct Phase {
    std::string name;
    double seconds = 0;
    std::size_t peak_after = 0;   // bytes of resident memory, the peak when the phase last ended
  };
  Clock::time_point start_;
  std::vector<Phase> phases_;
  std::size_t peak_ = 0;   // the largest peak read so far
};

}  // namespace gsp::cli
