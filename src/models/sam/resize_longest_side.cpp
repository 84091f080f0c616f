#include "models/sam/resize_longest_side.h"

#include <algorithm>
#include <cmath>

namespace cls::sam {

std::pair<int, int> preprocess_shape(int old_h, int old_w, int long_side_length) {
  const double scale = double(long_side_length) / double(std::max(old_h, old_w));
  return {int(old_h * scale + 0.5), int(old_w * scale + 0.5)};
}

void ResizeLongestSide::apply_coords(double* xy, size_t n_points, std::pair<int, int> original_hw) const {
  const auto [new_h, new_w] = target_shape(original_hw.first, original_hw.second);
  const double sx = double(new_w) / double(original_hw.second), sy = double(new_h) / double(original_hw.first);
  for (size_t i = 0; i < n_points; ++i) xy[2 * i] *= sx, xy[2 * i + 1] *= sy;
}

namespace {

constexpr int kPrecisionBits = 32 - 8 - 2;  // Pillow's PRECISION_BITS for 8-bit images

// Pillow precompute_coeffs + normalize_coeffs_8bpc for the bilinear filter (support 1).
struct Coeffs {
  int ksize = 0;
  std::vector<int> bounds;  // xmin, count per output index
  std::vector<int32_t> k;   // ksize per output index
};

Coeffs precompute_coeffs(int in_size, int out_size) {
  const double scale = double(in_size) / double(out_size);
  const double filterscale = std::max(scale, 1.0);
  const double support = 1.0 * filterscale;
  Coeffs c;
  c.ksize = int(std::ceil(support)) * 2 + 1;
  c.bounds.resize(size_t(out_size) * 2);
  c.k.assign(size_t(out_size) * c.ksize, 0);
  std::vector<double> w(size_t(c.ksize));
  for (int xx = 0; xx < out_size; ++xx) {
    const double center = (xx + 0.5) * scale;
    const double ss = 1.0 / filterscale;
    int xmin = int(center - support + 0.5);
    if (xmin < 0) xmin = 0;
    int xmax = int(center + support + 0.5);
    if (xmax > in_size) xmax = in_size;
    xmax -= xmin;
    double ww = 0.0;
    for (int x = 0; x < xmax; ++x) {
      double t = std::fabs((x + xmin - center + 0.5) * ss);
      const double v = t < 1.0 ? 1.0 - t : 0.0;
      w[size_t(x)] = v;
      ww += v;
    }
    for (int x = 0; x < xmax; ++x) {
      const double v = ww != 0.0 ? w[size_t(x)] / ww : w[size_t(x)];
      c.k[size_t(xx) * c.ksize + x] =
          v < 0 ? int32_t(-0.5 + v * (1 << kPrecisionBits)) : int32_t(0.5 + v * (1 << kPrecisionBits));
    }
    c.bounds[size_t(xx) * 2] = xmin;
    c.bounds[size_t(xx) * 2 + 1] = xmax;
  }
  return c;
}

inline uint8_t clip8(int64_t in) {
  const int64_t v = in >> kPrecisionBits;
  return uint8_t(v < 0 ? 0 : (v > 255 ? 255 : v));
}

}  // namespace

std::vector<uint8_t> resize_bilinear_pil(const uint8_t* src, int h, int w, int ch, int out_h, int out_w) {
  // Horizontal pass (skipped by Pillow when the width does not change; identical anyway).
  std::vector<uint8_t> mid;
  const uint8_t* hsrc = src;
  if (out_w != w) {
    const Coeffs c = precompute_coeffs(w, out_w);
    mid.resize(size_t(h) * out_w * ch);
    for (int y = 0; y < h; ++y)
      for (int xx = 0; xx < out_w; ++xx) {
        const int xmin = c.bounds[size_t(xx) * 2], n = c.bounds[size_t(xx) * 2 + 1];
        const int32_t* k = &c.k[size_t(xx) * c.ksize];
        for (int b = 0; b < ch; ++b) {
          int64_t ss = int64_t(1) << (kPrecisionBits - 1);
          for (int x = 0; x < n; ++x) ss += int64_t(src[(size_t(y) * w + xmin + x) * ch + b]) * k[x];
          mid[(size_t(y) * out_w + xx) * ch + b] = clip8(ss);
        }
      }
    hsrc = mid.data();
  }
  if (out_h == h) return out_w != w ? mid : std::vector<uint8_t>(src, src + size_t(h) * w * ch);
  const Coeffs c = precompute_coeffs(h, out_h);
  std::vector<uint8_t> out(size_t(out_h) * out_w * ch);
  for (int yy = 0; yy < out_h; ++yy) {
    const int ymin = c.bounds[size_t(yy) * 2], n = c.bounds[size_t(yy) * 2 + 1];
    const int32_t* k = &c.k[size_t(yy) * c.ksize];
    for (int xx = 0; xx < out_w; ++xx)
      for (int b = 0; b < ch; ++b) {
        int64_t ss = int64_t(1) << (kPrecisionBits - 1);
        for (int y = 0; y < n; ++y) ss += int64_t(hsrc[(size_t(ymin + y) * out_w + xx) * ch + b]) * k[y];
        out[(size_t(yy) * out_w + xx) * ch + b] = clip8(ss);
      }
  }
  return out;
}

}  // namespace cls::sam
