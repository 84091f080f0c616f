#pragma once
// Transformer GEMMs on one thread pool. Debian's LibTorch runs element-wise ops on its OpenMP threads
// and hands each GEMM to OpenBLAS, whose pthread build keeps a second pool: on a CPU with few cores
// the two take turns spinning and yielding on the same cores (the SAM encoder spent a third of its
// time in libgomp spins and sched_yield, docs/benchmarks.md). Under ScopedBlasThreads(1), these split
// the GEMMs over LibTorch's threads instead, each block one BLAS call on its own thread.
#include <ATen/core/Tensor.h>

#include "core/blas_threads.h"

namespace cls {

// Whether to split CPU work on x (and what derives from it) over LibTorch's threads by hand: on the
// CPU, with more than one thread, and only where autograd records nothing (the worker threads do not
// record it): grad mode off, or x not requiring grad.
bool split_over_threads(const at::Tensor& x);

// OpenBLAS held to the calling thread for a scope whose work on x is split over LibTorch's threads
// (split_over_threads); otherwise left as it is.
ScopedBlasThreads blas_threads_for_split(const at::Tensor& x);

// linear(x, weight, bias) with x's rows split over LibTorch's threads (when split_over_threads and
// there are rows enough; else at::linear). x [..., in], weight [out, in], bias [out] or undefined.
at::Tensor parallel_rows_linear(const at::Tensor& x, const at::Tensor& weight, const at::Tensor& bias);

}  // namespace cls
