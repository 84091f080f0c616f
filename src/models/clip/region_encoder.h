#pragma once
// Batched CLIP encoding of image regions (LangSplat: one 512-d feature per SAM mask).
#include <ATen/core/Tensor.h>
#include <opencv2/core.hpp>

#include <vector>

namespace cls::clip {

class ClipModel;

// CLIP's pixel normalisation (clip.py _transform / LangSplat's OpenCLIPNetwork.process).
constexpr float kClipMean[3] = {0.48145466f, 0.4578275f, 0.40821073f};
constexpr float kClipStd[3] = {0.26862954f, 0.26130258f, 0.27577711f};

// CV_8UC3 RGB crops (all size S x S) -> [N, 3, S, S] float32: /255, then (x - mean) / std.
at::Tensor normalize_crops(const std::vector<cv::Mat>& crops);

// LangSplat region features: the crop of every mask (region_crops.h) at the model's resolution,
// encoded `batch_size` at a time, L2-normalised -> [masks.size(), embed_dim] float32 on the CPU.
at::Tensor encode_regions(const ClipModel& model, const cv::Mat& rgb, const std::vector<cv::Mat>& masks,
                          int batch_size = 32);

}  // namespace cls::clip
