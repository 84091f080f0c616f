#include "models/sam_amg/binary_mask.h"

#include <algorithm>

namespace cls::amg {

int64_t BinaryMask::area() const {
  int64_t n = 0;
  for (uint8_t p : pixels) n += p != 0;
  return n;
}

BoxXyxy mask_to_box(const uint8_t* pixels, int height, int width, int stride) {
  int64_t x0 = width, y0 = height, x1 = -1, y1 = -1;
  for (int y = 0; y < height; ++y) {
    const uint8_t* row = pixels + static_cast<size_t>(y) * stride;
    int first = -1, last = -1;
    for (int x = 0; x < width; ++x)
      if (row[x]) {
        first = x;
        break;
      }
    if (first < 0) continue;
    for (int x = width - 1; x >= first; --x)
      if (row[x]) {
        last = x;
        break;
      }
    y0 = std::min<int64_t>(y0, y);
    y1 = y;
    x0 = std::min<int64_t>(x0, first);
    x1 = std::max<int64_t>(x1, last);
  }
  if (y1 < 0) return {};  // empty mask: the reference zeroes the box
  return {x0, y0, x1, y1};
}

}  // namespace cls::amg
