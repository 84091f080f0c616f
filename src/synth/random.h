#pragma once
// Deterministic randomness for the synthetic scenes: a splitmix64 generator and hashes of integer
// keys. No std:: distributions (their output differs between standard libraries), so a seed gives
// the same bytes everywhere; streams are keyed by (seed, purpose, index), so results do not depend
// on the order in which threads draw them.
#include <cmath>
#include <cstdint>

namespace cls::synth {

// splitmix64's output function: a strong 64-bit mixer.
inline uint64_t mix64(uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

// Hash of a sequence of integer keys.
inline uint64_t hash_keys(uint64_t a, uint64_t b, uint64_t c = 0, uint64_t d = 0) {
  uint64_t h = mix64(a + 0x9e3779b97f4a7c15ULL);
  h = mix64(h ^ (b + 0x9e3779b97f4a7c15ULL));
  h = mix64(h ^ (c + 0x9e3779b97f4a7c15ULL));
  return mix64(h ^ (d + 0x9e3779b97f4a7c15ULL));
}

// Uniform double in [0, 1) from the top 53 bits.
inline double unit_from_bits(uint64_t bits) { return static_cast<double>(bits >> 11) * 0x1.0p-53; }

// Purposes of the random streams (keys for Rng construction), so two uses never share a stream.
enum class Stream : uint64_t { Cameras = 1, Clutter, Lighting, Materials, SparsePoints, GroundTruth, CityError, DropOpenings, Occluders, Gps };

class Rng {
 public:
  Rng(uint64_t seed, Stream stream, uint64_t index = 0)
      : state_(hash_keys(seed, static_cast<uint64_t>(stream), index)) {}

  uint64_t next() {
    state_ += 0x9e3779b97f4a7c15ULL;
    return mix64(state_);
  }
  double uniform() { return unit_from_bits(next()); }                        // [0, 1)
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }  // [lo, hi)
  int below(int n) { return static_cast<int>(uniform() * n); }                // 0 .. n-1
  // Standard normal by Box-Muller (one value per call; std::log/cos/sin are correctly rounded
  // enough on glibc for reproducibility across runs of the same binary).
  double gaussian() {
    const double u1 = 1.0 - uniform();  // (0, 1]
    const double u2 = uniform();
    return std::sqrt(-2.0 * std::log(u1)) * std::cos(6.283185307179586 * u2);
  }

 private:
  uint64_t state_;
};

}  // namespace cls::synth
