#pragma once
// OpenMP's thread count for one scope (named in test failures), restored at its end, also when an ASSERT
// leaves early: ctest runs the suite with OMP_NUM_THREADS=1, so the paths that share work between threads
// run only where a test asks for threads.
#include <gtest/gtest.h>
#include <omp.h>

#include <string>

namespace cls::test {

class ScopedOmpThreads {
 public:
  explicit ScopedOmpThreads(int threads) : trace_(__FILE__, __LINE__, std::to_string(threads) + " threads") {
    omp_set_num_threads(threads);
  }
  ~ScopedOmpThreads() { omp_set_num_threads(previous_); }
  ScopedOmpThreads(const ScopedOmpThreads&) = delete;
  ScopedOmpThreads& operator=(const ScopedOmpThreads&) = delete;

 private:
  int previous_ = omp_get_max_threads();
  ::testing::ScopedTrace trace_;
};

}  // namespace cls::test
