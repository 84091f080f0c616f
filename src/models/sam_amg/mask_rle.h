#pragma once
// Uncompressed COCO run-length encoding as SAM's utils/amg.py writes it (mask_to_rle_pytorch,
// rle_to_mask, area_from_rle): pixels in column-major (Fortran) order, runs alternate starting with
// a run of zeros (length 0 when pixel (0, 0) is set); size = [height, width].
#include <cstdint>
#include <vector>

#include "models/sam_amg/binary_mask.h"

namespace cls::amg {

struct MaskRle {
  int height = 0;
  int width = 0;
  std::vector<uint32_t> counts;
};

MaskRle mask_to_rle(const BinaryMask& mask);
// Throws cls::Error when the counts do not add up to height * width.
BinaryMask rle_to_mask(const MaskRle& rle);
// Sum of the runs of ones (odd positions).
int64_t area_from_rle(const MaskRle& rle);

}  // namespace cls::amg
