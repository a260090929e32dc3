#include <gsp/cli/progress.hpp>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace gsp::cli {

bool stderr_is_terminal() { return ::isatty(STDERR_FILENO) == 1; }

Progress::Progress(std::string prefix, std::string label, bool enabled)
    : prefix_(std::move(prefix)), label_(std::move(label)), enabled_(enabled) {}

void Progress::update(double fraction) {
  if (!enabled_) return;
  std::unique_lock<std::mutex> lock(mutex_, std::try_to_lock);
  if (!lock.owns_lock() || !enabled_) return;
  if (!(fraction >= 0.0)) fraction = 0.0;  // also catches NaN
  fraction = std::min(fraction, 1.0);
  const int percent = static_cast<int>(std::floor(fraction * 100.0));
  const auto now = std::chrono::steady_clock::now();
  // Redrawing a terminal line costs a system call: 10 redraws per second are plenty.
  if (percent == last_percent_) return;
  if (percent < 100 && drawn_ && now - last_draw_ < std::chrono::milliseconds(100)) return;
  last_draw_ = now;
  last_percent_ = percent;
  draw(fraction);
}

void Progress::draw(double fraction) {
  std::fprintf(stderr, "\r%s: %s %3d%%", prefix_.c_str(), label_.c_str(),
               static_cast<int>(std::floor(fraction * 100.0)));
  std::fflush(stderr);
  drawn_ = true;
}

ProgressCallback Progress::callback() {
  if (!enabled_) return {};
  return [this](double fraction) { update(fraction); };
}

void Progress::finish() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (drawn_) {
    std::fputs("\r\033[K", stderr);  // carriage return + erase to end of line
    std::fflush(stderr);
  }
  drawn_ = false;
  enabled_ = false;
}

}  // namespace gsp::cli
