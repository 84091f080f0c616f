#include "models/sam_amg/amg_geometry.h"

#include <cmath>
#include <limits>

#include "core/error.h"

namespace cls::amg {

std::vector<Point2d> build_point_grid(int n) {
  if (n <= 0) throw Error("points_per_side must be positive");
  const double offset = 1.0 / (2.0 * n);
  // numpy linspace(start, stop, n): start + i * step, step = (stop - start) / (n - 1); last = stop.
  std::vector<double> side(n);
  const double start = offset, stop = 1.0 - offset;
  if (n == 1) {
    side[0] = start;
  } else {
    const double step = (stop - start) / (n - 1);
    for (int i = 0; i < n; ++i) side[i] = start + i * step;
    side[n - 1] = stop;
  }
  std::vector<Point2d> points;
  points.reserve(static_cast<size_t>(n) * n);
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) points.push_back({side[x], side[y]});
  return points;
}

std::vector<std::vector<Point2d>> build_all_layer_point_grids(int n_per_side, int n_layers,
                                                              int scale_per_layer) {
  if (scale_per_layer <= 0) throw Error("crop_n_points_downscale_factor must be positive");
  std::vector<std::vector<Point2d>> grids;
  for (int i = 0; i <= n_layers; ++i) {
    const int n = static_cast<int>(n_per_side / std::pow(static_cast<double>(scale_per_layer), i));
    grids.push_back(build_point_grid(n));
  }
  return grids;
}

std::vector<CropBox> generate_crop_boxes(int im_h, int im_w, int n_layers, double overlap_ratio) {
  std::vector<CropBox> boxes;
  boxes.push_back({0, 0, im_w, im_h, 0});
  const int short_side = std::min(im_h, im_w);
  for (int layer = 1; layer <= n_layers; ++layer) {
    const int per_side = 1 << layer;
    const int overlap = static_cast<int>(overlap_ratio * short_side * (2.0 / per_side));
    const auto crop_len = [&](int orig_len) {
      return static_cast<int>(std::ceil(static_cast<double>(overlap * (per_side - 1) + orig_len) / per_side));
    };
    const int crop_w = crop_len(im_w), crop_h = crop_len(im_h);
    for (int i = 0; i < per_side; ++i) {
      const int x0 = (crop_w - overlap) * i;
      for (int j = 0; j < per_side; ++j) {
        const int y0 = (crop_h - overlap) * j;
        boxes.push_back({x0, y0, std::min(x0 + crop_w, im_w), std::min(y0 + crop_h, im_h), layer});
      }
    }
  }
  return boxes;
}

bool is_box_near_crop_edge(const BoxXyxy& b, const CropBox& crop, int im_h, int im_w, double atol) {
  const double box[4] = {double(b.x0 + crop.x0), double(b.y0 + crop.y0), double(b.x1 + crop.x0),
                         double(b.y1 + crop.y0)};
  const double crop_edges[4] = {double(crop.x0), double(crop.y0), double(crop.x1), double(crop.y1)};
  const double image_edges[4] = {0.0, 0.0, double(im_w), double(im_h)};
  for (int k = 0; k < 4; ++k) {
    const bool near_crop = std::abs(box[k] - crop_edges[k]) <= atol;
    const bool near_image = std::abs(box[k] - image_edges[k]) <= atol;
    if (near_crop && !near_image) return true;
  }
  return false;
}

float stability_score(const float* logits, int height, int width, float threshold, float offset) {
  const float hi = threshold + offset, lo = threshold - offset;
  int64_t inter = 0, uni = 0;
  const size_t n = static_cast<size_t>(height) * width;
  for (size_t i = 0; i < n; ++i) {
    inter += logits[i] > hi;
    uni += logits[i] > lo;
  }
  // int32 / int32 true division in torch gives float32.
  return static_cast<float>(inter) / static_cast<float>(uni);
}

}  // namespace cls::amg
