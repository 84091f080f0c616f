#pragma once
// utils/amg.py remove_small_regions: fill small holes or drop small islands of a mask, using
// OpenCV's connectedComponentsWithStats with 8-connectivity exactly as the reference does.
#include "models/sam_amg/binary_mask.h"

namespace cls::amg {

enum class SmallRegionMode { Holes, Islands };

// Holes: components of the inverted mask (also those touching the border) with area < min_area are
// filled. Islands: components of the mask with area < min_area are removed; if every component is
// small the largest (first of equal size, in OpenCV label order) is kept. Returns whether the mask
// changed; `mask` is rewritten in place only then.
bool remove_small_regions(BinaryMask& mask, int64_t min_area, SmallRegionMode mode);

}  // namespace cls::amg
