#pragma once
// Per-Gaussian math of the rasterizer: rotation from a quaternion, 3D covariance, EWA projection to a
// 2D conic (Zwicker et al. 2002 as in 3DGS's preprocessCUDA / computeCov2D), screen radius and tile
// rectangle, and the hand-derived backward of each step. Shared by the CPU path and the CUDA kernels.
//
// Pixel convention (docs/conventions.md): pixel (i, j) has its centre at (i + 0.5, j + 0.5) in the
// pinhole image coordinates of the camera (explicit cx, cy), as COLMAP and gsplat define it. The
// original 3DGS samples at integer coordinates (its ndc2Pix); everything here is shifted so that a
// Gaussian projecting onto a pixel centre renders there, lining up with the label maps.
#include <cmath>

#include "core/host_device.h"
#include "core/math.h"

namespace cls {

constexpr int kTileSize = 16;          // 16x16 pixel tiles (BLOCK_X, BLOCK_Y of the original)
constexpr double kNearPlane = 0.2;     // Gaussians with camera z <= 0.2 are culled (in_frustum)
constexpr double kLowPass = 0.3;       // added to the 2D covariance diagonal (anti-aliasing)
constexpr double kFrustumClamp = 1.3;  // t.x/t.z, t.y/t.z clamped to 1.3x the half field of view

// The camera as the rasterizer needs it: world-to-camera (R, t) and pinhole intrinsics.
template <class T>
struct SplatCamera {
  Mat3<T> R = Mat3<T>::identity();
  Vec3<T> t{};
  T fx = 1, fy = 1, cx = 0, cy = 0;
  int width = 0, height = 0;
  CLS_HD int tiles_x() const { return (width + kTileSize - 1) / kTileSize; }
  CLS_HD int tiles_y() const { return (height + kTileSize - 1) / kTileSize; }
  CLS_HD Vec3<T> center() const { return -(transpose(R) * t); }
  // Frustum clamp limits. For a centred principal point these are the original's 1.3 * tan(fov/2);
  // with an off-centre one each side keeps 1.3x its own extent.
  CLS_HD T lim_x_neg() const { return T(kFrustumClamp) * cx / fx; }
  CLS_HD T lim_x_pos() const { return T(kFrustumClamp) * (T(width) - cx) / fx; }
  CLS_HD T lim_y_neg() const { return T(kFrustumClamp) * cy / fy; }
  CLS_HD T lim_y_pos() const { return T(kFrustumClamp) * (T(height) - cy) / fy; }
};

// Symmetric 3x3 matrix as a full matrix (clearer than packed storage; the cost is negligible).
template <class T>
CLS_HD Mat3<T> outer_sum_sym(const Mat3<T>& A) { return A + transpose(A); }

template <class T>
CLS_HD Mat3<T> operator+(const Mat3<T>& A, const Mat3<T>& B) {
  Mat3<T> r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r.m[i][j] = A.m[i][j] + B.m[i][j];
  return r;
}

// ---- rotation ---------------------------------------------------------------------------------
// quat_to_rotation (core/math.h) normalises q = (w, x, y, z). Backward: dL/dq of the raw quaternion
// given dL/dR.
template <class T>
CLS_HD void quat_to_rotation_backward(const T* q_raw, const Mat3<T>& dR, T* dq_raw) {
  const T n = std::sqrt(q_raw[0] * q_raw[0] + q_raw[1] * q_raw[1] + q_raw[2] * q_raw[2] + q_raw[3] * q_raw[3]);
  const T w = q_raw[0] / n, x = q_raw[1] / n, y = q_raw[2] / n, z = q_raw[3] / n;
  const auto& g = dR.m;
  T dw = 2 * (-z * g[0][1] + y * g[0][2] + z * g[1][0] - x * g[1][2] - y * g[2][0] + x * g[2][1]);
  T dx = 2 * (y * g[0][1] + z * g[0][2] + y * g[1][0] - 2 * x * g[1][1] - w * g[1][2] + z * g[2][0] +
              w * g[2][1] - 2 * x * g[2][2]);
  T dy = 2 * (-2 * y * g[0][0] + x * g[0][1] + w * g[0][2] + x * g[1][0] + z * g[1][2] - w * g[2][0] +
              z * g[2][1] - 2 * y * g[2][2]);
  T dz = 2 * (-2 * z * g[0][0] - w * g[0][1] + x * g[0][2] + w * g[1][0] - 2 * z * g[1][1] + y * g[1][2] +
              x * g[2][0] + y * g[2][1]);
  // through q/|q|: dL/dq = (g - q (q . g)) / |q|
  const T qg = w * dw + x * dx + y * dy + z * dz;
  dq_raw[0] = (dw - w * qg) / n;
  dq_raw[1] = (dx - x * qg) / n;
  dq_raw[2] = (dy - y * qg) / n;
  dq_raw[3] = (dz - z * qg) / n;
}

// ---- 3D covariance: Sigma = R S S^T R^T with S = diag(scale) (computeCov3D) -----------------------
template <class T>
CLS_HD Mat3<T> covariance_3d(const T* scale, const T* q) {
  const Mat3<T> R = quat_to_rotation(q[0], q[1], q[2], q[3]);
  Mat3<T> M;  // M = R S
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) M.m[i][j] = R.m[i][j] * scale[j];
  return M * transpose(M);
}

