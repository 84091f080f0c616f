#include "synth/city_error.h"

#include <cmath>

#include "core/error.h"
#include "core/strings.h"
#include "synth/random.h"

namespace cls::synth {

CityError parse_city_error(const std::string& text) {
  CityError e;
  const std::string usage = "--city-error wants t=METRES,r=DEGREES,s=FRACTION (any of them), got \"" + text + "\"";
  for (const auto& [key, x] : key_numbers(text, usage)) {
    if (key == "t" && x >= 0) e.metres = x;
    else if (key == "r" && x >= 0) e.degrees = x;
    else if (key == "s" && x > -1) e.scale = x;
    else throw UsageError(usage + ": t and r must be >= 0, s > -1, no other keys");
  }
  return e;
}

CityTransform city_error_transform(const CityError& e, uint64_t seed, Vec3d centre) {
  Rng rng(seed, Stream::CityError);
  auto random_unit = [&] {
    const Vec3d v{rng.gaussian(), rng.gaussian(), rng.gaussian()};
    return normalized(v);
  };
  const Vec3d direction = random_unit();
  const Vec3d axis = random_unit();
  const Mat3d R = axis_angle_to_rotation((e.degrees * M_PI / 180) * axis);
  const double s = 1 + e.scale;
  // x -> centre + s R (x - centre) + metres * direction
  return similarity_transform(s, R, centre + e.metres * direction - s * (R * centre));
}

}  // namespace cls::synth
