#pragma once
// LangSplat preprocess.py after the generator: masks_update (mask_nms per level with score =
// stability x predicted IoU, then `filter`, which keeps the survivors in list order) and the seg map
// of sam_encoder/mask2segmap with the level offsets added in `create`.
#include <cstdint>
#include <vector>

#include "models/sam_amg/mask_nms.h"
#include "models/sam_amg/mask_record.h"

namespace cls::amg {

enum class MaskNmsMethod { Fast, Reference, Torch };

struct MasksUpdateResult {
  MaskLevels levels;                                   // surviving records, original order
  std::array<std::vector<int>, kNumLevels> selected;   // mask_nms output (descending score)
  std::array<std::vector<int>, kNumLevels> kept;       // sorted input indices
};

// An empty level stays empty (the reference raises on np.stack of an empty list).
MasksUpdateResult masks_update(const MaskLevels& levels, const MaskNmsParams& params,
                               MaskNmsMethod method = MaskNmsMethod::Fast, int threads = 0);

// 4 x H x W, row-major per level, -1 where no mask. Per level masks are painted in list order
// (later ones overwrite), values are offset by the mask counts of the previous levels so that they
// index the concatenated [default | s | m | l] feature list (LangSplat's `create`).
struct SegMap {
  int height = 0, width = 0;
  std::vector<int32_t> values;  // kNumLevels * height * width
  std::array<int, kNumLevels> level_lengths{};
  int32_t at(int level, int y, int x) const {
    return values[(static_cast<size_t>(level) * height + y) * width + x];
  }
};
// Throws cls::Error if a record's mask is not height x width.
SegMap build_seg_map(const MaskLevels& levels, int height, int width);

}  // namespace cls::amg
