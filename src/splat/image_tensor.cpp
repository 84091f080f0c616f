#include "splat/image_tensor.h"

#include <opencv2/imgproc.hpp>
#include <torch/types.h>

#include "core/error.h"

namespace cls {

at::Tensor image_to_tensor_u8(const cv::Mat& bgr) {
  if (bgr.type() != CV_8UC3) throw Error("image_to_tensor: expected an 8-bit 3-channel image");
  cv::Mat rgb;
  cv::cvtColor(bgr, rgb, cv::COLOR_BGR2RGB);
  return torch::from_blob(rgb.data, {rgb.rows, rgb.cols, 3}, torch::kUInt8).clone();
}

at::Tensor image_to_tensor(const cv::Mat& bgr) { return image_to_tensor_u8(bgr).to(torch::kFloat32).div_(255.0f); }

cv::Mat tensor_to_image(const at::Tensor& rgb) {
  if (rgb.dim() != 3 || rgb.size(2) != 3) throw Error("tensor_to_image: expected an H x W x 3 tensor");
  const at::Tensor u8 =
      rgb.detach().to(torch::kCPU, torch::kFloat32).clamp(0, 1).mul(255).round().to(torch::kUInt8).contiguous();
  const cv::Mat view(int(u8.size(0)), int(u8.size(1)), CV_8UC3, u8.data_ptr<uint8_t>());
  cv::Mat bgr;
  cv::cvtColor(view, bgr, cv::COLOR_RGB2BGR);  // copies: `u8` may go
  return bgr;
}

}  // namespace cls
