#include "core/blas_threads.h"

#include <dlfcn.h>

namespace cls {

namespace {
using SetThreads = void (*)(int);
using GetThreads = int (*)();
SetThreads set_fn() { return reinterpret_cast<SetThreads>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads")); }
GetThreads get_fn() { return reinterpret_cast<GetThreads>(dlsym(RTLD_DEFAULT, "openblas_get_num_threads")); }
}  // namespace

int blas_threads() {
  const GetThreads get = get_fn();
  return get ? get() : 0;
}

ScopedBlasThreads::ScopedBlasThreads(int threads) {
  const SetThreads set = set_fn();
  previous_ = set ? blas_threads() : 0;
  if (previous_ > 0 && threads != previous_) set(threads);
}

ScopedBlasThreads::~ScopedBlasThreads() {
  if (previous_ > 0 && previous_ != blas_threads()) set_fn()(previous_);
}

}  // namespace cls
