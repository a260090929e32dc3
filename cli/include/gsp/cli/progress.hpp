#pragma once
// Progress on stderr for long work. Library code never prints: it is handed a
// ProgressCallback and calls it with the fraction done; the app decides whether anything
// is drawn. Drawing happens only when stderr is a terminal and --quiet was not given
// (Context::progress() decides), so logs and pipes never see carriage returns.
#include <atomic>
#include <chrono>
#include <functional>
#include <mutex>
#include <string>

namespace gsp::cli {

// What the library accepts: called with a fraction in [0, 1], possibly from worker threads,
// possibly often; it must be cheap, and may be empty (check before calling).
using ProgressCallback = std::function<void(double fraction)>;

// True when file descriptor 2 is a terminal.
bool stderr_is_terminal();

// One progress line "gsp-geodesic: computing  42%". Redraws at most every 100 ms (and when
// it reaches 100%); the line is erased when the reporter is finished or destroyed.
// Thread-safe: concurrent update() calls skip the redraw rather than wait for it.
class Progress {
 public:
  // A disabled reporter ignores every call.
  Progress(std::string prefix, std::string label, bool enabled);
  ~Progress() { finish(); }
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  bool enabled() const { return enabled_; }
  void update(double fraction);
  // A callback bound to this reporter; it must not be called after the reporter is gone.
  // Empty when the reporter is disabled, so the library can skip the calls entirely.
  ProgressCallback callback();
  // Erases the line; later updates are ignored.
  void finish();

 private:
  void draw(double fraction);  // caller holds mutex_

  std::string prefix_, label_;
  std::atomic<bool> enabled_;   // read without the lock on the fast path
  bool drawn_ = false;
  int last_percent_ = -1;
  std::chrono::steady_clock::time_point last_draw_{};
  std::mutex mutex_;
};

}  // namespace gsp::cli
