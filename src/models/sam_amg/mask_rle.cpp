#include "models/sam_amg/mask_rle.h"

#include "core/error.h"
#include "core/log.h"

namespace cls::amg {

MaskRle mask_to_rle(const BinaryMask& mask) {
  MaskRle rle;
  rle.height = mask.height;
  rle.width = mask.width;
  uint8_t current = 0;  // the first run counts zeros
  uint32_t run = 0;
  for (int x = 0; x < mask.width; ++x)
    for (int y = 0; y < mask.height; ++y) {
      const uint8_t v = mask.at(y, x) ? 1 : 0;
      if (v != current) {
        rle.counts.push_back(run);
        run = 0;
        current = v;
      }
      ++run;
    }
  rle.counts.push_back(run);
  return rle;
}

BinaryMask rle_to_mask(const MaskRle& rle) {
  if (rle.height < 0 || rle.width < 0) throw Error("RLE: negative size");
  const uint64_t total = static_cast<uint64_t>(rle.height) * rle.width;
  uint64_t sum = 0;
  for (uint32_t c : rle.counts) sum += c;
  if (sum != total)
    throw Error(cat("RLE: counts sum to ", sum, " but the size is ", rle.height, "x", rle.width));
  BinaryMask mask(rle.height, rle.width);
  uint64_t pos = 0;  // column-major index
  for (size_t i = 0; i < rle.counts.size(); ++i) {
    const uint64_t end = pos + rle.counts[i];
    if (i % 2 == 1)
      for (uint64_t p = pos; p < end; ++p) {
        const uint64_t x = p / rle.height, y = p % rle.height;
        mask.pixels[y * rle.width + x] = 1;
      }
    pos = end;
  }
  return mask;
}

int64_t area_from_rle(const MaskRle& rle) {
  int64_t area = 0;
  for (size_t i = 1; i < rle.counts.size(); i += 2) area += rle.counts[i];
  return area;
}

}  // namespace cls::amg
