#pragma once
// ChannelCosines (rasterize_cpu.h) for the 16 pixels of a sub-tile at once: the blended channels of the tile
// kernels' accumulators (acc[c], one lane per pixel) in, the P cosines per lane out, a register of lanes at a
// time as the rest of blend_lanes.h. Each accumulator row is loaded once per block of matrix rows, so the
// work is the multiply-adds, not the loads. Checked against the features rendered and compared in double
// (test_rasterize_cosines).
#include <cmath>
#include <cstddef>

#include "splat/blend_lanes.h"
#include "splat/rasterize_cpu.h"

namespace cls {

// y[r] = sum over c in [c0, nc) of m[r nc + c] acc[c] for kRows rows of m, on the register of lanes that
// starts `at` bytes in.
template <int kBytes, int kRows, class T, class P>
[[gnu::always_inline]] inline void rows_times_lanes(const Lanes<T>* acc, const T* m, int nc, int c0, std::size_t at,
                                                    P* y) {
  for (int r = 0; r < kRows; ++r) y[r] = P{};
  for (int c = c0; c < nc; ++c) {
    const P x = lane_register<kBytes>(acc[c], at);
    for (int r = 0; r < kRows; ++r) y[r] += x * m[static_cast<std::size_t>(r) * nc + c];
  }
}

// cosine[p] (P = cs.count vectors of lanes) = cos(F, p) per lane for the blended channels acc[0..nc).
template <int kBytes, class T>
[[gnu::always_inline]] inline void lane_cosines(const Lanes<T>* acc, int nc, const ChannelCosines<T>& cs,
                                                Lanes<T>* cosine) {
  using P = typename NativeVector<T, kBytes>::V;
  constexpr int kRows = 8;  // rows of R or directions per pass over acc: a load of acc per 8 multiply-adds
  const int k = cs.factor_rows, np = cs.count;
  Lanes<T> norm2;
  for (std::size_t at = 0; at < sizeof(Lanes<T>); at += kBytes) {
    P n2{}, y[kRows];
    // |R w|^2, R's rows kRows at a time from their diagonal (the rows below the first start with zeros)
    int i = 0;
    for (; i + kRows <= k; i += kRows) {
      rows_times_lanes<kBytes, kRows, T>(acc, cs.factor + static_cast<std::size_t>(i) * nc, nc, i, at, y);
      for (int r = 0; r < kRows; ++r) n2 += y[r] * y[r];
    }
    for (; i < k; ++i) {
      rows_times_lanes<kBytes, 1, T>(acc, cs.factor + static_cast<std::size_t>(i) * nc, nc, i, at, y);
      n2 += y[0] * y[0];
    }
    set_lane_register<kBytes>(norm2, at, n2);
    int p = 0;
    for (; p + kRows <= np; p += kRows) {
      rows_times_lanes<kBytes, kRows, T>(acc, cs.directions + static_cast<std::size_t>(p) * nc, nc, 0, at, y);
      for (int r = 0; r < kRows; ++r) set_lane_register<kBytes>(cosine[p + r], at, y[r]);
    }
    for (; p < np; ++p) {
      rows_times_lanes<kBytes, 1, T>(acc, cs.directions + static_cast<std::size_t>(p) * nc, nc, 0, at, y);
      set_lane_register<kBytes>(cosine[p], at, y[0]);
    }
  }
  for (int l = 0; l < kLanes; ++l) {
    const T inverse = norm2[l] > T(0) ? T(1) / std::sqrt(norm2[l]) : T(0);
    for (int q = 0; q < np; ++q) cosine[q][l] *= inverse;
  }
}

}  // namespace cls
