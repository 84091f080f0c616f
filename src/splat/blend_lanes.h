#pragma once
// The per-pixel blending math of blend_pixel.h for the 16 pixels of a 4x4 sub-tile at once (CPU): one
// lane per pixel in GCC vector types, which each instruction-set build of rasterize_cpu.cpp's tile
// kernels lowers to its own registers (4 SSE2, 2 AVX2 or 1 AVX-512 register for float). The CPU spends
// its time in this per-(Gaussian, pixel) work; lanes over pixels vectorise the power, exp, alpha tests
// and the transmittance chain, which per-channel loops cannot. The tests hold it to blend_pixel.h's
// scalar definitions through the double reference renderer and finite differences in double.
//
// Comparisons and selections go through lane_less, lane_less_equal and lane_select, which take the
// build's register size: GCC 12 splits the arithmetic and bitwise operations of a vector wider than the
// registers into registers, but lowers its comparisons one lane at a time (a scalar compare per lane, and
// a branch per lane for `m ? a : b`). Written as operators, every build but AVX-512's ran the
// blending scalar, slower than the SSE2 build on an AVX2 CPU (docs/benchmarks.md).
//
// Hand-written instead of a SIMD library: Debian has none that LibTorch's build already brings, and
// the operations needed are a few (compare, select, lane sums, one exp). Everything here, and
// blend_pixel.h's gaussian_power that the lanes share, is inlined into the tile kernels: no vector crosses
// a call, so GCC's -Wpsabi note (64-byte vectors change the ABI without AVX-512) does not apply; the
// includer silences it.
#include <cmath>
#include <cstdint>
#include <cstring>
#include <type_traits>

#include "splat/blend_pixel.h"

