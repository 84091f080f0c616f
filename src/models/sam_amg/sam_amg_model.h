#pragma once
// The AmgModel of a real SAM: SamPredictor.set_image and predict_torch (predict_batch) with one
// foreground point per prompt, multimask output, logits at the crop size.
#include "models/sam_amg/automatic_mask_generator.h"

namespace cls::sam {
class SamPredictor;
}

namespace cls::amg {

class SamPredictorAmgModel : public AmgModel {
 public:
  explicit SamPredictorAmgModel(sam::SamPredictor& predictor) : predictor_(predictor) {}
  void set_image(const uint8_t* rgb, int height, int width) override;
  void predict_points(const std::vector<Point2d>& points_1024, std::vector<float>& mask_logits,
                      std::vector<float>& iou_predictions) override;

 private:
  sam::SamPredictor& predictor_;
};

}  // namespace cls::amg
