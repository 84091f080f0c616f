#pragma once
// 8-bit BGR images (OpenCV's layout) <-> H x W x 3 float RGB tensors in [0, 1] (the rasterizer's layout).
#include <ATen/core/Tensor.h>
#include <opencv2/core/mat.hpp>

namespace cls {

at::Tensor image_to_tensor(const cv::Mat& bgr);
// The same as H x W x 3 uint8 RGB (a quarter of the memory; image_to_tensor = this / 255).
at::Tensor image_to_tensor_u8(const cv::Mat& bgr);
// Values are clamped to [0, 1] and rounded to 8 bits; any float dtype and device.
cv::Mat tensor_to_image(const at::Tensor& rgb);

}  // namespace cls
