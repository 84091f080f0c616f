#pragma once
// Per-pixel alpha of one Gaussian and its backward (renderCUDA of the original 3DGS):
// power = -0.5 (a dx^2 + c dy^2) - b dx dy with d = mean2d - pixel centre; skipped when power > 0;
// alpha = min(0.99, opacity * exp(power)); skipped when alpha < 1/255; blending stops before a
// Gaussian that would bring the transmittance T below 1e-4.
#include <cmath>

#include "core/host_device.h"

namespace cls {

constexpr double kAlphaMax = 0.99;
constexpr double kAlphaMin = 1.0 / 255.0;
constexpr double kTransmittanceMin = 1e-4;

// Alpha of a Gaussian at pixel centre (px, py); 0 when it is skipped.
template <class T>
CLS_HD T gaussian_alpha(const T* mean2d, const T* conic, T opacity, T px, T py) {
  const T dx = mean2d[0] - px, dy = mean2d[1] - py;
  const T power = T(-0.5) * (conic[0] * dx * dx + conic[2] * dy * dy) - conic[1] * dx * dy;
  if (power > T(0)) return T(0);
  const T raw = opacity * std::exp(power);
  const T alpha = raw < T(kAlphaMax) ? raw : T(kAlphaMax);
  return alpha < T(kAlphaMin) ? T(0) : alpha;
}

// Backward of gaussian_alpha for a Gaussian that contributed: adds dL/dmean2d (and its absolute
// value, the densification statistic), dL/dconic and returns dL/dopacity. Where the 0.99 clamp is
// active alpha does not depend on the inputs and every gradient is zero.
template <class T>
CLS_HD T gaussian_alpha_backward(const T* mean2d, const T* conic, T opacity, T px, T py, T dL_dalpha,
                                 T* dL_dmean2d, T* abs_dL_dmean2d, T* dL_dconic) {
  const T dx = mean2d[0] - px, dy = mean2d[1] - py;
  const T power = T(-0.5) * (conic[0] * dx * dx + conic[2] * dy * dy) - conic[1] * dx * dy;
  const T G = std::exp(power);
  if (opacity * G >= T(kAlphaMax)) return T(0);
  const T dL_dpower = opacity * G * dL_dalpha;
  const T gx = -dL_dpower * (conic[0] * dx + conic[1] * dy);
  const T gy = -dL_dpower * (conic[2] * dy + conic[1] * dx);
  dL_dmean2d[0] += gx;
  dL_dmean2d[1] += gy;
  abs_dL_dmean2d[0] += gx < T(0) ? -gx : gx;
  abs_dL_dmean2d[1] += gy < T(0) ? -gy : gy;
  dL_dconic[0] += T(-0.5) * dx * dx * dL_dpower;
  dL_dconic[1] += -dx * dy * dL_dpower;
  dL_dconic[2] += T(-0.5) * dy * dy * dL_dpower;
  return G * dL_dalpha;
}

}  // namespace cls
