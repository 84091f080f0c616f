#include "models/clip/region_encoder.h"

#include <ATen/ATen.h>

#include "core/error.h"
#include "models/clip/clip_model.h"
#include "models/clip/region_crops.h"

namespace cls::clip {

at::Tensor normalize_crops(const std::vector<cv::Mat>& crops) {
  if (crops.empty()) throw Error("normalize_crops: no crops");
  const int s = crops[0].rows;
  for (const cv::Mat& c : crops)
    if (c.type() != CV_8UC3 || c.rows != s || c.cols != s)
      throw Error("normalize_crops: every crop must be CV_8UC3 of the same square size");
  at::Tensor out = at::empty({static_cast<int64_t>(crops.size()), 3, s, s}, at::kFloat);
  float* dst = out.data_ptr<float>();
  const int64_t plane = int64_t(s) * s;
#pragma omp parallel for schedule(static)
  for (int64_t i = 0; i < static_cast<int64_t>(crops.size()); ++i) {
    const cv::Mat& c = crops[i];
    float* base = dst + i * 3 * plane;
    for (int y = 0; y < s; ++y) {
      const cv::Vec3b* row = c.ptr<cv::Vec3b>(y);
      for (int x = 0; x < s; ++x)
        for (int ch = 0; ch < 3; ++ch)
          base[ch * plane + int64_t(y) * s + x] = (row[x][ch] / 255.0f - kClipMean[ch]) / kClipStd[ch];
    }
  }
  return out;
}

at::Tensor encode_regions(const ClipModel& model, const cv::Mat& rgb, const std::vector<cv::Mat>& masks,
                          int batch_size) {
  if (batch_size <= 0) throw Error("encode_regions: batch size must be positive");
  const int res = model.config().arch.image_resolution;
  // Validate up front: nothing may throw inside the parallel loop.
  if (rgb.type() != CV_8UC3) throw Error("encode_regions: the image must be 8-bit RGB (CV_8UC3)");
  for (size_t i = 0; i < masks.size(); ++i)
    if (masks[i].type() != CV_8U || masks[i].size() != rgb.size())
      throw Error("encode_regions: mask " + std::to_string(i) + " must be CV_8U with the image's size");
  std::vector<at::Tensor> parts;
  for (size_t b = 0; b < masks.size(); b += static_cast<size_t>(batch_size)) {
    const size_t e = std::min(masks.size(), b + static_cast<size_t>(batch_size));
    std::vector<cv::Mat> crops(e - b);
#pragma omp parallel for schedule(dynamic)
    for (int64_t i = 0; i < static_cast<int64_t>(e - b); ++i) crops[i] = langsplat_region_crop(rgb, masks[b + i], res);
    const at::Tensor pixels = normalize_crops(crops).to(model.options().device);
    parts.push_back(l2_normalize(model.encode_image(pixels).to(at::kFloat)).cpu());
  }
  if (parts.empty()) return at::empty({0, model.config().arch.embed_dim}, at::kFloat);
  return at::cat(parts, 0);
}

}  // namespace cls::clip
