#pragma once
// Relevance maps as pictures: a float map colour-mapped over a fixed value range (OpenCV's turbo
// colormap: dark blue at `lo`, dark red at `hi`, values outside clamped), and the legend bar.
#include <ATen/core/Tensor.h>
#include <opencv2/core.hpp>

namespace cls {

struct MapRange {
  double lo = 0, hi = 1;
};

// map H x W (any float dtype) -> CV_8UC3 BGR (ready for cv::imwrite).
cv::Mat colour_map(const at::Tensor& map, MapRange range);

// A horizontal legend: `width` x `height` pixels running lo (left) to hi (right).
cv::Mat colour_legend(int width = 256, int height = 16);

}  // namespace cls