// Backward: dSigma is dL/dSigma with every entry of Sigma treated as independent (symmetric when the
// loss is). Adds dL/dscale and dL/dq (raw quaternion).
template <class T>
CLS_HD void covariance_3d_backward(const T* scale, const T* q, const Mat3<T>& dSigma, T* dscale, T* dq) {
  const Mat3<T> R = quat_to_rotation(q[0], q[1], q[2], q[3]);
  Mat3<T> M;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) M.m[i][j] = R.m[i][j] * scale[j];
  const Mat3<T> dM = outer_sum_sym(dSigma) * M;  // Sigma = M M^T
  Mat3<T> dR;
  for (int j = 0; j < 3; ++j) {
    T ds = 0;
    for (int i = 0; i < 3; ++i) {
      dR.m[i][j] = dM.m[i][j] * scale[j];
      ds += dM.m[i][j] * R.m[i][j];
    }
    dscale[j] += ds;
  }
  T dq_local[4];
  quat_to_rotation_backward(q, dR, dq_local);
  for (int k = 0; k < 4; ++k) dq[k] += dq_local[k];
}

// ---- EWA projection --------------------------------------------------------------------------
template <class T>
struct ProjectedGaussian {
  T mean2d[2];  // pixel coordinates (pixel centres at +0.5)
  T conic[3];   // inverse 2D covariance (a, b, c) of [[a, b], [b, c]]
  T depth;      // camera z
  int radius;   // 3 sigma of the larger eigenvalue, in pixels (ceil)
  int rect_min[2], rect_max[2];  // overlapped tiles [min, max)
  bool visible;
};

// Tile rectangle of a screen disc (getRect of the original, with its integer-centred coordinate p).
template <class T>
CLS_HD void tile_rect(T px, T py, int radius, int tiles_x, int tiles_y, int* rmin, int* rmax) {
  const T p[2] = {px - T(0.5), py - T(0.5)};  // to the original's integer-centred pixel coordinates
  const int grid[2] = {tiles_x, tiles_y};
  for (int k = 0; k < 2; ++k) {
    int lo = int((p[k] - T(radius)) / T(kTileSize));
    int hi = int((p[k] + T(radius) + T(kTileSize - 1)) / T(kTileSize));
    lo = lo < 0 ? 0 : lo;
    hi = hi < 0 ? 0 : hi;
    rmin[k] = lo < grid[k] ? lo : grid[k];
    rmax[k] = hi < grid[k] ? hi : grid[k];
  }
}

// Camera-frame point clamped to the frustum for the Jacobian (the original's 1.3x limits).
template <class T>
struct ClampedView {
  T tx, ty, tz;
  bool clamped_x, clamped_y;
  T lim_x, lim_y;  // the active limit (signed) where clamped
};

