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

// P is T, or on the CPU a vector of pixel lanes (blend_lanes.h).
template <class T, class P>
CLS_HD P gaussian_power(const T* mean2d, const T* conic, const P& px, const P& py) {
  const P dx = mean2d[0] - px, dy = mean2d[1] - py;
  return T(-0.5) * (conic[0] * dx * dx + conic[2] * dy * dy) - conic[1] * dx * dy;
}

// Alpha from power; G receives exp(power) (the backward needs it). 0 when skipped.
template <class T>
CLS_HD T alpha_from_power(T power, T opacity, T& G) {
  if (power > T(0)) return T(0);
  G = std::exp(power);
  const T raw = opacity * G;
  const T alpha = raw < T(kAlphaMax) ? raw : T(kAlphaMax);
  return alpha < T(kAlphaMin) ? T(0) : alpha;
}

// Alpha of a Gaussian at pixel centre (px, py); 0 when it is skipped.
template <class T>
CLS_HD T gaussian_alpha(const T* mean2d, const T* conic, T opacity, T px, T py) {
  T G;
  return alpha_from_power(gaussian_power(mean2d, conic, px, py), opacity, G);
}

// A power below which alpha < 1/255 for certain, so the exp can be skipped: log(1 / (255 opacity))
// less a margin far beyond rounding, so the skip decisions stay exactly those of alpha_from_power.
template <class T>
CLS_HD T alpha_cutoff_power(T opacity) {
  if (!(opacity > T(0))) return T(1e30);
  return -std::log(T(255) * opacity) - T(1e-3);
}

// Backward of gaussian_alpha for a Gaussian that contributed, given G = exp(power) from the forward
// evaluation: adds dL/dmean2d (and its absolute value, the densification statistic), dL/dconic and
// returns dL/dopacity. Where the 0.99 clamp is active alpha does not depend on the inputs and every
// gradient is zero.
template <class T>
CLS_HD T gaussian_alpha_backward(const T* mean2d, const T* conic, T opacity, T px, T py, T G, T dL_dalpha,
                                 T* dL_dmean2d, T* abs_dL_dmean2d, T* dL_dconic) {
  if (opacity * G >= T(kAlphaMax)) return T(0);
  const T dx = mean2d[0] - px, dy = mean2d[1] - py;
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
