#pragma once
// Measuring instruments: wall time, the time-stamp counter, heap in use, medians, and the
// relative error against exact distances.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace gsp::bench {

double now_seconds();          // steady clock (wall time)
double thread_cpu_seconds();   // CPU time of the calling thread (CLOCK_THREAD_CPUTIME_ID)

// Wall and thread CPU time since construction. On a shared machine the CPU clock leaves out
// the time the thread waited for a core, which wall time counts (--clock cpu).
struct Stopwatch {
  double wall0 = now_seconds(), cpu0 = thread_cpu_seconds();
  double wall() const { return now_seconds() - wall0; }
  double cpu() const { return thread_cpu_seconds() - cpu0; }
};

// The time-stamp counter (rdtsc) on x86; 0 elsewhere (have_cycle_counter() says which). It
// ticks at the CPU's nominal frequency whatever the current clock, so "cycles" are reference
// cycles, comparable between runs on one machine.
std::uint64_t cycle_counter();
bool have_cycle_counter();

// Bytes the allocator has handed out and not got back (glibc mallinfo2: uordblks + hblkhd,
// all arenas). 0 where unavailable (have_heap_counter() says which).
std::size_t heap_in_use();
bool have_heap_counter();

double median(std::vector<double> values);   // NaN for an empty list

// Relative errors |d - e| / e over the vertices with a finite, positive exact distance e
// (the source itself and other components are left out). An unreached vertex (d = inf)
// counts as error 1. The same definition as gsp-train-heuristic's objective.
struct ErrorStats {
  double mre = 0;               // mean relative error
  double max_re = 0;
  double signed_re = 0;         // mean of (d - e) / e: negative where the method under-estimates
  std::size_t counted = 0;      // vertices measured
  std::size_t unreached = 0;    // of those, left at +inf by the method
};
ErrorStats relative_errors(const std::vector<double>& approx, const std::vector<double>& exact);

// The CPU's name (Linux /proc/cpuinfo "model name"), or "" when unknown.
std::string cpu_model();

}  // namespace gsp::bench
