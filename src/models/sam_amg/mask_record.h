#pragma once
// One automatic-mask-generator output record (SamAutomaticMaskGenerator.generate) and the four
// lists LangSplat's fork returns.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "models/sam_amg/mask_rle.h"

namespace cls::amg {

struct MaskRecord {
  MaskRle segmentation;                // uncompressed RLE at image size
  int64_t area = 0;                    // area_from_rle
  std::array<int64_t, 4> bbox{};       // XYWH from the inclusive XYXY box (w = x1 - x0)
  float predicted_iou = 0.0f;
  std::array<double, 2> point{};       // the prompt point (x, y), image frame
  float stability_score = 0.0f;
  std::array<int64_t, 4> crop_box{};   // XYWH
};

// LangSplat's levels, in the order generate() returns them and the seg map stacks them.
enum Level { kDefault = 0, kSmall = 1, kMedium = 2, kLarge = 3 };
inline constexpr int kNumLevels = 4;
inline const char* level_name(int level) {
  static const char* names[kNumLevels] = {"default", "s", "m", "l"};
  return names[level];
}

using MaskLevels = std::array<std::vector<MaskRecord>, kNumLevels>;

}  // namespace cls::amg
