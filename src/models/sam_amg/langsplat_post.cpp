#include "models/sam_amg/langsplat_post.h"

#include <omp.h>

#include <algorithm>

#include "core/error.h"
#include "core/log.h"

namespace cls::amg {

MasksUpdateResult masks_update(const MaskLevels& levels, const MaskNmsParams& params, MaskNmsMethod method,
                               int threads) {
  MasksUpdateResult out;
  for (int l = 0; l < kNumLevels; ++l) {
    const auto& recs = levels[l];
    if (recs.empty()) continue;
    std::vector<double> scores(recs.size());
    for (size_t i = 0; i < recs.size(); ++i)  // Python floats: float64 product of the float32 values
      scores[i] = static_cast<double>(recs[i].stability_score) * static_cast<double>(recs[i].predicted_iou);
    std::vector<int> selected;
    if (method == MaskNmsMethod::Fast) {
      std::vector<PackedMask> packed(recs.size());
#pragma omp parallel for num_threads(threads > 0 ? threads : omp_get_max_threads()) schedule(dynamic)
      for (size_t i = 0; i < recs.size(); ++i) packed[i] = pack_mask(recs[i].segmentation);
      selected = mask_nms_fast(packed, scores, params, threads);
    } else {
      std::vector<BinaryMask> dense;
      for (const auto& r : recs) dense.push_back(rle_to_mask(r.segmentation));
      selected = method == MaskNmsMethod::Reference ? mask_nms_reference(dense, scores, params)
                                                    : mask_nms_torch(dense, scores, params);
    }
    out.selected[l] = selected;
    std::vector<int> kept = selected;
    std::sort(kept.begin(), kept.end());
    out.kept[l] = kept;
    for (int i : kept) out.levels[l].push_back(recs[i]);
  }
  return out;
}

SegMap build_seg_map(const MaskLevels& levels, int height, int width) {
  SegMap map;
  map.height = height, map.width = width;
  map.values.assign(static_cast<size_t>(kNumLevels) * height * width, -1);
  int32_t offset = 0;
  for (int l = 0; l < kNumLevels; ++l) {
    int32_t* plane = map.values.data() + static_cast<size_t>(l) * height * width;
    const auto& recs = levels[l];
    for (size_t i = 0; i < recs.size(); ++i) {
      const MaskRle& rle = recs[i].segmentation;
      if (rle.height != height || rle.width != width)
        throw Error(cat("seg map: mask ", i, " of level ", level_name(l), " is ", rle.height, "x", rle.width,
                        ", the image ", height, "x", width));
      uint64_t pos = 0;
      for (size_t c = 0; c < rle.counts.size(); ++c) {
        const uint64_t end = pos + rle.counts[c];
        if (end > static_cast<uint64_t>(height) * width) throw Error("seg map: RLE counts exceed the mask size");
        if (c % 2 == 1)
          for (uint64_t p = pos; p < end; ++p)
            plane[(p % height) * width + p / height] = offset + static_cast<int32_t>(i);
        pos = end;
      }
    }
    map.level_lengths[l] = static_cast<int>(recs.size());
    offset += static_cast<int32_t>(recs.size());
  }
  return map;
}

}  // namespace cls::amg
