// CPU SSIM: see ssim_cpu.h. Hand-written because LibTorch's CPU grouped convolutions were about a third
// of a training iteration (30 of 93 ms on the compare scene: forward and backward of the five moment maps,
// each a full-image tensor; docs/benchmarks.md). Here each task takes one channel and a band of rows with
// its 5-row halo, so the blurred rows stay in cache, and the forward leaves only three derivative planes
// for the backward.
#include "splat/ssim_cpu.h"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "splat/rasterize_cpu.h"

namespace cls {
namespace {

constexpr int kTaps = kSsimWindow, kRadius = kTaps / 2;
constexpr int kBand = 32;  // output rows per task: 5 maps x (32 + 10) rows x W stay in L2 at W = 1000

template <class T>
struct Window {
  T w[kTaps];
  Window() {
    const std::array<double, kTaps> taps = ssim_window_taps();
    for (int i = 0; i < kTaps; ++i) w[i] = T(taps[i]);
  }
};

// out[x] = sum_d w[d] in[x + d - 5], in read as zero outside [0, W): `pad` holds in with 5 zeros each side.
template <class T>
[[gnu::always_inline]] inline void blur_row(const T* pad, T* out, int W, const T* w) {
  for (int x = 0; x < W; ++x) out[x] = w[0] * pad[x];
  for (int d = 1; d < kTaps; ++d)
    for (int x = 0; x < W; ++x) out[x] += w[d] * pad[x + d];
}

// out[x] = sum_d w[d] rows[y + d - 5][x] over the rows inside [0, H); rows[r] is row r's horizontal blur.
template <class T, class Rows>
[[gnu::always_inline]] inline void blur_column(const Rows& rows, int y, int H, T* out, int W, const T* w) {
  const int d0 = std::max(0, kRadius - y), d1 = std::min(kTaps, H - y + kRadius);
  const T* first = rows(y + d0 - kRadius);
  for (int x = 0; x < W; ++x) out[x] = w[d0] * first[x];
  for (int d = d0 + 1; d < d1; ++d) {
    const T* r = rows(y + d - kRadius);
    for (int x = 0; x < W; ++x) out[x] += w[d] * r[x];
  }
}

// One task's rows: band [y0, y1) and its halo [r0, r1), clipped to the image.
struct Band {
  int c, y0, y1, r0, r1;
  Band(int task, int H) {
    const int bands = (H + kBand - 1) / kBand;
    c = task / bands;
    y0 = task % bands * kBand, y1 = std::min(H, y0 + kBand);
    r0 = std::max(0, y0 - kRadius), r1 = std::min(H, y1 + kRadius);
  }
};

int task_count(int H, int C) { return C * ((H + kBand - 1) / kBand); }

// The Q maps of one band blurred by the window: horizontal(fill) blurs the halo rows, fill(r, rows) writing
// row r of each map into rows[q] (W values; the 5 zeros on each side stay), then vertical(y, m) gives the
// blurred maps at output row y (Q x W into m).
template <class T>
class BandBlur {
 public:
  static constexpr int kMaxMaps = 5;
  BandBlur(const Band& band, int H, int W, int Q, const T* w)
      : band_(band), H_(H), W_(W), Q_(Q), rows_(band.r1 - band.r0), w_(w),
        hbuf_(static_cast<size_t>(Q) * rows_ * W), pad_(static_cast<size_t>(Q) * (W + 2 * kRadius), T(0)) {}
  template <class Fill>
  [[gnu::always_inline]] void horizontal(Fill&& fill) {
    T* p[kMaxMaps];
    for (int q = 0; q < Q_; ++q) p[q] = pad_.data() + q * (W_ + 2 * kRadius) + kRadius;
    for (int r = band_.r0; r < band_.r1; ++r) {
      fill(r, p);
      for (int q = 0; q < Q_; ++q) blur_row(p[q] - kRadius, hrow(q, r), W_, w_);
    }
  }
  [[gnu::always_inline]] void vertical(int y, T* m) {
    for (int q = 0; q < Q_; ++q) blur_column<T>([&](int r) { return hrow(q, r); }, y, H_, m + q * W_, W_, w_);
  }

