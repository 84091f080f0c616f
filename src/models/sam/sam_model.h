#pragma once
// The Segment Anything model (segment_anything/modeling/sam.py Sam): image encoder, prompt encoder
// and mask decoder under the official state_dict names, input normalisation/padding
// (Sam.preprocess) and mask post-processing (Sam.postprocess_masks).
#include <torch/torch.h>

#include <map>
#include <string>
#include <utility>

#include "models/sam/image_encoder.h"
#include "models/sam/mask_decoder.h"
#include "models/sam/prompt_encoder.h"
#include "models/sam/sam_config.h"
#include "models/weights/sam_weights.h"
#include "models/weights/weight_file.h"

namespace cls::sam {

struct SamImpl : torch::nn::Module {
  explicit SamImpl(const SamConfig& cfg);

  // [B,3,h,w] RGB 0..255 (any dtype) -> normalised (x - mean) / std in float32, zero-padded
  // bottom/right to img_size x img_size.
  torch::Tensor preprocess(const torch::Tensor& x) const;
  // Low-res logits [B,C,256,256] -> [B,C,H,W]: bilinear to img_size, crop to the resized input
  // (input_hw), bilinear to the original size (align_corners=False both times).
  torch::Tensor postprocess_masks(const torch::Tensor& masks, std::pair<int64_t, int64_t> input_hw,
                                  std::pair<int64_t, int64_t> original_hw) const;

  SamConfig config;
  ImageEncoderViT image_encoder{nullptr};
  PromptEncoder prompt_encoder{nullptr};
  MaskDecoder mask_decoder{nullptr};
  torch::Tensor pixel_mean, pixel_std;  // [3,1,1], not part of the state_dict
};
TORCH_MODULE(Sam);

// Every parameter and persistent buffer of the model by its official state_dict name.
std::map<std::string, torch::Tensor> sam_state_names(SamImpl& model);

// Copies `weights` (official names, e.g. "image_encoder.blocks.0.attn.qkv.weight") into the model.
// All problems are collected from the header first (missing keys, unexpected keys, shape
// mismatches, non-floating dtypes) and reported in one cls::Error naming the file and the tensors;
// nothing is copied then. Floating tensors of other precisions (f16, bf16, f64) are converted.
void load_sam_weights(SamImpl& model, const WeightFile& weights);

// Builds the model of `cfg` and loads a checkpoint in any supported container and key layout
// (official or Hugging Face names; load_sam_checkpoint), in eval mode.
Sam load_sam(const std::string& path, const SamConfig& cfg);

}  // namespace cls::sam
