#include "models/sam_amg/sam_amg_model.h"

#include <torch/torch.h>

#include "models/sam/sam_predictor.h"

namespace cls::amg {

void SamPredictorAmgModel::set_image(const uint8_t* rgb, int height, int width) {
  predictor_.set_image(rgb, height, width);
}

void SamPredictorAmgModel::predict_points(const std::vector<Point2d>& points_1024, std::vector<float>& mask_logits,
                                          std::vector<float>& iou_predictions) {
  const int64_t b = static_cast<int64_t>(points_1024.size());
  // float64 points, as the reference AMG hands NumPy coordinates to predict_torch.
  auto coords = torch::empty({b, 1, 2}, torch::kFloat64);
  auto* c = coords.data_ptr<double>();
  for (int64_t i = 0; i < b; ++i) c[2 * i] = points_1024[i][0], c[2 * i + 1] = points_1024[i][1];
  const auto labels = torch::ones({b, 1}, torch::kInt32);
  const torch::Device device = predictor_.device();
  torch::NoGradGuard no_grad;
  const sam::SamPrediction pred = predictor_.predict_batch(coords.to(device), labels.to(device), torch::Tensor(),
                                                          torch::Tensor(), /*multimask_output=*/true,
                                                          /*return_logits=*/true);
  const auto masks = pred.masks.to(torch::kCPU, torch::kFloat32).contiguous();
  const auto ious = pred.iou_predictions.to(torch::kCPU, torch::kFloat32).contiguous();
  mask_logits.assign(masks.data_ptr<float>(), masks.data_ptr<float>() + masks.numel());
  iou_predictions.assign(ious.data_ptr<float>(), ious.data_ptr<float>() + ious.numel());
}

}  // namespace cls::amg
