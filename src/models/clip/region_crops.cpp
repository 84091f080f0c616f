#include "models/clip/region_crops.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>

#include "core/error.h"

namespace cls::clip {

MaskBox sam_mask_box(const cv::Mat& mask) {
  if (mask.type() != CV_8U) throw Error("sam_mask_box: the mask must be CV_8U");
  int x0 = mask.cols, y0 = mask.rows, x1 = -1, y1 = -1;
  for (int y = 0; y < mask.rows; ++y) {
    const uint8_t* row = mask.ptr<uint8_t>(y);
    for (int x = 0; x < mask.cols; ++x) {
      if (!row[x]) continue;
      x0 = std::min(x0, x);
      x1 = std::max(x1, x);
      y0 = std::min(y0, y);
      y1 = std::max(y1, y);
    }
  }
  if (x1 < 0) return {};
  return {x0, y0, x1 - x0, y1 - y0};
}

cv::Mat langsplat_region_crop(const cv::Mat& rgb, const cv::Mat& mask, const MaskBox& box, int out_size) {
  if (rgb.type() != CV_8UC3) throw Error("region crop: the image must be 8-bit RGB (CV_8UC3)");
  if (mask.type() != CV_8U || mask.size() != rgb.size())
    throw Error("region crop: the mask must be CV_8U with the image's size");
  if (out_size <= 0) throw Error("region crop: output size must be positive");
  // Clip the box to the image like numpy slicing does.
  const int x0 = std::clamp(box.x, 0, rgb.cols), y0 = std::clamp(box.y, 0, rgb.rows);
  const int x1 = std::clamp(box.x + box.w, x0, rgb.cols), y1 = std::clamp(box.y + box.h, y0, rgb.rows);
  const int w = x1 - x0, h = y1 - y0, side = std::max(w, h);
  if (w == 0 || h == 0) return cv::Mat::zeros(out_size, out_size, CV_8UC3);
  cv::Mat square = cv::Mat::zeros(side, side, CV_8UC3);
  const int ox = (side - w) / 2, oy = (side - h) / 2;  // pad_img: centred, floor
  for (int y = 0; y < h; ++y) {
    const cv::Vec3b* src = rgb.ptr<cv::Vec3b>(y0 + y) + x0;
    const uint8_t* m = mask.ptr<uint8_t>(y0 + y) + x0;
    cv::Vec3b* dst = square.ptr<cv::Vec3b>(oy + y) + ox;
    for (int x = 0; x < w; ++x) dst[x] = m[x] ? src[x] : cv::Vec3b(0, 0, 0);
  }
  if (side == out_size) return square;
  cv::Mat out;
  cv::resize(square, out, cv::Size(out_size, out_size), 0, 0, cv::INTER_LINEAR);
  return out;
}

cv::Mat langsplat_region_crop(const cv::Mat& rgb, const cv::Mat& mask, int out_size) {
  return langsplat_region_crop(rgb, mask, sam_mask_box(mask), out_size);
}

}  // namespace cls::clip
