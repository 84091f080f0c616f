#pragma once
// Axis-aligned bounding box in the scene frame.
#include <algorithm>
#include <limits>

#include "core/math.h"

namespace cls::synth {

struct Box3d {
  Vec3d lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
           std::numeric_limits<double>::infinity()};
  Vec3d hi{-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
           -std::numeric_limits<double>::infinity()};

  void extend(Vec3d p) {
    for (int i = 0; i < 3; ++i) {
      lo[i] = std::min(lo[i], p[i]);
      hi[i] = std::max(hi[i], p[i]);
    }
  }
  bool empty() const { return !(lo.x <= hi.x); }
  Vec3d center() const { return 0.5 * (lo + hi); }
  Vec3d size() const { return hi - lo; }
};

}  // namespace cls::synth
