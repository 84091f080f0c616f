#pragma once
// A deliberate error in the city transform a synthetic scene gives the pipeline (synth --city-error),
// so alignment and robustness benchmarks know the truth: images, points and ground truth stay exact.
#include <cstdint>
#include <string>

#include "citymodel/city_transform.h"
#include "core/math.h"

namespace cls::synth {

struct CityError {
  double metres = 0;   // translation length (scene units)
  double degrees = 0;  // rotation angle
  double scale = 0;    // relative scale error: the model comes out 1 + scale times its size
  bool any() const { return metres != 0 || degrees != 0 || scale != 0; }
};

// Parses "t=METRES,r=DEGREES,s=FRACTION" (any subset, any order); cls::UsageError naming the bad part.
CityError parse_city_error(const std::string& text);

// The error as a scene-frame similarity about `centre`: scale 1 + e.scale, a rotation of e.degrees about
// a random axis and a translation of e.metres in a random direction, both drawn from `seed`.
CityTransform city_error_transform(const CityError& e, uint64_t seed, Vec3d centre);

}  // namespace cls::synth
