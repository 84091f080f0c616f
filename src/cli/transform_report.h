#pragma once
// How `align` and `georef` print the distance between two city transforms.
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>

#include "raycast/alignment.h"

namespace cls {

inline nlohmann::json difference_json(const TransformDifference& d) {
  return {{"centre", d.centre}, {"max_displacement", d.max_displacement}, {"rotation_deg", d.rotation_deg},
          {"scale", d.scale}};
}

inline std::string describe(const TransformDifference& d) {
  char text[160];
  std::snprintf(text, sizeof text, "%.4f m at the model's centre (%.4f m at most), %.4f deg, scale %+.3f%%", d.centre,
                d.max_displacement, d.rotation_deg, 100 * d.scale);
  return text;
}

}  // namespace cls
