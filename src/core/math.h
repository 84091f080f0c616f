#pragma once
// Small fixed-size vector/matrix types shared by CPU code and CUDA kernels.
#include <cmath>

#include "core/host_device.h"

namespace cls {

template <class T>
struct Vec3 {
  T x{}, y{}, z{};
  CLS_HD T& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }
  CLS_HD const T& operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
};

template <class T> CLS_HD Vec3<T> operator+(Vec3<T> a, Vec3<T> b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
template <class T> CLS_HD Vec3<T> operator-(Vec3<T> a, Vec3<T> b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
template <class T> CLS_HD Vec3<T> operator-(Vec3<T> a) { return {-a.x, -a.y, -a.z}; }
template <class T> CLS_HD Vec3<T> operator*(T s, Vec3<T> a) { return {s * a.x, s * a.y, s * a.z}; }
template <class T> CLS_HD Vec3<T> operator*(Vec3<T> a, T s) { return {s * a.x, s * a.y, s * a.z}; }
template <class T> CLS_HD T dot(Vec3<T> a, Vec3<T> b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
template <class T> CLS_HD Vec3<T> cross(Vec3<T> a, Vec3<T> b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
template <class T> CLS_HD T norm(Vec3<T> a) { return std::sqrt(dot(a, a)); }
template <class T> CLS_HD Vec3<T> normalized(Vec3<T> a) { return (T(1) / norm(a)) * a; }
template <class U, class T> CLS_HD Vec3<U> cast(Vec3<T> a) { return {U(a.x), U(a.y), U(a.z)}; }

// Row-major 3x3 matrix.
template <class T>
struct Mat3 {
  T m[3][3]{};
  CLS_HD static Mat3 identity() {
    Mat3 r;
    r.m[0][0] = r.m[1][1] = r.m[2][2] = T(1);
    return r;
  }
  CLS_HD Vec3<T> row(int i) const { return {m[i][0], m[i][1], m[i][2]}; }
};

template <class T> CLS_HD Vec3<T> operator*(const Mat3<T>& A, Vec3<T> v) {
  return {dot(A.row(0), v), dot(A.row(1), v), dot(A.row(2), v)};
}
template <class T> CLS_HD Mat3<T> operator*(const Mat3<T>& A, const Mat3<T>& B) {
  Mat3<T> r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r.m[i][j] = A.m[i][0] * B.m[0][j] + A.m[i][1] * B.m[1][j] + A.m[i][2] * B.m[2][j];
  return r;
}
template <class T> CLS_HD Mat3<T> transpose(const Mat3<T>& A) {
  Mat3<T> r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r.m[i][j] = A.m[j][i];
  return r;
}

// Rotation matrix of a unit quaternion (w, x, y, z), Hamilton convention as COLMAP writes it.
template <class T> CLS_HD Mat3<T> quat_to_rotation(T w, T x, T y, T z) {
  const T n = std::sqrt(w * w + x * x + y * y + z * z);
  w /= n; x /= n; y /= n; z /= n;
  Mat3<T> R;
  R.m[0][0] = 1 - 2 * (y * y + z * z); R.m[0][1] = 2 * (x * y - w * z);     R.m[0][2] = 2 * (x * z + w * y);
  R.m[1][0] = 2 * (x * y + w * z);     R.m[1][1] = 1 - 2 * (x * x + z * z); R.m[1][2] = 2 * (y * z - w * x);
  R.m[2][0] = 2 * (x * z - w * y);     R.m[2][1] = 2 * (y * z + w * x);     R.m[2][2] = 1 - 2 * (x * x + y * y);
  return R;
}

// Rotation by |w| radians about w / |w| (Rodrigues' formula); the identity for w = 0.
template <class T> CLS_HD Mat3<T> axis_angle_to_rotation(Vec3<T> w) {
  const T angle = norm(w);
  if (!(angle > T(0))) return Mat3<T>::identity();
  const Vec3<T> k = (T(1) / angle) * w;
  const T c = std::cos(angle), s = std::sin(angle), v = T(1) - c;
  Mat3<T> R;
  R.m[0][0] = c + k.x * k.x * v;       R.m[0][1] = k.x * k.y * v - k.z * s; R.m[0][2] = k.x * k.z * v + k.y * s;
  R.m[1][0] = k.y * k.x * v + k.z * s; R.m[1][1] = c + k.y * k.y * v;       R.m[1][2] = k.y * k.z * v - k.x * s;
  R.m[2][0] = k.z * k.x * v - k.y * s; R.m[2][1] = k.z * k.y * v + k.x * s; R.m[2][2] = c + k.z * k.z * v;
  return R;
}

// The angle (radians, in [0, pi]) of rotation R; atan2 keeps small angles exact where acos would not.
template <class T> CLS_HD T rotation_angle(const Mat3<T>& R) {
  const T sx = R.m[2][1] - R.m[1][2], sy = R.m[0][2] - R.m[2][0], sz = R.m[1][0] - R.m[0][1];
  return std::atan2(T(0.5) * std::sqrt(sx * sx + sy * sy + sz * sz), T(0.5) * (R.m[0][0] + R.m[1][1] + R.m[2][2] - T(1)));
}

using Vec3d = Vec3<double>;
using Vec3f = Vec3<float>;
using Mat3d = Mat3<double>;
using Mat3f = Mat3<float>;

}  // namespace cls
