#pragma once
// LangSplat's mask_nms (preprocess.py): score-ordered suppression of masks by mask IoU and by
// containment ("inner" overlap), O(M^2) pairs. Three implementations that must agree exactly:
//  - mask_nms_reference: the Python algorithm written out literally (dense masks, full M x M
//    matrices, triu/tril column maxima); slow, the yardstick of the tests;
//  - mask_nms_fast: bit-packed masks, popcount intersections restricted to the overlap of the two
//    masks' bounding boxes, pairs spread over threads; the decision uses the same float32 formulas
//    on the same integer counts, so it is exact, not approximate;
//  - mask_nms_torch (mask_nms_torch.cpp): intersections as a chunked matrix product on a LibTorch
//    device (CPU or CUDA), then the matrix formulation of the reference.
#include <cstdint>
#include <vector>

#include "models/sam_amg/binary_mask.h"
#include "models/sam_amg/mask_rle.h"

namespace cls::amg {

struct MaskNmsParams {
  double iou_thr = 0.8;    // LangSplat masks_update values
  double score_thr = 0.7;
  double inner_thr = 0.5;
};

// What mask_nms returns: the surviving input indices in descending-score order.
//
// Ties in score: torch.sort(descending) is not stable; here the sort is stable (lower index first).
// Fallbacks: when no mask passes one of the score / inner tests LangSplat means to keep the top 3
// masks for that test, but its code indexes a 1-D tensor with two indices and raises IndexError;
// here the intended top-3 fallback is applied instead of failing.
// Masks of zero area behave as in torch (0/0 = NaN IoU against another empty mask: never kept).
std::vector<int> mask_nms_reference(const std::vector<BinaryMask>& masks, const std::vector<double>& scores,
                                    const MaskNmsParams& params);

// A mask packed 64 pixels per word, row by row, with the bounding range of its set pixels.
struct PackedMask {
  int height = 0, width = 0, words_per_row = 0;
  std::vector<uint64_t> bits;  // height * words_per_row
  int64_t area = 0;
  int row_begin = 0, row_end = 0;    // rows holding set pixels: [row_begin, row_end)
  int word_begin = 0, word_end = 0;  // words holding set pixels: [word_begin, word_end)
};
PackedMask pack_mask(const BinaryMask& mask);
PackedMask pack_mask(const MaskRle& rle);
int64_t intersection_area(const PackedMask& a, const PackedMask& b);

// threads <= 0: OpenMP's default.
std::vector<int> mask_nms_fast(const std::vector<PackedMask>& masks, const std::vector<double>& scores,
                               const MaskNmsParams& params, int threads = 0);

// device: a LibTorch device string ("cpu", "cuda", "cuda:1"). Exact as long as masks have fewer
// than 2^24 pixels (float32 counts, as the reference).
std::vector<int> mask_nms_torch(const std::vector<BinaryMask>& masks, const std::vector<double>& scores,
                                const MaskNmsParams& params, const char* device = "cpu");

// Shared by all three: the descending score order, and the final selection from the keep flags.
std::vector<int> score_order(const std::vector<double>& scores);
std::vector<int> select_kept(const std::vector<int>& order, const std::vector<double>& sorted_scores,
                             const std::vector<float>& iou_max, const std::vector<float>& inner_max_u,
                             const std::vector<float>& inner_max_l, const MaskNmsParams& params);

}  // namespace cls::amg
