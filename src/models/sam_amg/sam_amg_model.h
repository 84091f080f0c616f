#pragma once
// The AmgModel of a real SAM: SamPredictor.set_image and predict_torch (predict_batch) with one
// foreground point per prompt, multimask output; the low-res logits are kept and only the masks the
// generator asks for are upsampled to the crop size (Sam.postprocess_masks).
#include <ATen/core/Tensor.h>

#include "models/sam_amg/automatic_mask_generator.h"

namespace cls::sam {
class SamPredictor;
}

namespace cls::amg {

class SamPredictorAmgModel : public AmgModel {
 public:
  explicit SamPredictorAmgModel(sam::SamPredictor& predictor) : predictor_(predictor) {}
  void set_image(const uint8_t* rgb, int height, int width) override;
  int input_size() const override;
  void predict_points(const std::vector<Point2d>& points_input, std::vector<float>& iou_predictions) override;
  void upsample_masks(const std::vector<int64_t>& indices, std::vector<float>& mask_logits) override;

 private:
  sam::SamPredictor& predictor_;
  at::Tensor low_res_logits_;  // [B * 3, 1, 256, 256] of the last predict_points, on the model's device
};

}  // namespace cls::amg