namespace cls {

constexpr int kLaneSide = 4;                       // the sub-tile's side in pixels
constexpr int kLanes = kLaneSide * kLaneSide;       // one lane per pixel

template <class T>
struct LaneTypes;
template <>
struct LaneTypes<float> {
  using V = float __attribute__((vector_size(kLanes * sizeof(float))));
};
template <>
struct LaneTypes<double> {
  using V = double __attribute__((vector_size(kLanes * sizeof(double))));
};
template <class T>
using Lanes = typename LaneTypes<T>::V;
// Per-lane truth values: all bits set (-1) or 0, integers of the lanes' width.
template <class T>
using LaneMask = decltype(Lanes<T>{} < Lanes<T>{});

// A vector of one register: kBytes of E (16 SSE2 and NEON, 32 AVX2, 64 AVX-512), what a build's tile
// kernels pass to the helpers below as kBytes.
// (Spelled out per type: GCC drops vector_size from a dependent type.)
template <class E, int kBytes>
struct NativeVector;
#define CLS_NATIVE_VECTOR(E, BYTES)                         \
  template <>                                               \
  struct NativeVector<E, BYTES> {                           \
    using V = E __attribute__((vector_size(BYTES)));        \
  };
#define CLS_NATIVE_VECTORS(E) CLS_NATIVE_VECTOR(E, 16) CLS_NATIVE_VECTOR(E, 32) CLS_NATIVE_VECTOR(E, 64)
CLS_NATIVE_VECTORS(float)
CLS_NATIVE_VECTORS(double)
#undef CLS_NATIVE_VECTORS
#undef CLS_NATIVE_VECTOR

// The register of v (a Lanes<T>) that starts `at` bytes in, and its store.
template <int kBytes, class Vec>
[[gnu::always_inline]] inline auto lane_register(const Vec& v, std::size_t at) {
  typename NativeVector<std::remove_cv_t<std::remove_reference_t<decltype(v[0])>>, kBytes>::V p;
  std::memcpy(&p, reinterpret_cast<const char*>(&v) + at, kBytes);
  return p;
}
template <int kBytes, class Vec, class P>
[[gnu::always_inline]] inline void set_lane_register(Vec& v, std::size_t at, const P& p) {
  static_assert(sizeof(P) == kBytes, "one register");
  std::memcpy(reinterpret_cast<char*>(&v) + at, &p, kBytes);
}

// op applied a register at a time: the lanes of a and b (Lanes<T>) cut into registers of kBytes, op on
// each pair, the results (a register each) put together in order.
template <int kBytes, class Out, class In, class Op>
[[gnu::always_inline]] inline Out lanes_by_register(const In& a, const In& b, Op op) {
  static_assert(sizeof(In) % kBytes == 0 && sizeof(Out) == sizeof(In), "whole registers of lanes");
  Out out;
  for (std::size_t at = 0; at < sizeof(In); at += kBytes)
    set_lane_register<kBytes>(out, at, op(lane_register<kBytes>(a, at), lane_register<kBytes>(b, at)));
  return out;
}

struct LessOp {
  template <class P>
  [[gnu::always_inline]] auto operator()(const P& a, const P& b) const {
    return a < b;
  }
};
struct LessEqualOp {
  template <class P>
  [[gnu::always_inline]] auto operator()(const P& a, const P& b) const {
    return a <= b;
  }
};

// a < b and a <= b per lane of Lanes<T> (IEEE: false where either is NaN), as a LaneMask<T>.
template <int kBytes, class V>
[[gnu::always_inline]] inline auto lane_less(const V& a, const V& b) {
  return lanes_by_register<kBytes, decltype(a < b)>(a, b, LessOp{});
}
template <int kBytes, class V>
[[gnu::always_inline]] inline auto lane_less_equal(const V& a, const V& b) {
  return lanes_by_register<kBytes, decltype(a <= b)>(a, b, LessEqualOp{});
}

// y += x s, a register at a time, for y in memory (an accumulator row). Written as y += x * s, GCC 12
// moves a vector wider than the registers through the stack and general registers on every store (the AVX2
// build's dense backward spent most of its time so).
template <int kBytes, class Vec, class E>
[[gnu::always_inline]] inline void lane_add_scaled(Vec& y, const Vec& x, E s) {
  static_assert(sizeof(Vec) % kBytes == 0, "whole registers of lanes");
  for (std::size_t at = 0; at < sizeof(Vec); at += kBytes)
    set_lane_register<kBytes>(y, at, lane_register<kBytes>(y, at) + lane_register<kBytes>(x, at) * s);
}

// m ? a : b per lane for masks m of all bits or none (LaneMask), a and b Lanes<T> or LaneMask<T>: the
// bits of a where m is set, of b elsewhere.
template <int kBytes, class Vec, class Mask>
[[gnu::always_inline]] inline Vec lane_select(const Mask& m, const Vec& a, const Vec& b) {
  static_assert(sizeof(Vec) == sizeof(Mask), "a mask lane per value lane");
  const Mask bits_a = __builtin_bit_cast(Mask, a), bits_b = __builtin_bit_cast(Mask, b);
  return __builtin_bit_cast(Vec, bits_b ^ ((bits_a ^ bits_b) & m));
}

// The lane sums of 16 vectors at once: lane i of the result is the sum of q[i]'s lanes (a transpose by
// halving: 15 steps of two shuffles and an add, against 16 separate sums).
template <class V>
[[gnu::always_inline]] inline V lane_sums(const V* q) {
  V t[8], u[4], w[2];
  for (int i = 0; i < 8; ++i)
    t[i] = __builtin_shufflevector(q[2 * i], q[2 * i + 1], 0, 1, 2, 3, 4, 5, 6, 7, 16, 17, 18, 19, 20, 21, 22, 23) +
           __builtin_shufflevector(q[2 * i], q[2 * i + 1], 8, 9, 10, 11, 12, 13, 14, 15, 24, 25, 26, 27, 28, 29, 30, 31);
  for (int i = 0; i < 4; ++i)
    u[i] = __builtin_shufflevector(t[2 * i], t[2 * i + 1], 0, 1, 2, 3, 8, 9, 10, 11, 16, 17, 18, 19, 24, 25, 26, 27) +
           __builtin_shufflevector(t[2 * i], t[2 * i + 1], 4, 5, 6, 7, 12, 13, 14, 15, 20, 21, 22, 23, 28, 29, 30, 31);
  for (int i = 0; i < 2; ++i)
    w[i] = __builtin_shufflevector(u[2 * i], u[2 * i + 1], 0, 1, 4, 5, 8, 9, 12, 13, 16, 17, 20, 21, 24, 25, 28, 29) +
           __builtin_shufflevector(u[2 * i], u[2 * i + 1], 2, 3, 6, 7, 10, 11, 14, 15, 18, 19, 22, 23, 26, 27, 30, 31);
  return __builtin_shufflevector(w[0], w[1], 0, 2, 4, 6, 8, 10, 12, 14, 16, 18, 20, 22, 24, 26, 28, 30) +
         __builtin_shufflevector(w[0], w[1], 1, 3, 5, 7, 9, 11, 13, 15, 17, 19, 21, 23, 25, 27, 29, 31);
}

template <class Mask>
[[gnu::always_inline]] inline bool any_lane(const Mask& m) {
  const auto a = __builtin_shufflevector(m, m, 0, 1, 2, 3, 4, 5, 6, 7) |
                 __builtin_shufflevector(m, m, 8, 9, 10, 11, 12, 13, 14, 15);
  const auto b = __builtin_shufflevector(a, a, 0, 1, 2, 3) | __builtin_shufflevector(a, a, 4, 5, 6, 7);
  return (b[0] | b[1] | b[2] | b[3]) != 0;
}

// exp of powers <= 0. float: Cephes' expf (range reduction by ln 2 in two parts, a degree-6
// polynomial, 2^n through the exponent bits), relative error about 1e-7 like the library's expf, and
// the same in the forward and the backward, so both take the same skip decisions. double (the
// finite-difference checks): the library's exp per lane.
template <int kBytes>
[[gnu::always_inline]] inline Lanes<float> lane_exp(const Lanes<float>& power) {
  using V = Lanes<float>;
  using I = LaneMask<float>;
  const V floor = V{} - 87.0f;
  V x = lane_select<kBytes>(lane_less_equal<kBytes>(floor, power), power, floor);  // NaN too: no NaN reaches
                                                                                   // the integer conversion
  x = lane_select<kBytes>(lane_less<kBytes>(V{}, x), V{}, x);
  const float kRound = 12582912.0f;  // 1.5 * 2^23: adding and subtracting it rounds to an integer
  const V n = (x * 1.44269504088896341f + kRound) - kRound;
  x = x - n * 0.693359375f;
  x = x - n * -2.12194440e-4f;
  V p = x * 1.9875691500e-4f + 1.3981999507e-3f;
  p = p * x + 8.3334519073e-3f;
  p = p * x + 4.1665795894e-2f;
  p = p * x + 1.6666665459e-1f;
  p = p * x + 5.0000001201e-1f;
  p = p * (x * x) + x + 1.0f;
  const I bits = (__builtin_convertvector(n, I) + 127) << 23;
  return p * __builtin_bit_cast(V, bits);
}

template <int kBytes>
[[gnu::always_inline]] inline Lanes<double> lane_exp(const Lanes<double>& x) {
  Lanes<double> r;
  for (int l = 0; l < kLanes; ++l) r[l] = x[l] > 0.0 ? 1.0 : std::exp(x[l]);
  return r;
}

// alpha_from_power per lane: alpha where `pass` (power <= 0 and alpha >= 1/255, and `pass` on entry), 0
// elsewhere; G = exp(power). The exp runs in every lane anyway, so the cutoff power (a skip of the scalar
// exp) is not tested: below it alpha < 1/255 for certain. One mask comparison only, the power test a select
// of floats: GCC 12 turns two comparisons combined into a mask into a scalar compare per lane in the
// AVX-512 build (where the registers hold all 16 lanes and lane_less is the plain comparison).
template <int kBytes, class T>
[[gnu::always_inline]] inline Lanes<T> lane_alpha(const Lanes<T>& power, T opacity, LaneMask<T>& pass, Lanes<T>& G) {
  using V = Lanes<T>;
  G = lane_exp<kBytes>(power);
  const V raw = opacity * G, max = V{} + T(kAlphaMax);
  V alpha = lane_select<kBytes>(lane_less<kBytes>(raw, max), raw, max);
  alpha = lane_select<kBytes>(lane_less_equal<kBytes>(power, V{}), alpha, V{});
  pass &= lane_less_equal<kBytes>(V{} + T(kAlphaMin), alpha);
  return lane_select<kBytes>(pass, alpha, V{});
}

// gaussian_alpha_backward per lane where `contributed` (zero elsewhere and at the 0.99 clamp): q[0..1]
// dL/dmean2d, q[2..3] its absolute value, q[4..6] dL/dconic, q[7] dL/dopacity.
template <int kBytes, class T>
[[gnu::always_inline]] inline void lane_alpha_backward(const T* mean2d, const T* conic, T opacity, const Lanes<T>& cx,
                                                       const Lanes<T>& cy, const Lanes<T>& G, const Lanes<T>& dL_dalpha,
                                                       const LaneMask<T>& contributed, Lanes<T>* q) {
  using V = Lanes<T>;
  const LaneMask<T> pass = contributed & lane_less<kBytes>(opacity * G, V{} + T(kAlphaMax));
  const V dx = mean2d[0] - cx, dy = mean2d[1] - cy;
  const V dL_dpower = lane_select<kBytes>(pass, opacity * G * dL_dalpha, V{});
  const V gx = -dL_dpower * (conic[0] * dx + conic[1] * dy);
  const V gy = -dL_dpower * (conic[2] * dy + conic[1] * dx);
  q[0] = gx;
  q[1] = gy;
  q[2] = lane_select<kBytes>(lane_less<kBytes>(gx, V{}), -gx, gx);
  q[3] = lane_select<kBytes>(lane_less<kBytes>(gy, V{}), -gy, gy);
  q[4] = T(-0.5) * dx * dx * dL_dpower;
  q[5] = -dx * dy * dL_dpower;
  q[6] = T(-0.5) * dy * dy * dL_dpower;
  q[7] = lane_select<kBytes>(pass, G * dL_dalpha, V{});
}

}  // namespace cls
