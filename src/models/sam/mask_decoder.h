#pragma once
// SAM's mask decoder (segment_anything/modeling/mask_decoder.py): IoU and mask tokens through the
// two-way transformer, 4x upscaling of the image embedding, hypernetwork MLPs giving one mask per
// mask token, and the IoU prediction head.
#include <torch/torch.h>

#include "models/sam/sam_config.h"
#include "models/sam/sam_layers.h"
#include "models/sam/two_way_transformer.h"

namespace cls::sam {

struct MaskDecoderOutput {
  torch::Tensor low_res_masks;    // [B, C, 256, 256] logits; C = 3 (multimask) or 1
  torch::Tensor iou_predictions;  // [B, C]
};

struct MaskDecoderImpl : torch::nn::Module {
  explicit MaskDecoderImpl(const SamConfig& cfg);
  // image_embeddings [1 or B, C, 64, 64] (repeated per prompt when 1), image_pe [1, C, 64, 64],
  // sparse [B, N, C], dense [B, C, 64, 64]. `shared`: share_image of the same image embedding, for
  // prompts without mask input (dense = the no-mask embedding), or null; with it, image_pe is not
  // read (it may be undefined) and the image embedding gives only the grid size.
  MaskDecoderOutput forward(const torch::Tensor& image_embeddings, const torch::Tensor& image_pe,
                            const torch::Tensor& sparse_prompt_embeddings, const torch::Tensor& dense_prompt_embeddings,
                            bool multimask_output, const SharedImageSide* shared = nullptr);
  // All num_mask_tokens outputs (output 0 = single-mask, 1.. = multimask).
  MaskDecoderOutput predict_masks(const torch::Tensor& image_embeddings, const torch::Tensor& image_pe,
                                  const torch::Tensor& sparse_prompt_embeddings, const torch::Tensor& dense_prompt_embeddings,
                                  const SharedImageSide* shared = nullptr);
  // What every prompt without mask input shares for an image embedding [1, C, 64, 64]: the first
  // transformer block's projected image side (SharedImageSide). dense_no_mask: the prompt encoder's
  // dense embedding without a mask (any batch; its first entry is used).
  SharedImageSide share_image(const torch::Tensor& image_embeddings, const torch::Tensor& image_pe,
                              const torch::Tensor& dense_no_mask);
  // Low-res mask logits [b, M, 4h, 4w] from the transformer's keys [b, h*w, C] (channel-last) and
  // the hypernetworks' outputs [b, M, C/8]: output_upscaling, then a product per mask token.
  torch::Tensor masks_from_keys(const torch::Tensor& keys, const torch::Tensor& hyper_in, int64_t h, int64_t w);

  int64_t num_mask_tokens;
  TwoWayTransformer transformer{nullptr};
  torch::nn::Embedding iou_token{nullptr}, mask_tokens{nullptr};
  torch::nn::Sequential output_upscaling;
  torch::nn::ModuleList output_hypernetworks_mlps;
  MLP iou_prediction_head{nullptr};
};
TORCH_MODULE(MaskDecoder);

}  // namespace cls::sam
