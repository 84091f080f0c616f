#pragma once
// Plain binary masks and the integer boxes SAM's AMG derives from them.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace cls::amg {

// A binary mask at image resolution, row-major (y * width + x), one byte per pixel (0 or 1).
struct BinaryMask {
  int height = 0;
  int width = 0;
  std::vector<uint8_t> pixels;

  BinaryMask() = default;
  BinaryMask(int h, int w) : height(h), width(w), pixels(static_cast<size_t>(h) * w, 0) {}
  uint8_t at(int y, int x) const { return pixels[static_cast<size_t>(y) * width + x]; }
  int64_t area() const;
};

// XYXY box with *inclusive* maxima, as SAM's batched_mask_to_box returns it (int64 there).
struct BoxXyxy {
  int64_t x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  bool operator==(const BoxXyxy& o) const {
    return x0 == o.x0 && y0 == o.y0 && x1 == o.x1 && y1 == o.y1;
  }
};

// utils/amg.py batched_mask_to_box for one mask: [min x, min y, max x, max y] of the set pixels,
// [0, 0, 0, 0] for an empty mask. `stride` is the row pitch of `pixels` (>= width).
BoxXyxy mask_to_box(const uint8_t* pixels, int height, int width, int stride);
inline BoxXyxy mask_to_box(const BinaryMask& m) { return mask_to_box(m.pixels.data(), m.height, m.width, m.width); }

}  // namespace cls::amg
