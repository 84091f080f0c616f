#pragma once
// Products of a few hundred rows with an L x L matrix, for the sparse cosine loss's per-tile work
// (sparse_loss.cpp): out = A M and out += X^T Y, every matrix row-major with rows of L.
//
// Hand-written, not a BLAS call, because (1) they run inside the per-build kernels (the build's registers: 16,
// 32 or 64 bytes) on one tile's rows, a few hundred, where OpenBLAS's packing of A and M for each call is a
// large share of the work, and (2) Debian 12's OpenBLAS 0.3.21 runs its AVX2 (Haswell) kernels on AMD CPUs
// with AVX-512: on the 2-core AVX-512 host these took a quarter of a sparse training iteration through
// OpenBLAS (docs/benchmarks.md, "The sparse cosine loss in one pass with its map"). The tests hold the loss
// that uses them to its LibTorch reference (SparseCosineLoss.*), with L below, at and above a register panel.
#include <cstdint>
#include <cstring>

#include "splat/blend_lanes.h"

namespace cls {

// Registers of columns per panel: 4 x 4 accumulators and a panel of M fit AVX-512's 32 registers, 4 x 2 the 16
// of AVX2 and SSE2.
template <int kBytes>
constexpr int kPanelRegisters = kBytes == 64 ? 4 : 2;

// One register from p, and to p (register by register: a whole array copied at once went through the stack).
template <int kBytes, class T>
[[gnu::always_inline]] inline typename NativeVector<T, kBytes>::V load_register(const T* p) {
  typename NativeVector<T, kBytes>::V v;
  std::memcpy(&v, p, kBytes);
  return v;
}
template <int kBytes, class T, class P>
[[gnu::always_inline]] inline void store_register(T* p, const P& v) {
  std::memcpy(p, &v, kBytes);
}

// kRows rows of out (stride l), for i < kRows and every column c:
//   out[i][c] (+)= sum over t < steps of s[i si + t st] panels[t][c]     (panels: rows of l)
// whole panels of columns in registers, the columns after them one at a time. A M and X^T Y are both this form.
template <int kBytes, int kRows, class T>
[[gnu::always_inline]] inline void scaled_row_sums(const T* s, int64_t si, int64_t st, const T* panels, int64_t l,
                                                   int64_t steps, bool accumulate, T* out) {
  using P = typename NativeVector<T, kBytes>::V;
  constexpr int R = kPanelRegisters<kBytes>, kPer = kBytes / int(sizeof(T));
  int64_t c0 = 0;
  for (; c0 + R * kPer <= l; c0 += R * kPer) {
    P acc[kRows][R];
    for (int i = 0; i < kRows; ++i)
      for (int j = 0; j < R; ++j) acc[i][j] = accumulate ? load_register<kBytes>(out + i * l + c0 + j * kPer) : P{};
    for (int64_t t = 0; t < steps; ++t) {
      P panel[R];
#pragma GCC unroll 4
      for (int j = 0; j < R; ++j) panel[j] = load_register<kBytes>(panels + t * l + c0 + j * kPer);
#pragma GCC unroll 4
      for (int i = 0; i < kRows; ++i) {
        const T x = s[i * si + t * st];
#pragma GCC unroll 4
        for (int j = 0; j < R; ++j) acc[i][j] += x * panel[j];
      }
    }
    for (int i = 0; i < kRows; ++i)
      for (int j = 0; j < R; ++j) store_register<kBytes>(out + i * l + c0 + j * kPer, acc[i][j]);
  }
  for (; c0 < l; ++c0)
    for (int i = 0; i < kRows; ++i) {
      T sum = accumulate ? out[i * l + c0] : T(0);
      for (int64_t t = 0; t < steps; ++t) sum += s[i * si + t * st] * panels[t * l + c0];
      out[i * l + c0] = sum;
    }
}

// out = A M for A rows x l, M l x l.
template <int kBytes, class T>
[[gnu::always_inline]] inline void rows_times_matrix(const T* a, int64_t rows, int64_t l, const T* m, T* out) {
  int64_t r = 0;
  for (; r + 4 <= rows; r += 4) scaled_row_sums<kBytes, 4>(a + r * l, l, 1, m, l, l, false, out + r * l);
  for (; r < rows; ++r) scaled_row_sums<kBytes, 1>(a + r * l, l, 1, m, l, l, false, out + r * l);
}

// out (l x l) += X^T Y for X, Y rows x l.
template <int kBytes, class T>
[[gnu::always_inline]] inline void add_transposed_product(const T* x, const T* y, int64_t rows, int64_t l, T* out) {
  int64_t i = 0;
  for (; i + 4 <= l; i += 4) scaled_row_sums<kBytes, 4>(x + i, 1, l, y, l, rows, true, out + i * l);
  for (; i < l; ++i) scaled_row_sums<kBytes, 1>(x + i, 1, l, y, l, rows, true, out + i * l);
}

}  // namespace cls
