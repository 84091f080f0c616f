#include "query/relevance_image.h"

#include <opencv2/imgproc.hpp>
#include <torch/types.h>

#include "core/error.h"

namespace cls {

cv::Mat colour_map(const at::Tensor& map, MapRange range) {
  if (!map.defined() || map.dim() != 2) throw Error("colour_map: the map must be H x W");
  if (!(range.hi > range.lo)) throw Error("colour_map: empty value range");
  const at::Tensor u8 = ((map.to(torch::kCPU, torch::kFloat64) - range.lo) * (255.0 / (range.hi - range.lo)))
                            .clamp(0, 255)
                            .round()
                            .to(torch::kUInt8)
                            .contiguous();
  const cv::Mat grey(int(map.size(0)), int(map.size(1)), CV_8UC1, u8.data_ptr<uint8_t>());
  cv::Mat out;
  cv::applyColorMap(grey, out, cv::COLORMAP_TURBO);  // copies: `u8` may go
  return out;
}

cv::Mat colour_legend(int width, int height) {
  cv::Mat grey(height, width, CV_8UC1);
  for (int x = 0; x < width; ++x) grey.col(x).setTo(cv::Scalar(width > 1 ? 255.0 * x / (width - 1) : 0));
  cv::Mat out;
  cv::applyColorMap(grey, out, cv::COLORMAP_TURBO);
  return out;
}

}  // namespace cls