template <class T>
CLS_HD ClampedView<T> clamp_to_frustum(const SplatCamera<T>& cam, Vec3<T> t) {
  ClampedView<T> v;
  v.tz = t.z;
  const T xr = t.x / t.z, yr = t.y / t.z;
  const T lxn = -cam.lim_x_neg(), lxp = cam.lim_x_pos(), lyn = -cam.lim_y_neg(), lyp = cam.lim_y_pos();
  v.clamped_x = xr < lxn || xr > lxp;
  v.clamped_y = yr < lyn || yr > lyp;
  v.lim_x = xr < lxn ? lxn : lxp;
  v.lim_y = yr < lyn ? lyn : lyp;
  v.tx = (v.clamped_x ? v.lim_x : xr) * t.z;
  v.ty = (v.clamped_y ? v.lim_y : yr) * t.z;
  return v;
}

// 2D covariance (before the low-pass) Sigma' = T Sigma T^T with T = J W, J the pinhole Jacobian at
// the clamped point and W the world-to-camera rotation. Returns T (2x3) in Tm.
template <class T>
CLS_HD void ewa_cov2d(const SplatCamera<T>& cam, const ClampedView<T>& v, const Mat3<T>& Sigma, T Tm[2][3],
                      T cov[3]) {
  const T iz = T(1) / v.tz, iz2 = iz * iz;
  const T J[2][3] = {{cam.fx * iz, T(0), -cam.fx * v.tx * iz2}, {T(0), cam.fy * iz, -cam.fy * v.ty * iz2}};
  for (int r = 0; r < 2; ++r)
    for (int k = 0; k < 3; ++k) Tm[r][k] = J[r][0] * cam.R.m[0][k] + J[r][1] * cam.R.m[1][k] + J[r][2] * cam.R.m[2][k];
  T TS[2][3];
  for (int r = 0; r < 2; ++r)
    for (int k = 0; k < 3; ++k) TS[r][k] = Tm[r][0] * Sigma.m[0][k] + Tm[r][1] * Sigma.m[1][k] + Tm[r][2] * Sigma.m[2][k];
  cov[0] = TS[0][0] * Tm[0][0] + TS[0][1] * Tm[0][1] + TS[0][2] * Tm[0][2];
  cov[1] = TS[0][0] * Tm[1][0] + TS[0][1] * Tm[1][1] + TS[0][2] * Tm[1][2];
  cov[2] = TS[1][0] * Tm[1][0] + TS[1][1] * Tm[1][1] + TS[1][2] * Tm[1][2];
}

// Projects one Gaussian (preprocessCUDA): culling, EWA covariance + low-pass, conic, radius, tiles.
template <class T>
CLS_HD ProjectedGaussian<T> project_gaussian(const SplatCamera<T>& cam, Vec3<T> mean, const Mat3<T>& Sigma) {
  ProjectedGaussian<T> p{};
  p.visible = false;
  const Vec3<T> t = cam.R * mean + cam.t;
  if (t.z <= T(kNearPlane)) return p;
  const ClampedView<T> v = clamp_to_frustum(cam, t);
  T Tm[2][3], cov[3];
  ewa_cov2d(cam, v, Sigma, Tm, cov);
  const T a = cov[0] + T(kLowPass), b = cov[1], c = cov[2] + T(kLowPass);
  const T det = a * c - b * b;
  if (!(det > T(0))) return p;
  const T inv_det = T(1) / det;
  p.conic[0] = c * inv_det;
  p.conic[1] = -b * inv_det;
  p.conic[2] = a * inv_det;
  const T mid = T(0.5) * (a + c);
  const T disc = mid * mid - det;
  const T lambda1 = mid + std::sqrt(disc > T(0.1) ? disc : T(0.1));
  p.radius = int(std::ceil(T(3) * std::sqrt(lambda1)));
  p.mean2d[0] = cam.fx * t.x / t.z + cam.cx;
  p.mean2d[1] = cam.fy * t.y / t.z + cam.cy;
  p.depth = t.z;
  tile_rect(p.mean2d[0], p.mean2d[1], p.radius, cam.tiles_x(), cam.tiles_y(), p.rect_min, p.rect_max);
  if ((p.rect_max[0] - p.rect_min[0]) * (p.rect_max[1] - p.rect_min[1]) == 0) return p;
  p.visible = true;
  return p;
}

