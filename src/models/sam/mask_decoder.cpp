#include "models/sam/mask_decoder.h"

namespace cls::sam {

using torch::indexing::Slice;

MaskDecoderImpl::MaskDecoderImpl(const SamConfig& cfg) : num_mask_tokens(cfg.num_multimask_outputs + 1) {
  const int64_t dim = cfg.prompt_embed_dim;
  transformer = register_module("transformer", TwoWayTransformer(cfg.decoder_depth, dim, cfg.decoder_num_heads,
                                                                 cfg.decoder_mlp_dim, cfg.attention_downsample_rate));
  iou_token = register_module("iou_token", torch::nn::Embedding(1, dim));
  mask_tokens = register_module("mask_tokens", torch::nn::Embedding(num_mask_tokens, dim));
  using torch::nn::ConvTranspose2dOptions;
  output_upscaling->push_back(torch::nn::ConvTranspose2d(ConvTranspose2dOptions(dim, dim / 4, 2).stride(2)));
  output_upscaling->push_back(LayerNorm2d(dim / 4));
  output_upscaling->push_back(torch::nn::GELU());
  output_upscaling->push_back(torch::nn::ConvTranspose2d(ConvTranspose2dOptions(dim / 4, dim / 8, 2).stride(2)));
  output_upscaling->push_back(torch::nn::GELU());
  register_module("output_upscaling", output_upscaling);
  for (int64_t i = 0; i < num_mask_tokens; ++i) output_hypernetworks_mlps->push_back(MLP(dim, dim, dim / 8, 3));
  register_module("output_hypernetworks_mlps", output_hypernetworks_mlps);
  iou_prediction_head = register_module("iou_prediction_head", MLP(dim, cfg.iou_head_hidden_dim, num_mask_tokens, cfg.iou_head_depth));
}

MaskDecoderOutput MaskDecoderImpl::forward(const torch::Tensor& image_embeddings, const torch::Tensor& image_pe,
                                           const torch::Tensor& sparse, const torch::Tensor& dense, bool multimask_output) {
  auto out = predict_masks(image_embeddings, image_pe, sparse, dense);
  const auto slice = multimask_output ? Slice(1, torch::indexing::None) : Slice(0, 1);
  out.low_res_masks = out.low_res_masks.index({Slice(), slice});
  out.iou_predictions = out.iou_predictions.index({Slice(), slice});
  return out;
}

MaskDecoderOutput MaskDecoderImpl::predict_masks(const torch::Tensor& image_embeddings, const torch::Tensor& image_pe,
                                                 const torch::Tensor& sparse, const torch::Tensor& dense) {
  auto output_tokens = torch::cat({iou_token->weight, mask_tokens->weight}, 0);
  output_tokens = output_tokens.unsqueeze(0).expand({sparse.size(0), -1, -1});
  const auto tokens = torch::cat({output_tokens, sparse}, 1);
  const int64_t n = tokens.size(0);
  // One image embedding shared by all prompts (the reference's repeat_interleave). Without mask
  // inputs the dense embedding is one vector broadcast to every prompt (stride 0), so the prompts
  // share src too and the transformer takes it once; it is per prompt only after the first block.
  torch::Tensor src, pos_src;
  if (image_embeddings.size(0) == 1 && image_pe.size(0) == 1 && (n == 1 || dense.stride(0) == 0)) {
    src = image_embeddings + dense.narrow(0, 0, 1);
    pos_src = image_pe;
  } else {
    src = image_embeddings.size(0) == n ? image_embeddings : torch::repeat_interleave(image_embeddings, n, 0);
    src = src + dense;
    pos_src = image_pe.size(0) == n ? image_pe : torch::repeat_interleave(image_pe, n, 0);
  }
  const int64_t c = src.size(1), h = src.size(2), w = src.size(3);

  auto [hs, keys] = transformer(src, pos_src, tokens);
  const int64_t b = keys.size(0);
  const auto iou_token_out = hs.index({Slice(), 0, Slice()});
  const auto mask_tokens_out = hs.index({Slice(), Slice(1, 1 + num_mask_tokens), Slice()});

  const auto upscaled = output_upscaling->forward(keys.transpose(1, 2).reshape({b, c, h, w}));
  std::vector<torch::Tensor> hyper;
  for (int64_t i = 0; i < num_mask_tokens; ++i)
    hyper.push_back(output_hypernetworks_mlps[i]->as<MLP>()->forward(mask_tokens_out.index({Slice(), i, Slice()})));
  const auto hyper_in = torch::stack(hyper, 1);
  const int64_t ub = upscaled.size(0), uc = upscaled.size(1), uh = upscaled.size(2), uw = upscaled.size(3);
  MaskDecoderOutput out;
  out.low_res_masks = torch::matmul(hyper_in, upscaled.view({ub, uc, uh * uw})).view({ub, -1, uh, uw});
  out.iou_predictions = iou_prediction_head(iou_token_out);
  return out;
}

}  // namespace cls::sam
