#pragma once
// How many threads OpenBLAS may use, for one scope. Debian's LibTorch calls OpenBLAS, whose pthread
// build (libopenblas0-pthread) keeps its own pool beside LibTorch's OpenMP one. Where GEMMs alternate
// with element-wise ops (SAM's mask decoder, the transformers' blocks), the two pools take turns
// spinning on the same cores: on 2 cores the decoder ran 2.2x slower than with OpenBLAS held to the
// calling thread, and the encoders split their GEMMs over LibTorch's threads instead
// (models/parallel_linear.h, docs/benchmarks.md). The functions are looked up at run time, so this is a
// no-op with another BLAS.
namespace cls {

class ScopedBlasThreads {
 public:
  explicit ScopedBlasThreads(int threads);
  ~ScopedBlasThreads();
  ScopedBlasThreads(const ScopedBlasThreads&) = delete;
  ScopedBlasThreads& operator=(const ScopedBlasThreads&) = delete;

 private:
  int previous_ = 0;  // 0: OpenBLAS not found, nothing to restore
};

// OpenBLAS's current thread count, or 0 when OpenBLAS is not loaded.
int blas_threads();

}  // namespace cls