// Backward of project_gaussian given dL/dmean2d, dL/dconic (a, b, c with b the single off-diagonal
// parameter) and dL/ddepth: returns dL/dmean (world) and adds dL/dSigma (full-matrix convention).
template <class T>
CLS_HD Vec3<T> project_gaussian_backward(const SplatCamera<T>& cam, Vec3<T> mean, const Mat3<T>& Sigma,
                                         const T* dL_dmean2d, const T* dL_dconic, T dL_ddepth, Mat3<T>& dL_dSigma) {
  const Vec3<T> t = cam.R * mean + cam.t;
  const ClampedView<T> v = clamp_to_frustum(cam, t);
  T Tm[2][3], cov[3];
  ewa_cov2d(cam, v, Sigma, Tm, cov);
  const T a = cov[0] + T(kLowPass), b = cov[1], c = cov[2] + T(kLowPass);
  const T det = a * c - b * b;
  const T id2 = T(1) / (det * det);
  // conic = (c, -b, a) / det
  const T gA = dL_dconic[0], gB = dL_dconic[1], gC = dL_dconic[2];
  const T da = id2 * (-c * c * gA + b * c * gB - b * b * gC);
  const T db = id2 * (2 * b * c * gA - (a * c + b * b) * gB + 2 * a * b * gC);
  const T dc = id2 * (-b * b * gA + a * b * gB - a * a * gC);
  // cov2d = Tm Sigma Tm^T as a symmetric matrix G2 with dL = tr(G2^T dcov)
  const T G2[2][2] = {{da, T(0.5) * db}, {T(0.5) * db, dc}};
  // dL/dSigma = Tm^T G2 Tm
  T G2T[2][3];
  for (int r = 0; r < 2; ++r)
    for (int k = 0; k < 3; ++k) G2T[r][k] = G2[r][0] * Tm[0][k] + G2[r][1] * Tm[1][k];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) dL_dSigma.m[i][j] += Tm[0][i] * G2T[0][j] + Tm[1][i] * G2T[1][j];
  // dL/dTm = 2 G2 Tm Sigma
  T dTm[2][3];
  for (int r = 0; r < 2; ++r)
    for (int k = 0; k < 3; ++k)
      dTm[r][k] = 2 * (G2T[r][0] * Sigma.m[0][k] + G2T[r][1] * Sigma.m[1][k] + G2T[r][2] * Sigma.m[2][k]);
  // dL/dJ = dL/dTm W^T (only the four non-constant entries of J are needed)
  auto dJ = [&](int r, int j) { return dTm[r][0] * cam.R.m[j][0] + dTm[r][1] * cam.R.m[j][1] + dTm[r][2] * cam.R.m[j][2]; };
  const T dJ00 = dJ(0, 0), dJ02 = dJ(0, 2), dJ11 = dJ(1, 1), dJ12 = dJ(1, 2);
  const T iz = T(1) / t.z, iz2 = iz * iz, iz3 = iz2 * iz;
  Vec3<T> dt{};
  dt.z = -cam.fx * iz2 * dJ00 - cam.fy * iz2 * dJ11;
  // J02 = -fx tx / tz^2 with tx = t.x unless clamped (then tx = lim * tz, J02 = -fx lim / tz)
  if (v.clamped_x) {
    dt.z += cam.fx * v.lim_x * iz2 * dJ02;
  } else {
    dt.x += -cam.fx * iz2 * dJ02;
    dt.z += 2 * cam.fx * t.x * iz3 * dJ02;
  }
  if (v.clamped_y) {
    dt.z += cam.fy * v.lim_y * iz2 * dJ12;
  } else {
    dt.y += -cam.fy * iz2 * dJ12;
    dt.z += 2 * cam.fy * t.y * iz3 * dJ12;
  }
  // mean2d = (fx t.x / t.z + cx, fy t.y / t.z + cy), depth = t.z
  dt.x += cam.fx * iz * dL_dmean2d[0];
  dt.y += cam.fy * iz * dL_dmean2d[1];
  dt.z += -cam.fx * t.x * iz2 * dL_dmean2d[0] - cam.fy * t.y * iz2 * dL_dmean2d[1] + dL_ddepth;
  return transpose(cam.R) * dt;
}

}  // namespace cls
