#pragma once
// A slow, obviously correct renderer the fast paths are tested against: double precision, every
// pixel blends ALL Gaussians sorted by depth, written out with plain matrix products instead of the
// rasterizer's fused expressions. It keeps the rasterizer's discrete rules (near plane, frustum clamp,
// low-pass, 3-sigma tile rectangle, alpha clamps, early stop) so the outputs must agree exactly up to
// rounding.
#include <vector>

#include "splat/rasterize_cpu.h"

namespace cls {

struct ReferenceImage {
  int width = 0, height = 0, channels = 0;
  std::vector<double> image;  // H x W x C
  std::vector<double> alpha;  // H x W
  std::vector<double> depth;  // H x W
};

ReferenceImage reference_render(const SplatCamera<double>& cam, const SplatInputs<double>& in);

}  // namespace cls
