#include "synth/noise.h"

#include <cmath>

#include "synth/random.h"

namespace cls::synth {

float cell_random(int64_t i, int64_t j, int64_t k, uint64_t key) {
  return static_cast<float>(unit_from_bits(hash_keys(key, static_cast<uint64_t>(i), static_cast<uint64_t>(j),
                                                     static_cast<uint64_t>(k))));
}

namespace {
float smooth(float t) { return t * t * (3.0f - 2.0f * t); }
float lerp(float a, float b, float t) { return a + (b - a) * t; }
}  // namespace

float value_noise(float x, float y, float z, uint64_t key) {
  const float fx = std::floor(x), fy = std::floor(y), fz = std::floor(z);
  const auto ix = static_cast<int64_t>(fx), iy = static_cast<int64_t>(fy), iz = static_cast<int64_t>(fz);
  const float tx = smooth(x - fx), ty = smooth(y - fy), tz = smooth(z - fz);
  float c[2][2][2];
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b)
      for (int d = 0; d < 2; ++d) c[a][b][d] = cell_random(ix + a, iy + b, iz + d, key);
  const float x00 = lerp(c[0][0][0], c[1][0][0], tx), x10 = lerp(c[0][1][0], c[1][1][0], tx);
  const float x01 = lerp(c[0][0][1], c[1][0][1], tx), x11 = lerp(c[0][1][1], c[1][1][1], tx);
  return lerp(lerp(x00, x10, ty), lerp(x01, x11, ty), tz);
}

float fbm(float x, float y, float z, int octaves, uint64_t key) {
  float sum = 0, amplitude = 0.5f, total = 0, f = 1;
  for (int o = 0; o < octaves; ++o) {
    sum += amplitude * value_noise(x * f, y * f, z * f, key + static_cast<uint64_t>(o));
    total += amplitude;
    amplitude *= 0.5f;
    f *= 2.0f;
  }
  return sum / total;
}

}  // namespace cls::synth
