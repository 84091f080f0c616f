#pragma once
// SAM's ViT image encoder (segment_anything/modeling/image_encoder.py ImageEncoderViT): patch
// embedding, absolute position embedding, pre-norm transformer blocks with 14x14 windowed attention
// except in the global blocks, decomposed relative positions, and the conv/LayerNorm2d neck.
#include <torch/torch.h>

#include <utility>

#include "models/sam/sam_config.h"
#include "models/sam/sam_layers.h"

namespace cls::sam {

// window_partition: [B,H,W,C] -> [B*nW, ws, ws, C], zero-padding H and W up to multiples of ws.
// Returns the windows and the padded (Hp, Wp).
std::pair<torch::Tensor, std::pair<int64_t, int64_t>> window_partition(const torch::Tensor& x, int64_t window_size);
// window_unpartition: the inverse, cropping the padding away: -> [B, H, W, C].
torch::Tensor window_unpartition(const torch::Tensor& windows, int64_t window_size, std::pair<int64_t, int64_t> pad_hw,
                                 std::pair<int64_t, int64_t> hw);
// get_rel_pos: the [q_size, k_size, C] table of relative-position embeddings, rel_pos linearly
// interpolated (align_corners=False) when its length differs from 2*max(q,k)-1.
torch::Tensor get_rel_pos(int64_t q_size, int64_t k_size, const torch::Tensor& rel_pos);
// add_decomposed_rel_pos (MViTv2): attn[b,(qh,qw),(kh,kw)] += q.Rh[qh,kh] + q.Rw[qw,kw], with q unscaled.
// Rh [q_h, k_h, C] and Rw [q_w, k_w, C] are get_rel_pos tables; q [B, q_h*q_w, C] may be a band of whole
// query rows when Rh is sliced to the same rows.
torch::Tensor add_decomposed_rel_pos(const torch::Tensor& attn, const torch::Tensor& q, const torch::Tensor& Rh,
                                     const torch::Tensor& Rw, std::pair<int64_t, int64_t> q_hw,
                                     std::pair<int64_t, int64_t> k_hw);

// Multi-head attention over a [B,H,W,C] token grid with optional decomposed relative positions.
// Computed in bands of heads and query rows so that no attention matrix exceeds a few MB (SAM's
// global blocks would otherwise make several [heads, 4096, 4096] tensors, 805 MB each for ViT-B):
// each row's softmax is its own, so the result is the reference's.
struct ViTAttentionImpl : torch::nn::Module {
  ViTAttentionImpl(int64_t dim, int64_t num_heads, bool qkv_bias, bool use_rel_pos, std::pair<int64_t, int64_t> input_size);
  torch::Tensor forward(const torch::Tensor& x);
  int64_t num_heads;
  double scale;
  bool use_rel_pos;
  torch::nn::Linear qkv{nullptr}, proj{nullptr};
  torch::Tensor rel_pos_h, rel_pos_w;
};
TORCH_MODULE(ViTAttention);

// One pre-norm block; window_size 0 = global attention.
struct ViTBlockImpl : torch::nn::Module {
  ViTBlockImpl(const SamConfig& cfg, int64_t window_size);
  torch::Tensor forward(const torch::Tensor& x);
  int64_t window_size;
  torch::nn::LayerNorm norm1{nullptr}, norm2{nullptr};
  ViTAttention attn{nullptr};
  MLPBlock mlp{nullptr};
};
TORCH_MODULE(ViTBlock);

struct PatchEmbedImpl : torch::nn::Module {
  PatchEmbedImpl(int64_t patch_size, int64_t in_chans, int64_t embed_dim);
  torch::Tensor forward(const torch::Tensor& x);  // [B,3,H,W] -> [B,H/16,W/16,C]
  torch::nn::Conv2d proj{nullptr};
};
TORCH_MODULE(PatchEmbed);

struct ImageEncoderViTImpl : torch::nn::Module {
  explicit ImageEncoderViTImpl(const SamConfig& cfg);
  // [B,3,1024,1024] normalised and padded -> [B,out_chans,64,64]
  torch::Tensor forward(const torch::Tensor& x);
  PatchEmbed patch_embed{nullptr};
  torch::Tensor pos_embed;
  torch::nn::ModuleList blocks;
  torch::nn::Sequential neck;
};
TORCH_MODULE(ImageEncoderViT);

}  // namespace cls::sam
