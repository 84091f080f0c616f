#pragma once
// CLIP ViT (openai/CLIP clip/model.py: VisionTransformer, Transformer, ResidualAttentionBlock,
// CLIP.encode_image / encode_text / forward) as plain tensors and ATen ops.
// Weights use the reference state_dict names ("visual.transformer.resblocks.N.attn.in_proj_weight",
// "token_embedding.weight", ...); the Hugging Face layout is mapped to these by the weights module.
// Compute: fp32 on CPU; fp16/bf16 on CUDA (LayerNorm always in fp32, as the reference's LayerNorm).
#include <ATen/core/Tensor.h>
#include <c10/core/Device.h>

#include <map>
#include <string>
#include <vector>

#include "models/clip/clip_config.h"
#include "models/weights/weight_file.h"

namespace cls::clip {

// Activations captured for debugging/parity, named like the fixture files
// ("visual.ln_pre", "visual.transformer.resblocks.0.attn", "ln_final", "text_pooled", ...).
using ClipTrace = std::map<std::string, at::Tensor>;

struct ClipOptions {
  c10::Device device = c10::Device(c10::kCPU);
  at::ScalarType dtype = at::kFloat;  // kHalf / kBFloat16 only on CUDA
};

class ClipModel {
 public:
  // `weights` in any layout models/weights knows (OpenAI/OpenCLIP, Hugging Face, JIT archive):
  // names and shapes are checked against the architecture first (map_weights_strict: every
  // missing, unexpected, mis-shaped or non-float tensor in one cls::Error naming the file), then
  // each tensor is read and converted to the compute dtype/device (any float storage: f32/f16/bf16).
  ClipModel(const ClipConfig& config, const WeightFile& weights, const ClipOptions& options = {});
  // The same from a canonical name -> tensor map (tests, random weights); `source` names it in errors.
  ClipModel(const ClipConfig& config, const std::map<std::string, at::Tensor>& state,
            const ClipOptions& options = {}, const std::string& source = "CLIP weights");

  const ClipConfig& config() const { return config_; }
  const ClipOptions& options() const { return options_; }

  // images: [N, 3, R, R] normalised pixels (any float dtype/device) -> [N, embed_dim], unnormalised.
  at::Tensor encode_image(const at::Tensor& images, ClipTrace* trace = nullptr) const;
  // tokens: [B, context] int64 -> [B, embed_dim], unnormalised; pooled at argmax(tokens) (the
  // first end-of-text token).
  at::Tensor encode_text(const at::Tensor& tokens, ClipTrace* trace = nullptr) const;
  // CLIP.forward: exp(logit_scale) * normalise(img) @ normalise(txt)^T  -> [N, B] (fp32).
  at::Tensor logits_per_image(const at::Tensor& image_features, const at::Tensor& text_features) const;
  float logit_scale() const { return logit_scale_; }

 private:
  struct Block {
    at::Tensor ln_1_w, ln_1_b, in_proj_w, in_proj_b, out_proj_w, out_proj_b;
    at::Tensor ln_2_w, ln_2_b, c_fc_w, c_fc_b, c_proj_w, c_proj_b;
  };
  at::Tensor run_blocks(at::Tensor x, const std::vector<Block>& blocks, int heads, const at::Tensor& mask,
                        const std::string& prefix, ClipTrace* trace) const;

  ClipConfig config_;
  ClipOptions options_;
  // Vision tower.
  at::Tensor conv1_w_, class_embedding_, visual_pos_, ln_pre_w_, ln_pre_b_, ln_post_w_, ln_post_b_, visual_proj_;
  std::vector<Block> visual_blocks_;
  // Text tower.
  at::Tensor token_embedding_, text_pos_, ln_final_w_, ln_final_b_, text_projection_, causal_mask_;
  std::vector<Block> text_blocks_;
  float logit_scale_ = 0.f;  // exp(stored log scale)
};

// L2 normalisation along the last dimension (no epsilon, as the reference forward).
at::Tensor l2_normalize(const at::Tensor& features);

}  // namespace cls::clip
