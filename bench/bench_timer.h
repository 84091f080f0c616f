#pragma once
// Wall-clock and process CPU time for the benchmarks. On a shared machine, work per CPU-second x
// threads estimates what the threads would reach on idle cores (docs/benchmarks.md says which
// figure a run reports).
#include <time.h>

#include <chrono>

namespace cls::bench {

using Clock = std::chrono::steady_clock;

inline double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

inline double cpu_seconds() {
  timespec t;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

}  // namespace cls::bench
