#include "export/spz.h"

#include <torch/torch.h>
#include <zlib.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "core/endian.h"
#include "core/error.h"
#include "core/log.h"
#include "export/finite_values.h"
#include "splat/sh.h"

namespace cls {
namespace {

constexpr uint32_t kSpzMagic = 0x5053474e;
constexpr double kSpzColorScale = 0.15;
constexpr int kMaxFractionalBits = 12;  // SPZ's own choice: 1/4096 of a unit

uint8_t to_byte(double x) { return static_cast<uint8_t>(std::clamp(std::round(x), 0.0, 255.0)); }

// SPZ's SH quantisation: 8 bits around 128, then the nearest centre of buckets of `bucket` values.
uint8_t sh_byte(double x, int bucket) {
  int q = static_cast<int>(std::round(x * 128.0) + 128.0);
  q = (q + bucket / 2) / bucket * bucket;
  return static_cast<uint8_t>(std::clamp(q, 0, 255));
}

std::string gzip(const std::string& raw) {
  z_stream z{};
  if (deflateInit2(&z, Z_BEST_COMPRESSION, Z_DEFLATED, 15 + 16, 9, Z_DEFAULT_STRATEGY) != Z_OK)
    throw Error("export: SPZ: zlib's deflateInit2 failed");
  std::string out(deflateBound(&z, raw.size()), '\0');
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(raw.data()));
  z.avail_in = static_cast<uInt>(raw.size());
  z.next_out = reinterpret_cast<Bytef*>(out.data());
  z.avail_out = static_cast<uInt>(out.size());
  const int rc = deflate(&z, Z_FINISH);
  out.resize(z.total_out);
  deflateEnd(&z);
  if (rc != Z_STREAM_END) throw Error("export: SPZ: zlib's deflate did not finish");
  return out;
}

template <class T>
void append(std::string& s, T v) {
  static_assert(host_is_little_endian(), "SPZ is little-endian; add a byte swap for this host");
  s.append(reinterpret_cast<const char*>(&v), sizeof v);
}

}  // namespace

int spz_flip_sign(int k) {
  // A direction whose basis values are all non-zero, and its mirror.
  const double x = 0.36, y = 0.48, z = 0.8;
  double b[kMaxShCoeffs], f[kMaxShCoeffs];
  sh_basis(kMaxShDegree, x, y, z, b);
  sh_basis(kMaxShDegree, -x, y, -z, f);
  return f[k] * b[k] > 0 ? 1 : -1;
}

std::string spz_v2(const GaussianModel& g, SpzAxes axes) {
  at::NoGradGuard no_grad;
  const int64_t n = g.size();
  if (n > int64_t(UINT32_MAX)) throw Error("export: SPZ holds at most 2^32 - 1 Gaussians");
  const std::vector<float> means = finite_floats(g.means, "positions"), log_scales = finite_floats(g.log_scales, "log-scales"),
                           logits = finite_floats(g.opacity_logits, "opacity logits"),
                           sh = finite_floats(g.sh(), "spherical harmonics"), quats = finite_floats(g.quats, "rotations");
  const int degree = g.sh_degree(), coeffs = sh_coeff_count(degree);

  float extent = 0;
  for (float v : means) extent = std::max(extent, std::abs(v));
  int bits = kMaxFractionalBits;
  while (bits > 0 && std::ldexp(double(extent), bits) >= double((1 << 23) - 1)) --bits;
  if (std::ldexp(double(extent), bits) >= double((1 << 23) - 1))
    throw Error(cat("export: SPZ: a coordinate of ", extent, " exceeds what 24-bit fixed point holds (2^23)"));

  std::string raw;
  append<uint32_t>(raw, kSpzMagic);
  append<uint32_t>(raw, kSpzVersion);
  append<uint32_t>(raw, static_cast<uint32_t>(n));
  for (uint8_t b : {uint8_t(degree), uint8_t(bits), uint8_t(0), uint8_t(0)}) append<uint8_t>(raw, b);

  const bool luf = axes == SpzAxes::Luf;
  const double flip[3] = {luf ? -1.0 : 1.0, 1, luf ? -1.0 : 1.0};  // LUF -> RUB
  for (int64_t i = 0; i < n; ++i)
    for (int a = 0; a < 3; ++a) {
      const int32_t fixed = static_cast<int32_t>(std::lround(std::ldexp(flip[a] * means[3 * i + a], bits)));
      for (int byte = 0; byte < 3; ++byte) raw.push_back(static_cast<char>((fixed >> (8 * byte)) & 0xff));
    }
  for (int64_t i = 0; i < n; ++i) raw.push_back(static_cast<char>(to_byte(255.0 / (1.0 + std::exp(-double(logits[i]))))));
  for (int64_t i = 0; i < n; ++i)
    for (int c = 0; c < 3; ++c)
      raw.push_back(static_cast<char>(to_byte(sh[i * coeffs * 3 + c] * kSpzColorScale * 255.0 + 127.5)));
  for (int64_t i = 0; i < 3 * n; ++i) raw.push_back(static_cast<char>(to_byte((log_scales[i] + 10.0) * 16.0)));
  for (int64_t i = 0; i < n; ++i) {
    // (w, x, y, z) -> unit (x, y, z, w); x and z flipping is a half turn about y: x and z of the axis flip.
    double q[4] = {quats[4 * i + 1], quats[4 * i + 2], quats[4 * i + 3], quats[4 * i]};
    const double len = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    if (!(len > 0)) throw Error(cat("export: SPZ: Gaussian ", i, " has a zero quaternion"));
    const double sign = q[3] < 0 ? -1 : 1;
    for (int c = 0; c < 3; ++c) raw.push_back(static_cast<char>(to_byte(sign * flip[c] * q[c] / len * 127.5 + 127.5)));
  }
  int flips[kMaxShCoeffs];
  for (int k = 0; k < coeffs; ++k) flips[k] = luf ? spz_flip_sign(k) : 1;
  for (int64_t i = 0; i < n; ++i)
    for (int k = 1; k < coeffs; ++k)
      for (int c = 0; c < 3; ++c)
        raw.push_back(static_cast<char>(sh_byte(flips[k] * sh[(i * coeffs + k) * 3 + c], k < 4 ? 8 : 16)));
  return gzip(raw);
}

}  // namespace cls
