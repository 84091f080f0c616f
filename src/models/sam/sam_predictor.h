#pragma once
// SamPredictor (segment_anything/predictor.py): encode an image once (set_image), then decode masks
// for point / box / mask prompts given in original-image pixels (predict), or for a batch of prompts
// already in the model-input frame, img_size (1024 for the official models) on the longest side
// (predict_batch = the reference's predict_torch, used by the automatic mask generator).
#include <torch/torch.h>

#include <array>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "models/sam/resize_longest_side.h"
#include "models/sam/sam_model.h"

namespace cls::sam {

// One prompt set in original-image pixel coordinates.
struct SamPrompt {
  std::vector<std::array<double, 2>> points;  // (x, y)
  std::vector<int> labels;                    // 1 foreground, 0 background
  std::optional<std::array<double, 4>> box;   // XYXY
  torch::Tensor mask_input;                   // [1, 256, 256] low-res logits, or undefined
};

struct SamPrediction {
  torch::Tensor masks;            // [B, C, H, W] logits (return_logits) or bool (logit > mask_threshold);
                                  // undefined when predict_batch did not upsample
  torch::Tensor iou_predictions;  // [B, C]
  torch::Tensor low_res_logits;   // [B, C, 256, 256]
};

class SamPredictor {
 public:
  explicit SamPredictor(Sam model);

  // H x W x 3 RGB uint8, row-major. Resizes (Pillow-exact bilinear), normalises, pads and encodes.
  void set_image(const uint8_t* rgb, int height, int width);
  // Use a precomputed embedding [1, C, 64, 64] for an image of original_hw (no encoder run).
  void set_features(const torch::Tensor& features, std::pair<int, int> original_hw);
  void reset_image();

  // The exact tensor entering the image encoder for an image: [1, 3, 1024, 1024] float32.
  torch::Tensor transformed_input(const uint8_t* rgb, int height, int width) const;

  // predict(): coordinates are transformed in float64, then become float32 tensors as in the reference.
  SamPrediction predict(const SamPrompt& prompt, bool multimask_output = true, bool return_logits = false);

  // predict_torch(): point_coords [B, N, 2] (model-input frame, float32 or float64 — arithmetic up to the
  // positional encoding happens in that dtype, as in the reference), point_labels [B, N] int,
  // boxes [B, 4], mask_input [B, 1, 256, 256]; undefined tensors = absent. upsample = false leaves
  // masks undefined (no postprocess_masks), for callers that upsample only the masks they keep.
  SamPrediction predict_batch(const torch::Tensor& point_coords, const torch::Tensor& point_labels,
                              const torch::Tensor& boxes, const torch::Tensor& mask_input, bool multimask_output = true,
                              bool return_logits = false, bool upsample = true);

  // Makes the decoder's image side for prompts without mask input now (predict_batch makes it at the
  // first such prompt). After it, predict_batch without mask input only reads the predictor, so
  // several threads may call it at once.
  void share_image();

  bool is_image_set() const { return features_.defined(); }
  const torch::Tensor& features() const { return features_; }
  std::pair<int, int> original_size() const { return original_hw_; }
  std::pair<int, int> input_size() const { return input_hw_; }
  const ResizeLongestSide& transform() const { return transform_; }
  Sam& model() { return model_; }
  torch::Device device() const;

 private:
  Sam model_;
  ResizeLongestSide transform_;
  torch::Tensor features_;
  std::pair<int, int> original_hw_{0, 0}, input_hw_{0, 0};
  // The decoder's image side for prompts without mask input, made by share_image (MaskDecoderImpl::share_image).
  SharedImageSide shared_image_;
};

}  // namespace cls::sam
