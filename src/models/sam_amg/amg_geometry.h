#pragma once
// Geometry helpers of SAM's utils/amg.py and utils/transforms.py that the automatic mask
// generator needs: point grids, crop boxes, crop-edge test, the longest-side resize of prompts.
#include <array>
#include <cstdint>
#include <vector>

#include "models/sam_amg/binary_mask.h"

namespace cls::amg {

using Point2d = std::array<double, 2>;  // (x, y)

// build_point_grid: n x n points in [0, 1]^2, offset 1/(2n), x varies fastest (float64 linspace).
std::vector<Point2d> build_point_grid(int n_per_side);
// build_all_layer_point_grids: layer i uses int(n / scale_per_layer^i) points per side.
std::vector<std::vector<Point2d>> build_all_layer_point_grids(int n_per_side, int n_layers,
                                                              int scale_per_layer);

// XYXY crop box with exclusive maxima (image slicing [y0:y1, x0:x1]).
struct CropBox {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  int layer = 0;
  int width() const { return x1 - x0; }
  int height() const { return y1 - y0; }
};
// generate_crop_boxes: layer 0 is the whole image, layer i has 2^i x 2^i overlapping crops,
// enumerated x-major (for each x0, for each y0).
std::vector<CropBox> generate_crop_boxes(int image_h, int image_w, int n_layers, double overlap_ratio);

// is_box_near_crop_edge (atol 20, rtol 0): `box` in crop coordinates (inclusive maxima) is moved to
// the image frame and tested against the crop edges that are not also image edges [0, 0, W, H].
bool is_box_near_crop_edge(const BoxXyxy& box_in_crop, const CropBox& crop, int image_h, int image_w,
                           double atol = 20.0);

// calculate_stability_score for one mask of logits: #(logit > t + offset) / #(logit > t - offset)
// in float32 (0/0 = NaN, as the reference).
float stability_score(const float* logits, int height, int width, float mask_threshold, float offset);

}  // namespace cls::amg
