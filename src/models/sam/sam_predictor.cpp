#include "models/sam/sam_predictor.h"

#include "core/error.h"

namespace cls::sam {

SamPredictor::SamPredictor(Sam model) : model_(std::move(model)) {
  transform_.target_length = model_->config.image_size;
  model_->eval();
}

torch::Device SamPredictor::device() const { return model_->prompt_encoder->no_mask_embed->weight.device(); }

torch::Tensor SamPredictor::transformed_input(const uint8_t* rgb, int height, int width) const {
  if (height <= 0 || width <= 0) throw Error("SAM: empty image");
  const auto [nh, nw] = transform_.target_shape(height, width);
  auto resized = resize_bilinear_pil(rgb, height, width, 3, nh, nw);
  auto t = torch::from_blob(resized.data(), {nh, nw, 3}, torch::kUInt8).permute({2, 0, 1}).contiguous().unsqueeze(0);
  return model_->preprocess(t.to(device()));
}

void SamPredictor::set_image(const uint8_t* rgb, int height, int width) {
  torch::NoGradGuard no_grad;
  const auto input = transformed_input(rgb, height, width);
  features_ = model_->image_encoder->forward(input);
  shared_image_ = {};
  original_hw_ = {height, width};
  input_hw_ = transform_.target_shape(height, width);
}

void SamPredictor::set_features(const torch::Tensor& features, std::pair<int, int> original_hw) {
  const int64_t side = model_->config.image_embedding_size();
  if (features.dim() != 4 || features.size(0) != 1 || features.size(1) != model_->config.prompt_embed_dim ||
      features.size(2) != side || features.size(3) != side)
    throw Error("SAM: image embedding has the wrong shape for this model");
  features_ = features.to(device(), torch::kFloat);
  shared_image_ = {};
  original_hw_ = original_hw;
  input_hw_ = transform_.target_shape(original_hw.first, original_hw.second);
}

void SamPredictor::reset_image() {
  features_ = torch::Tensor();
  shared_image_ = {};
  original_hw_ = input_hw_ = {0, 0};
}

void SamPredictor::share_image() {
  if (!is_image_set()) throw Error("SAM: set_image must be called before predict");
  if (shared_image_.defined()) return;
  torch::NoGradGuard no_grad;
  shared_image_ = model_->mask_decoder->share_image(features_, model_->prompt_encoder->get_dense_pe(),
                                                    model_->prompt_encoder->dense_without_mask(1));
}

SamPrediction SamPredictor::predict(const SamPrompt& prompt, bool multimask_output, bool return_logits) {
  if (!is_image_set()) throw Error("SAM: set_image must be called before predict");
  if (prompt.points.size() != prompt.labels.size()) throw Error("SAM: every prompt point needs a label");
  const auto f32 = torch::TensorOptions().dtype(torch::kFloat).device(device());
  torch::Tensor coords, labels, box, mask;
  if (!prompt.points.empty()) {
    std::vector<double> xy;
    for (const auto& p : prompt.points) xy.push_back(p[0]), xy.push_back(p[1]);
    transform_.apply_coords(xy.data(), prompt.points.size(), original_hw_);
    const int64_t n = int64_t(prompt.points.size());
    coords = torch::from_blob(xy.data(), {1, n, 2}, torch::kDouble).to(f32);
    labels = torch::tensor(std::vector<int32_t>(prompt.labels.begin(), prompt.labels.end()), torch::kInt).view({1, n}).to(device());
  }
  if (prompt.box) {
    std::array<double, 4> b = *prompt.box;
    transform_.apply_coords(b.data(), 2, original_hw_);
    box = torch::from_blob(b.data(), {1, 4}, torch::kDouble).to(f32);
  }
  if (prompt.mask_input.defined()) {
    const int64_t side = 4 * model_->config.image_embedding_size();
    if (prompt.mask_input.sizes() != torch::IntArrayRef{1, side, side})
      throw Error("SAM: mask_input must be 1 x " + std::to_string(side) + " x " + std::to_string(side) + " low-res logits");
    mask = prompt.mask_input.to(f32).unsqueeze(0);
  }
  auto out = predict_batch(coords, labels, box, mask, multimask_output, return_logits);
  return out;
}

SamPrediction SamPredictor::predict_batch(const torch::Tensor& point_coords, const torch::Tensor& point_labels,
                                          const torch::Tensor& boxes, const torch::Tensor& mask_input,
                                          bool multimask_output, bool return_logits, bool upsample) {
  if (!is_image_set()) throw Error("SAM: set_image must be called before predict");
  if (point_coords.defined() != point_labels.defined()) throw Error("SAM: point coordinates need labels");
  torch::NoGradGuard no_grad;
  // Prompts may come from the CPU while the model sits on a GPU.
  const auto dev = device();
  const auto on_device = [&](const torch::Tensor& t) { return t.defined() ? t.to(dev) : t; };
  const auto emb = model_->prompt_encoder->forward(on_device(point_coords), on_device(point_labels), on_device(boxes),
                                                   on_device(mask_input));
  // Without mask input, the image side (with its positional encoding) is made once per image.
  const bool no_mask = !mask_input.defined();
  if (no_mask) share_image();
  const auto dec = no_mask ? model_->mask_decoder->forward(features_, torch::Tensor(), emb.sparse, emb.dense,
                                                           multimask_output, &shared_image_)
                           : model_->mask_decoder->forward(features_, model_->prompt_encoder->get_dense_pe(),
                                                           emb.sparse, emb.dense, multimask_output);
  SamPrediction out;
  out.low_res_logits = dec.low_res_masks;
  out.iou_predictions = dec.iou_predictions;
  if (!upsample) return out;
  out.masks = model_->postprocess_masks(dec.low_res_masks, input_hw_, original_hw_);
  if (!return_logits) out.masks = out.masks > model_->config.mask_threshold;
  return out;
}

}  // namespace cls::sam
