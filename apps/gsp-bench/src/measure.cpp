#include "measure.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <limits>

#include <time.h>

#if defined(__x86_64__) || defined(__i386__)
#include <x86intrin.h>
#define GSP_BENCH_RDTSC 1
#endif

#if defined(__GLIBC__) && (__GLIBC__ > 2 || (__GLIBC__ == 2 && __GLIBC_MINOR__ >= 33))
#include <malloc.h>
#define GSP_BENCH_MALLINFO2 1
#endif

namespace gsp::bench {

double now_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

double thread_cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

std::uint64_t cycle_counter() {
#ifdef GSP_BENCH_RDTSC
  return __rdtsc();
#else
  return 0;
#endif
}

bool have_cycle_counter() {
#ifdef GSP_BENCH_RDTSC
  return true;
#else
  return false;
#endif
}

std::size_t heap_in_use() {
#ifdef GSP_BENCH_MALLINFO2
  const struct mallinfo2 m = mallinfo2();
  return m.uordblks + m.hblkhd;
#else
  return 0;
#endif
}

bool have_heap_counter() {
#ifdef GSP_BENCH_MALLINFO2
  return true;
#else
  return false;
#endif
}

double median(std::vector<double> v) {
  if (v.empty()) return std::numeric_limits<double>::quiet_NaN();
  const std::size_t mid = v.size() / 2;
  std::nth_element(v.begin(), v.begin() + mid, v.end());
  if (v.size() % 2) return v[mid];
  const double upper = v[mid];
  return 0.5 * (*std::max_element(v.begin(), v.begin() + mid) + upper);
}

ErrorStats relative_errors(const std::vector<double>& approx, const std::vector<double>& exact) {
  ErrorStats s;
  double sum = 0, signed_sum = 0;
  const std::size_t n = std::min(approx.size(), exact.size());
  for (std::size_t v = 0; v < n; ++v) {
    const double e = exact[v];
    if (!(e > 0) || !std::isfinite(e)) continue;
    double re = 1;
    double sre = 1;
    if (std::isfinite(approx[v])) sre = (approx[v] - e) / e, re = std::abs(sre);
    else ++s.unreached;
    sum += re;
    signed_sum += sre;
    s.max_re = std::max(s.max_re, re);
    ++s.counted;
  }
  if (s.counted) s.mre = sum / double(s.counted), s.signed_re = signed_sum / double(s.counted);
  return s;
}

std::string cpu_model() {
  std::ifstream in("/proc/cpuinfo");
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("model name", 0) != 0) continue;
    const auto colon = line.find(':');
    if (colon == std::string::npos) break;
    const auto start = line.find_first_not_of(' ', colon + 1);
    return start == std::string::npos ? "" : line.substr(start);
  }
  return "";
}

}  // namespace gsp::bench
