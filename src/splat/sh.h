#pragma once
// Real spherical harmonics up to degree 3 for view-dependent colour, with the constants, sign
// convention and clamp of the original 3DGS (computeColorFromSH): colour = max(0, sum_k b_k(d) c_k + 0.5).
// Shared by the CPU rasterizer, the reference renderer and the CUDA kernels.
#include "core/host_device.h"
#include "core/math.h"

namespace cls {

constexpr int kMaxShDegree = 3;
constexpr int kMaxShCoeffs = 16;
CLS_HD constexpr int sh_coeff_count(int degree) { return (degree + 1) * (degree + 1); }
constexpr double kShC0 = 0.28209479177387814;  // Y_0^0: colour = 0.5 + kShC0 * DC (3DGS RGB2SH / SH2RGB)

// Basis values b_k(x, y, z) for k < (degree+1)^2 of a unit direction.
template <class T>
CLS_HD void sh_basis(int degree, T x, T y, T z, T* b) {
  const T C0 = T(kShC0), C1 = T(0.4886025119029199);
  b[0] = C0;
  if (degree < 1) return;
  b[1] = -C1 * y;
  b[2] = C1 * z;
  b[3] = -C1 * x;
  if (degree < 2) return;
  const T xx = x * x, yy = y * y, zz = z * z;
  b[4] = T(1.0925484305920792) * x * y;
  b[5] = T(-1.0925484305920792) * y * z;
  b[6] = T(0.31539156525252005) * (2 * zz - xx - yy);
  b[7] = T(-1.0925484305920792) * x * z;
  b[8] = T(0.5462742152960396) * (xx - yy);
  if (degree < 3) return;
  b[9] = T(-0.5900435899266435) * y * (3 * xx - yy);
  b[10] = T(2.890611442640554) * x * y * z;
  b[11] = T(-0.4570457994644658) * y * (4 * zz - xx - yy);
  b[12] = T(0.3731763325901154) * z * (2 * zz - 3 * xx - 3 * yy);
  b[13] = T(-0.4570457994644658) * x * (4 * zz - xx - yy);
  b[14] = T(1.445305721320277) * z * (xx - yy);
  b[15] = T(-0.5900435899266435) * x * (xx - 3 * yy);
}

// Partial derivatives of the basis with respect to x, y and z (the direction treated as free).
template <class T>
CLS_HD void sh_basis_grad(int degree, T x, T y, T z, T* bx, T* by, T* bz) {
  for (int k = 0; k < kMaxShCoeffs; ++k) bx[k] = by[k] = bz[k] = T(0);
  const T C1 = T(0.4886025119029199);
  if (degree < 1) return;
  by[1] = -C1;
  bz[2] = C1;
  bx[3] = -C1;
  if (degree < 2) return;
  const T a4 = T(1.0925484305920792), a5 = T(-1.0925484305920792), a6 = T(0.31539156525252005),
          a7 = T(-1.0925484305920792), a8 = T(0.5462742152960396);
  bx[4] = a4 * y, by[4] = a4 * x;
  by[5] = a5 * z, bz[5] = a5 * y;
  bx[6] = -2 * a6 * x, by[6] = -2 * a6 * y, bz[6] = 4 * a6 * z;
  bx[7] = a7 * z, bz[7] = a7 * x;
  bx[8] = 2 * a8 * x, by[8] = -2 * a8 * y;
  if (degree < 3) return;
  const T xx = x * x, yy = y * y, zz = z * z;
  const T c9 = T(-0.5900435899266435), c10 = T(2.890611442640554), c11 = T(-0.4570457994644658),
          c12 = T(0.3731763325901154), c13 = T(-0.4570457994644658), c14 = T(1.445305721320277),
          c15 = T(-0.5900435899266435);
  bx[9] = c9 * 6 * x * y, by[9] = c9 * (3 * xx - 3 * yy);
  bx[10] = c10 * y * z, by[10] = c10 * x * z, bz[10] = c10 * x * y;
  bx[11] = c11 * (-2 * x * y), by[11] = c11 * (4 * zz - xx - 3 * yy), bz[11] = c11 * 8 * y * z;
  bx[12] = c12 * (-6 * x * z), by[12] = c12 * (-6 * y * z), bz[12] = c12 * (6 * zz - 3 * xx - 3 * yy);
  bx[13] = c13 * (4 * zz - 3 * xx - yy), by[13] = c13 * (-2 * x * y), bz[13] = c13 * 8 * x * z;
  bx[14] = c14 * 2 * x * z, by[14] = c14 * (-2 * y * z), bz[14] = c14 * (xx - yy);
  bx[15] = c15 * (3 * xx - 3 * yy), by[15] = c15 * (-6 * x * y);
}

// Colour of one Gaussian seen along the (unnormalised) direction v = mean - camera centre.
// coeffs: (degree+1)^2 x 3, coefficient-major ([k][rgb], the layout of 3DGS's features tensor).
// clamped[c] records where max(0, .) cut the value (its gradient is zero there).
template <class T>
CLS_HD void sh_to_rgb(int degree, const T* coeffs, Vec3<T> v, T* rgb, bool* clamped) {
  const Vec3<T> d = normalized(v);
  T b[kMaxShCoeffs] = {};
  sh_basis(degree, d.x, d.y, d.z, b);
  const int count = sh_coeff_count(degree);
  for (int c = 0; c < 3; ++c) {
    T s = T(0.5);
    CLS_UNROLL
    for (int k = 0; k < kMaxShCoeffs; ++k)  // a constant bound: on the GPU b stays in registers
      if (k < count) s += b[k] * coeffs[3 * k + c];
    clamped[c] = s < T(0);
    rgb[c] = clamped[c] ? T(0) : s;
  }
}

// Backward of sh_to_rgb: adds dL/dcoeffs and returns dL/dv (through the normalisation).
template <class T>
CLS_HD Vec3<T> sh_to_rgb_backward(int degree, const T* coeffs, Vec3<T> v, const bool* clamped,
                                  const T* dL_drgb, T* dL_dcoeffs) {
  const T inv_len = T(1) / norm(v);
  const Vec3<T> d = inv_len * v;
  T b[kMaxShCoeffs], bx[kMaxShCoeffs], by[kMaxShCoeffs], bz[kMaxShCoeffs];
  sh_basis(degree, d.x, d.y, d.z, b);
  sh_basis_grad(degree, d.x, d.y, d.z, bx, by, bz);
  T g[3];
  for (int c = 0; c < 3; ++c) g[c] = clamped[c] ? T(0) : dL_drgb[c];
  Vec3<T> dL_dd{};
  const int count = sh_coeff_count(degree);
  CLS_UNROLL
  for (int k = 0; k < kMaxShCoeffs; ++k) {  // a constant bound: on the GPU the bases stay in registers
    if (k >= count) break;
    T s = T(0);
    for (int c = 0; c < 3; ++c) {
      dL_dcoeffs[3 * k + c] += b[k] * g[c];
      s += coeffs[3 * k + c] * g[c];
    }
    dL_dd.x += bx[k] * s, dL_dd.y += by[k] * s, dL_dd.z += bz[k] * s;
  }
  // d = v/|v|: dL/dv = (dL/dd - d (d . dL/dd)) / |v|
  return inv_len * (dL_dd - dot(d, dL_dd) * d);
}

}  // namespace cls
