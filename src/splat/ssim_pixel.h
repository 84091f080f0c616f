#pragma once
// One pixel's SSIM from its blurred local moments, and the derivatives the backward needs: the math
// shared by the CPU kernels (ssim_cpu.cpp) and the CUDA kernels (ssim_cuda.cu). The constants are
// ssim_cpu.h's (3DGS's C1 = 0.01^2, C2 = 0.03^2).
#include "core/host_device.h"

namespace cls {

constexpr double kSsimC1 = 0.01 * 0.01, kSsimC2 = 0.03 * 0.03;  // for a dynamic range of 1

// SSIM from mu_a, mu_b, E[a^2], E[b^2], E[ab]; with d not null, d[0..2] receive dSSIM/dmu_a,
// dSSIM/dE[a^2] and dSSIM/dE[ab] (dividing by the denominator only, as the map itself).
template <class T>
CLS_HD T ssim_pixel(T ma, T mb, T e_aa, T e_bb, T e_ab, T* d) {
  const T mab = ma * mb;
  const T A1 = 2 * mab + T(kSsimC1), A2 = 2 * (e_ab - mab) + T(kSsimC2);
  const T B1 = ma * ma + mb * mb + T(kSsimC1), B2 = (e_aa - ma * ma) + (e_bb - mb * mb) + T(kSsimC2);
  const T D = B1 * B2, s = (A1 * A2) / D;
  if (d) {
    d[0] = (2 * mb * (A2 - A1) - s * 2 * ma * (B2 - B1)) / D;
    d[1] = -s * B1 / D;
    d[2] = 2 * A1 / D;
  }
  return s;
}

}  // namespace cls
