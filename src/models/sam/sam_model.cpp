#include "models/sam/sam_model.h"

#include <algorithm>
#include <vector>

#include "core/error.h"

namespace cls::sam {

namespace F = torch::nn::functional;
using torch::indexing::Slice;

SamImpl::SamImpl(const SamConfig& cfg) : config(cfg) {
  image_encoder = register_module("image_encoder", ImageEncoderViT(cfg));
  prompt_encoder = register_module("prompt_encoder", PromptEncoder(cfg));
  mask_decoder = register_module("mask_decoder", MaskDecoder(cfg));
  // Non-persistent in the reference: kept out of the module's buffers so the state_dict matches.
  pixel_mean = torch::tensor({cfg.pixel_mean[0], cfg.pixel_mean[1], cfg.pixel_mean[2]}).view({-1, 1, 1});
  pixel_std = torch::tensor({cfg.pixel_std[0], cfg.pixel_std[1], cfg.pixel_std[2]}).view({-1, 1, 1});
}

torch::Tensor SamImpl::preprocess(const torch::Tensor& x) const {
  const auto dev = x.device();
  auto y = (x.to(torch::kFloat) - pixel_mean.to(dev)) / pixel_std.to(dev);
  const int64_t h = y.size(2), w = y.size(3);
  const int64_t padh = config.image_size - h, padw = config.image_size - w;
  return F::pad(y, F::PadFuncOptions({0, padw, 0, padh}));
}

torch::Tensor SamImpl::postprocess_masks(const torch::Tensor& masks, std::pair<int64_t, int64_t> input_hw,
                                         std::pair<int64_t, int64_t> original_hw) const {
  auto opts = F::InterpolateFuncOptions().mode(torch::kBilinear).align_corners(false);
  auto m = F::interpolate(masks, opts.size(std::vector<int64_t>{config.image_size, config.image_size}));
  m = m.index({"...", Slice(0, input_hw.first), Slice(0, input_hw.second)});
  return F::interpolate(m, opts.size(std::vector<int64_t>{original_hw.first, original_hw.second}));
}

std::map<std::string, torch::Tensor> sam_state_names(SamImpl& model) {
  std::map<std::string, torch::Tensor> names;
  for (const auto& p : model.named_parameters(/*recurse=*/true)) names[p.key()] = p.value();
  for (const auto& b : model.named_buffers(/*recurse=*/true)) names[b.key()] = b.value();
  return names;
}

void load_sam_weights(SamImpl& model, const WeightFile& weights) {
  auto targets = sam_state_names(model);
  std::vector<std::string> problems;
  for (const auto& [name, target] : targets) {
    if (!weights.contains(name)) {
      problems.push_back("missing tensor " + name);
      continue;
    }
    const TensorInfo& info = weights.info(name);
    if (!at::isFloatingType(info.dtype)) problems.push_back("tensor " + name + " is not floating point");
    else if (info.shape != target.sizes().vec())
      problems.push_back("tensor " + name + " has shape " + shape_string(info.shape) + ", expected " +
                         shape_string(target.sizes().vec()));
  }
  for (const auto& name : weights.names())
    if (!targets.count(name)) problems.push_back("unexpected tensor " + name);
  if (!problems.empty()) {
    std::string msg = "SAM weights do not match the model (embed_dim " + std::to_string(model.config.encoder_embed_dim) +
                      ", depth " + std::to_string(model.config.encoder_depth) + "): ";
    const size_t shown = std::min<size_t>(problems.size(), 12);
    for (size_t i = 0; i < shown; ++i) msg += (i ? "; " : "") + problems[i];
    if (shown < problems.size()) msg += "; and " + std::to_string(problems.size() - shown) + " more";
    fail(weights.source(), msg);
  }
  torch::NoGradGuard no_grad;
  for (auto& [name, target] : targets) target.copy_(weights.get(name, target.scalar_type()));
}

Sam load_sam(const std::string& path, const SamConfig& cfg) {
  Sam model(cfg);
  load_sam_weights(*model, load_sam_checkpoint(path, cfg));
  model->eval();
  return model;
}

}  // namespace cls::sam
