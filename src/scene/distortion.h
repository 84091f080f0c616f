#pragma once
// Lens distortion on normalized camera coordinates (x, y) = (X / Z, Y / Z), shared by CPU code
// and CUDA kernels.
//
// The model is COLMAP's OPENCV model (src/colmap/sensor/models.h, OpenCVCameraModel::Distortion)
// extended by a third radial term k3 (FULL_OPENCV's radial numerator, which Pix4D uses):
//   r2 = x^2 + y^2,  radial = k1 r2 + k2 r2^2 + k3 r2^3
//   x_d = x + x radial + 2 p1 x y + p2 (r2 + 2 x^2)
//   y_d = y + y radial + p1 (r2 + 2 y^2) + 2 p2 x y
// COLMAP's SIMPLE_RADIAL (k) and RADIAL (k1, k2) are this model with the other terms zero.
// Pixel coordinates follow as u = fx x_d + cx, v = fy y_d + cy.
#include "core/host_device.h"

namespace cls {

template <class T>
struct DistortionCoeffs {
  T k1 = 0, k2 = 0, k3 = 0;  // radial
  T p1 = 0, p2 = 0;          // tangential (decentering)
  CLS_HD bool is_zero() const { return k1 == 0 && k2 == 0 && k3 == 0 && p1 == 0 && p2 == 0; }
};

// (x, y) -> (x_d, y_d).
template <class T>
CLS_HD void distort_normalized(const DistortionCoeffs<T>& d, T x, T y, T& xd, T& yd) {
  const T r2 = x * x + y * y;
  const T radial = r2 * (d.k1 + r2 * (d.k2 + r2 * d.k3));
  xd = x + x * radial + T(2) * d.p1 * x * y + d.p2 * (r2 + T(2) * x * x);
  yd = y + y * radial + d.p1 * (r2 + T(2) * y * y) + T(2) * d.p2 * x * y;
}

// Jacobian of distort_normalized: [[dxd/dx, dxd/dy], [dyd/dx, dyd/dy]].
template <class T>
CLS_HD void distortion_jacobian(const DistortionCoeffs<T>& d, T x, T y, T& j00, T& j01, T& j10, T& j11) {
  const T r2 = x * x + y * y;
  const T radial = r2 * (d.k1 + r2 * (d.k2 + r2 * d.k3));
  const T dradial_dr2 = d.k1 + r2 * (T(2) * d.k2 + T(3) * r2 * d.k3);
  const T cross = T(2) * x * y * dradial_dr2 + T(2) * d.p1 * x + T(2) * d.p2 * y;
  j00 = T(1) + radial + T(2) * x * x * dradial_dr2 + T(2) * d.p1 * y + T(6) * d.p2 * x;
  j01 = cross;
  j10 = cross;
  j11 = T(1) + radial + T(2) * y * y * dradial_dr2 + T(6) * d.p1 * y + T(2) * d.p2 * x;
}

// Inverts distort_normalized by Newton's method, starting from the distorted point (as COLMAP's
// IterativeUndistortion does, there with a numeric Jacobian). Returns false if it does not
// converge, e.g. for a point beyond the fold of a strongly distorting lens.
template <class T>
CLS_HD bool undistort_normalized(const DistortionCoeffs<T>& d, T xd, T yd, T& x, T& y) {
  const T tol = sizeof(T) == 4 ? T(1e-6) : T(1e-13);
  x = xd;
  y = yd;
  if (d.is_zero()) return true;
  for (int it = 0; it < 100; ++it) {
    T fx, fy, j00, j01, j10, j11;
    distort_normalized(d, x, y, fx, fy);
    fx -= xd;
    fy -= yd;
    distortion_jacobian(d, x, y, j00, j01, j10, j11);
    const T det = j00 * j11 - j01 * j10;
    if (!(det > tol || det < -tol)) return false;  // also catches NaN
    const T dx = (j11 * fx - j01 * fy) / det;
    const T dy = (j00 * fy - j10 * fx) / det;
    x -= dx;
    y -= dy;
    const T scale = T(1) + (x < 0 ? -x : x) + (y < 0 ? -y : y);
    if ((dx < 0 ? -dx : dx) + (dy < 0 ? -dy : dy) <= tol * scale) return true;
  }
  return false;
}

}  // namespace cls
