#pragma once
// ResizeLongestSide (segment_anything/utils/transforms.py): the longest image side becomes
// target_length, images are resampled exactly like Pillow's BILINEAR resize on uint8 (what the
// reference does through torchvision's to_pil_image + resize), coordinates are scaled in float64.
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace cls::sam {

// get_preprocess_shape: scale = long / max(h, w); (int(h * scale + 0.5), int(w * scale + 0.5)).
std::pair<int, int> preprocess_shape(int old_h, int old_w, int long_side_length);

// Pillow ImagingResample with the bilinear (triangle) filter on an 8-bit H x W x C image:
// horizontal pass then vertical pass, each rounded to uint8, 22-bit fixed-point coefficients;
// down-scaling widens the filter support (anti-aliasing).
std::vector<uint8_t> resize_bilinear_pil(const uint8_t* src, int h, int w, int channels, int out_h, int out_w);

// apply_coords on one (x, y): x * (new_w / old_w), y * (new_h / old_h) for the image of size old_hw.
struct ResizeLongestSide {
  int target_length = 1024;
  std::pair<int, int> target_shape(int h, int w) const { return preprocess_shape(h, w, target_length); }
  // In-place on interleaved x, y pairs (boxes are two corners: x0, y0, x1, y1).
  void apply_coords(double* xy, size_t n_points, std::pair<int, int> original_hw) const;
};

}  // namespace cls::sam
