#include "models/sam/mask_decoder.h"

#include "core/error.h"

namespace cls::sam {

using torch::indexing::Slice;

namespace {

// ConvTranspose2d with kernel 2 and stride 2 (the kernel windows do not overlap) on channel-last
// input x [P, Cin]: each position gives its 2 x 2 outputs in one product, [P, 4 * Cout] with
// columns (i, j, out channel) for output (2y + i, 2x + j). The same sums as the convolution.
torch::Tensor conv_transpose_2x2(const torch::Tensor& x, const torch::nn::ConvTranspose2dImpl& conv) {
  const auto& w = conv.weight;  // [Cin, Cout, 2, 2]
  return torch::addmm(conv.bias.repeat({4}), x, w.permute({0, 2, 3, 1}).reshape({w.size(0), -1}));
}

}  // namespace

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
                                           const torch::Tensor& sparse, const torch::Tensor& dense, bool multimask_output,
                                           const SharedImageSide* shared) {
  auto out = predict_masks(image_embeddings, image_pe, sparse, dense, shared);
  const auto slice = multimask_output ? Slice(1, torch::indexing::None) : Slice(0, 1);
  out.low_res_masks = out.low_res_masks.index({Slice(), slice});
  out.iou_predictions = out.iou_predictions.index({Slice(), slice});
  return out;
}

SharedImageSide MaskDecoderImpl::share_image(const torch::Tensor& image_embeddings, const torch::Tensor& image_pe,
                                             const torch::Tensor& dense_no_mask) {
  return transformer->share_image(image_embeddings + dense_no_mask.narrow(0, 0, 1), image_pe);
}

MaskDecoderOutput MaskDecoderImpl::predict_masks(const torch::Tensor& image_embeddings, const torch::Tensor& image_pe,
                                                 const torch::Tensor& sparse, const torch::Tensor& dense,
                                                 const SharedImageSide* shared) {
  auto output_tokens = torch::cat({iou_token->weight, mask_tokens->weight}, 0);
  output_tokens = output_tokens.unsqueeze(0).expand({sparse.size(0), -1, -1});
  const auto tokens = torch::cat({output_tokens, sparse}, 1);
  const int64_t n = tokens.size(0);
  // One image embedding shared by all prompts (the reference's repeat_interleave). Without mask
  // inputs the dense embedding is one vector broadcast to every prompt (stride 0), so the prompts
  // share src too and the transformer takes it once; it is per prompt only after the first block.
  // With `shared`, the transformer takes src and its PE from there, made once per image.
  const bool one_src = image_embeddings.size(0) == 1 && (n == 1 || dense.stride(0) == 0);
  if (shared && !one_src) throw Error("SAM mask decoder: a shared image side needs one image and no mask input");
  torch::Tensor src, pos_src;
  if (!shared) {
    if (one_src && image_pe.size(0) == 1) {
      src = image_embeddings + dense.narrow(0, 0, 1);
      pos_src = image_pe;
    } else {
      src = image_embeddings.size(0) == n ? image_embeddings : torch::repeat_interleave(image_embeddings, n, 0);
      src = src + dense;
      pos_src = image_pe.size(0) == n ? image_pe : torch::repeat_interleave(image_pe, n, 0);
    }
  }
  const int64_t h = image_embeddings.size(2), w = image_embeddings.size(3);

  auto [hs, keys] = transformer(src, pos_src, tokens, shared);
  const auto iou_token_out = hs.index({Slice(), 0, Slice()});
  const auto mask_tokens_out = hs.index({Slice(), Slice(1, 1 + num_mask_tokens), Slice()});

  std::vector<torch::Tensor> hyper;
  for (int64_t i = 0; i < num_mask_tokens; ++i)
    hyper.push_back(output_hypernetworks_mlps[i]->as<MLP>()->forward(mask_tokens_out.index({Slice(), i, Slice()})));
  MaskDecoderOutput out;
  out.low_res_masks = masks_from_keys(keys, torch::stack(hyper, 1), h, w);
  out.iou_predictions = iou_prediction_head(iou_token_out);
  return out;
}

// output_upscaling (ConvT 2x2/2, LayerNorm2d, GELU, ConvT 2x2/2, GELU) in channel-last order, as the
// transformer leaves keys: every step is per position over channels, so no [C, H, W] copy of the
// embedding or of the 4x upscaled planes is made, LayerNorm2d is a LayerNorm over the last dimension,
// and only the masks themselves are put in image order.
torch::Tensor MaskDecoderImpl::masks_from_keys(const torch::Tensor& keys, const torch::Tensor& hyper_in, int64_t h,
                                               int64_t w) {
  const auto& conv1 = *output_upscaling[0]->as<torch::nn::ConvTranspose2dImpl>();
  const auto& norm = *output_upscaling[1]->as<LayerNorm2dImpl>();
  const auto& conv2 = *output_upscaling[3]->as<torch::nn::ConvTranspose2dImpl>();
  const int64_t b = keys.size(0), c = keys.size(2), c1 = norm.weight.size(0), c2 = conv2.weight.size(1);
  const int64_t masks = hyper_in.size(1);
  auto up = conv_transpose_2x2(keys.reshape({-1, c}), conv1).view({-1, c1});  // rows (y, x, i, j)
  up = torch::gelu(torch::layer_norm(up, {c1}, norm.weight, norm.bias, norm.eps));
  up = torch::gelu(conv_transpose_2x2(up, conv2)).view({b, h * w * 16, c2});  // rows (y, x, i, j, k, l)
  // Row (y, x, i, j, k, l) is mask pixel (4y + 2i + k, 4x + 2j + l).
  return torch::bmm(up, hyper_in.transpose(1, 2))
      .view({b, h, w, 2, 2, 2, 2, masks})
      .permute({0, 7, 1, 3, 5, 2, 4, 6})
      .reshape({b, masks, 4 * h, 4 * w});
}

}  // namespace cls::sam
