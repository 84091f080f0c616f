#include "models/sam_amg/sam_amg_model.h"

#include <torch/torch.h>

#include "core/error.h"
#include "models/sam/sam_predictor.h"

namespace cls::amg {

void SamPredictorAmgModel::set_image(const uint8_t* rgb, int height, int width) {
  low_res_logits_ = at::Tensor();
  predictor_.set_image(rgb, height, width);
}

void SamPredictorAmgModel::predict_points(const std::vector<Point2d>& points_1024,
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
                                                          /*return_logits=*/true, /*upsample=*/false);
  // One channel per mask: bilinear interpolation works plane by plane, so upsampling a subset gives
  // the same values as upsampling the whole [B, 3] batch.
  low_res_logits_ = pred.low_res_logits.flatten(0, 1).unsqueeze(1);
  const auto ious = pred.iou_predictions.to(torch::kCPU, torch::kFloat32).contiguous();
  iou_predictions.assign(ious.data_ptr<float>(), ious.data_ptr<float>() + ious.numel());
}

void SamPredictorAmgModel::upsample_masks(const std::vector<int64_t>& indices, std::vector<float>& mask_logits) {
  if (!low_res_logits_.defined()) throw Error("AMG: upsample_masks before predict_points");
  const int64_t n = low_res_logits_.size(0);
  for (int64_t i : indices)
    if (i < 0 || i >= n) throw Error("AMG: mask index " + std::to_string(i) + " outside the last batch of " + std::to_string(n));
  torch::NoGradGuard no_grad;
  const auto idx = torch::tensor(indices, torch::kInt64).to(low_res_logits_.device());
  const auto low = low_res_logits_.index_select(0, idx);
  const auto masks = predictor_.model()
                         ->postprocess_masks(low, predictor_.input_size(), predictor_.original_size())
                         .to(torch::kCPU, torch::kFloat32)
                         .contiguous();
  mask_logits.assign(masks.data_ptr<float>(), masks.data_ptr<float>() + masks.numel());
}

}  // namespace cls::amg
