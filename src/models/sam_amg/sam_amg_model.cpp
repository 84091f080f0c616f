#include "models/sam_amg/sam_amg_model.h"

#include <torch/torch.h>

#include <algorithm>
#include <cstring>

#include "core/blas_threads.h"
#include "core/error.h"
#include "models/sam/sam_layers.h"
#include "models/sam/sam_predictor.h"

namespace cls::amg {

namespace {

// The reference decodes a whole points_per_batch (64) at once and upsamples every mask of it
// through a 1024 x 1024 plane: tensors of 64-600 MB per step. Slices whose largest tensor stays within
// budget (at most sam::kCpuBlockBytes in flight: below glibc's mmap ceiling, so freed blocks are reused).
int64_t slice_count(int64_t bytes_per_item, int64_t budget = sam::kCpuBlockBytes) {
  return std::max<int64_t>(1, budget / std::max<int64_t>(1, bytes_per_item));
}

}  // namespace

void SamPredictorAmgModel::set_image(const uint8_t* rgb, int height, int width) {
  low_res_logits_ = at::Tensor();
  predictor_.set_image(rgb, height, width);
}

int SamPredictorAmgModel::input_size() const { return predictor_.transform().target_length; }

void SamPredictorAmgModel::predict_points(const std::vector<Point2d>& points_input,
                                          std::vector<float>& iou_predictions) {
  if (!predictor_.is_image_set()) throw Error("AMG: predict_points before set_image");
  const int64_t b = static_cast<int64_t>(points_input.size());
  // float64 points, as the reference AMG hands NumPy coordinates to predict_torch.
  auto coords = torch::empty({b, 1, 2}, torch::kFloat64);
  auto* c = coords.data_ptr<double>();
  for (int64_t i = 0; i < b; ++i) c[2 * i] = points_input[i][0], c[2 * i + 1] = points_input[i][1];
  const torch::Device device = predictor_.device();
  coords = coords.to(device);
  const auto labels = torch::ones({b, 1}, torch::TensorOptions().dtype(torch::kInt32).device(device));
  torch::NoGradGuard no_grad;
  // The decoder's largest per-prompt tensor is the upscaled embedding: C/8 channels at 4x the
  // embedding side, i.e. 2 * C * side^2 floats.
  const auto& cfg = predictor_.model()->config;
  const int64_t side = cfg.image_embedding_size();
  // On the CPU the threads decode slices side by side: each within its share of kCpuBlockBytes, and at
  // least one slice per thread.
  const int64_t threads = at::get_num_threads();
  const int64_t step =
      device.is_cpu()
          ? std::min(slice_count(2 * cfg.prompt_embed_dim * side * side * 4, sam::kCpuBlockBytes / threads),
                     (b + threads - 1) / threads)
          : b;
  iou_predictions.clear();
  if (b == 0) {  // nothing to upsample from this batch
    low_res_logits_ = torch::empty({0, 1, 0, 0}, torch::TensorOptions().device(device));
    return;
  }
  const int64_t per = cfg.num_multimask_outputs;  // masks per prompt
  const int64_t low_side = 4 * side;
  const std::vector<int64_t> shape = {b * per, 1, low_side, low_side};
  const auto options = predictor_.features().options();  // the decoder's dtype and device
  if (!low_res_logits_.defined() || low_res_logits_.sizes() != shape || low_res_logits_.dtype() != options.dtype() ||
      low_res_logits_.device() != options.device())
    low_res_logits_ = torch::empty(shape, options);
  iou_predictions.assign(static_cast<size_t>(b * per), 0.f);
  const auto decode = [&](int64_t s, int64_t e) {
    const sam::SamPrediction pred =
        predictor_.predict_batch(coords.slice(0, s, e), labels.slice(0, s, e), torch::Tensor(), torch::Tensor(),
                                 /*multimask_output=*/true, /*return_logits=*/true, /*upsample=*/false);
    // One channel per mask: bilinear interpolation works plane by plane, so upsampling a subset gives
    // the same values as upsampling the whole [B, 3] batch. The buffer is kept across batches.
    const auto low = pred.low_res_logits.flatten(0, 1).unsqueeze(1);
    if (low.size(0) != (e - s) * per || low.size(2) != low_side || low.size(3) != low_side)
      throw Error("AMG: the SAM decoder returned masks of an unexpected shape");
    low_res_logits_.slice(0, s * per, e * per).copy_(low);
    const auto ious = pred.iou_predictions.to(torch::kCPU, torch::kFloat32).contiguous();
    std::copy(ious.data_ptr<float>(), ious.data_ptr<float>() + ious.numel(), iou_predictions.begin() + s * per);
  };
  if (!device.is_cpu()) return decode(0, b);
  // On the CPU the slices are split over LibTorch's threads (a run of them each), OpenBLAS held to the
  // calling thread: with the slices' small products handed to OpenBLAS one core decoded while
  // LibTorch's other threads spun (docs/benchmarks.md). The slices write disjoint parts of the outputs.
  predictor_.share_image();
  const ScopedBlasThreads blas(1);  // see core/blas_threads.h
  const int64_t slices = (b + step - 1) / step;
  at::parallel_for(0, slices, 1, [&](int64_t first, int64_t last) {
    for (int64_t i = first; i < last; ++i) decode(i * step, std::min(b, (i + 1) * step));
  });
}

void SamPredictorAmgModel::upsample_masks(const std::vector<int64_t>& indices, std::vector<float>& mask_logits) {
  if (!low_res_logits_.defined()) throw Error("AMG: upsample_masks before predict_points");
  const int64_t n = low_res_logits_.size(0);
  for (int64_t i : indices)
    if (i < 0 || i >= n) throw Error("AMG: mask index " + std::to_string(i) + " outside the last batch of " + std::to_string(n));
  torch::NoGradGuard no_grad;
  const auto [h, w] = predictor_.original_size();
  const size_t plane = static_cast<size_t>(h) * w;
  mask_logits.resize(indices.size() * plane);
  // postprocess_masks passes each mask through an image_size^2 plane.
  const int64_t side = predictor_.model()->config.image_size;
  const int64_t count = static_cast<int64_t>(indices.size());
  const int64_t step = low_res_logits_.device().is_cpu() ? slice_count(side * side * 4) : count;
  for (int64_t s = 0; s < count; s += step) {
    const int64_t e = std::min(count, s + step);
    const std::vector<int64_t> part(indices.begin() + s, indices.begin() + e);
    const auto idx = torch::tensor(part, torch::kInt64).to(low_res_logits_.device());
    const auto masks = predictor_.model()
                           ->postprocess_masks(low_res_logits_.index_select(0, idx), predictor_.input_size(),
                                               predictor_.original_size())
                           .to(torch::kCPU, torch::kFloat32)
                           .contiguous();
    std::memcpy(mask_logits.data() + s * plane, masks.data_ptr<float>(), masks.numel() * sizeof(float));
  }
}

}  // namespace cls::amg