 private:
  T* hrow(int q, int r) { return hbuf_.data() + (static_cast<size_t>(q) * rows_ + (r - band_.r0)) * W_; }
  Band band_;
  int H_, W_, Q_, rows_;
  const T* w_;
  std::vector<T> hbuf_, pad_;
};

template <class T>
[[gnu::always_inline]] inline double forward_band(const T* a, const T* b, int H, int W, int C, T* dm, int task,
                                                  const Window<T>& win) {
  const Band band(task, H);
  BandBlur<T> blur(band, H, W, 5, win.w);  // a, b, a^2, b^2, ab
  blur.horizontal([&](int r, T* const* p) {
    const T* ar = a + static_cast<size_t>(r) * W * C + band.c;
    const T* br = b + static_cast<size_t>(r) * W * C + band.c;
    for (int x = 0; x < W; ++x) {
      const T va = ar[static_cast<size_t>(x) * C], vb = br[static_cast<size_t>(x) * C];
      p[0][x] = va, p[1][x] = vb, p[2][x] = va * va, p[3][x] = vb * vb, p[4][x] = va * vb;
    }
  });
  std::vector<T> m(static_cast<size_t>(5) * W);
  double sum = 0;
  const size_t plane = static_cast<size_t>(H) * W;
  for (int y = band.y0; y < band.y1; ++y) {
    blur.vertical(y, m.data());
    const T *mu_a = m.data(), *mu_b = mu_a + W, *e_aa = mu_b + W, *e_bb = e_aa + W, *e_ab = e_bb + W;
    T* d_mu = dm ? dm + (static_cast<size_t>(band.c) * 3) * plane + static_cast<size_t>(y) * W : nullptr;
    T row_sum = 0;
    if (d_mu) {
      for (int x = 0; x < W; ++x) {
        T d[3];
        row_sum += ssim_pixel(mu_a[x], mu_b[x], e_aa[x], e_bb[x], e_ab[x], d);
        d_mu[x] = d[0], d_mu[plane + x] = d[1], d_mu[2 * plane + x] = d[2];
      }
    } else {
      for (int x = 0; x < W; ++x) row_sum += ssim_pixel(mu_a[x], mu_b[x], e_aa[x], e_bb[x], e_ab[x], static_cast<T*>(nullptr));
    }
    sum += double(row_sum);
  }
  return sum;
}

template <class T>
[[gnu::always_inline]] inline void backward_band(const T* a, const T* b, const T* dm, int H, int W, int C, T g,
                                                 T* grad, int task, const Window<T>& win) {
  const Band band(task, H);
  const size_t plane = static_cast<size_t>(H) * W;
  BandBlur<T> blur(band, H, W, 3, win.w);  // the three derivative planes of this channel
  blur.horizontal([&](int r, T* const* p) {
    for (int k = 0; k < 3; ++k) {
      const T* src = dm + (static_cast<size_t>(band.c) * 3 + k) * plane + static_cast<size_t>(r) * W;
      std::copy(src, src + W, p[k]);
    }
  });
  std::vector<T> m(static_cast<size_t>(3) * W);
  for (int y = band.y0; y < band.y1; ++y) {
    blur.vertical(y, m.data());
    const size_t row = static_cast<size_t>(y) * W * C + band.c;
    for (int x = 0; x < W; ++x) {
      const size_t i = row + static_cast<size_t>(x) * C;
      grad[i] = g * (m[x] + 2 * a[i] * m[W + x] + b[i] * m[2 * W + x]);
    }
  }
}

template <class T>
using ForwardFn = double (*)(const T*, const T*, int, int, int, T*, int, const Window<T>&);
template <class T>
using BackwardFn = void (*)(const T*, const T*, const T*, int, int, int, T, T*, int, const Window<T>&);

// Instruction-set builds as the tile kernels' (rasterize_cpu.h): the rows vectorise per build.
#define CLS_SSIM_KERNELS(NAME, ATTRIBUTE)                                                                    \
  template <class T>                                                                                         \
  ATTRIBUTE double forward_band_##NAME(const T* a, const T* b, int H, int W, int C, T* dm, int task,         \
                                       const Window<T>& win) {                                               \
    return forward_band(a, b, H, W, C, dm, task, win);                                                       \
  }                                                                                                          \
  template <class T>                                                                                         \
  ATTRIBUTE void backward_band_##NAME(const T* a, const T* b, const T* dm, int H, int W, int C, T g, T* grad, \
                                      int task, const Window<T>& win) {                                      \
    backward_band(a, b, dm, H, W, C, g, grad, task, win);                                                    \
  }
CLS_SSIM_KERNELS(baseline, )
#if CLS_X86_KERNELS
CLS_SSIM_KERNELS(v3, [[gnu::target("arch=x86-64-v3")]])
CLS_SSIM_KERNELS(v4, [[gnu::target("arch=x86-64-v4,prefer-vector-width=512")]])
#endif
#undef CLS_SSIM_KERNELS

template <class T>
std::pair<ForwardFn<T>, BackwardFn<T>> band_kernels() {
#if CLS_X86_KERNELS
  const CpuKernels k = cpu_kernels();
  if (k == CpuKernels::X86_64_V4) return {&forward_band_v4<T>, &backward_band_v4<T>};
  if (k == CpuKernels::X86_64_V3) return {&forward_band_v3<T>, &backward_band_v3<T>};
#endif
  return {&forward_band_baseline<T>, &backward_band_baseline<T>};
}

}  // namespace

std::array<double, kSsimWindow> ssim_window_taps() {
  constexpr double kSigma = 1.5;
  std::array<double, kTaps> w{};
  double sum = 0;
  for (int i = 0; i < kTaps; ++i) {
    const double x = i - kRadius;
    sum += (w[i] = std::exp(-x * x / (2 * kSigma * kSigma)));
  }
  for (double& v : w) v /= sum;
  return w;
}

template <class T>
double ssim_forward_cpu(const T* a, const T* b, int H, int W, int C, T* dmoments) {
  const Window<T> win;
  const ForwardFn<T> fn = band_kernels<T>().first;
  const int tasks = task_count(H, C);
  std::vector<double> sums(tasks);  // added in task order: the same result for any thread count
#pragma omp parallel for schedule(dynamic, 1)
  for (int t = 0; t < tasks; ++t) sums[t] = fn(a, b, H, W, C, dmoments, t, win);
  double total = 0;
  for (double s : sums) total += s;
  return total / (double(H) * W * C);
}

template <class T>
void ssim_backward_cpu(const T* a, const T* b, const T* dmoments, int H, int W, int C, T scale, T* grad_a) {
  const Window<T> win;
  const BackwardFn<T> fn = band_kernels<T>().second;
  const T g = T(double(scale) / (double(H) * W * C));
  const int tasks = task_count(H, C);
#pragma omp parallel for schedule(dynamic, 1)
  for (int t = 0; t < tasks; ++t) fn(a, b, dmoments, H, W, C, g, grad_a, t, win);
}

template double ssim_forward_cpu<float>(const float*, const float*, int, int, int, float*);
template double ssim_forward_cpu<double>(const double*, const double*, int, int, int, double*);
template void ssim_backward_cpu<float>(const float*, const float*, const float*, int, int, int, float, float*);
template void ssim_backward_cpu<double>(const double*, const double*, const double*, int, int, int, double, double*);

}  // namespace cls
