#pragma once
// SAM's two-way transformer (segment_anything/modeling/transformer.py): tokens attend to the image
// embedding and the image embedding attends back to the tokens, in every block.
#include <torch/torch.h>

#include "models/sam/sam_layers.h"

namespace cls::sam {

// Attention with q/k/v projected down to dim / downsample_rate (transformer.py Attention).
struct DecoderAttentionImpl : torch::nn::Module {
  DecoderAttentionImpl(int64_t embedding_dim, int64_t num_heads, int64_t downsample_rate = 1);
  torch::Tensor forward(const torch::Tensor& q, const torch::Tensor& k, const torch::Tensor& v);
  int64_t num_heads;
  torch::nn::Linear q_proj{nullptr}, k_proj{nullptr}, v_proj{nullptr}, out_proj{nullptr};
};
TORCH_MODULE(DecoderAttention);

struct TwoWayAttentionBlockImpl : torch::nn::Module {
  TwoWayAttentionBlockImpl(int64_t embedding_dim, int64_t num_heads, int64_t mlp_dim, int64_t downsample_rate,
                           bool skip_first_layer_pe);
  // Updates queries [B,Nq,C] and keys [B,HW,C] in place of the reference's returned pair.
  void forward(torch::Tensor& queries, torch::Tensor& keys, const torch::Tensor& query_pe, const torch::Tensor& key_pe);
  bool skip_first_layer_pe;
  DecoderAttention self_attn{nullptr}, cross_attn_token_to_image{nullptr}, cross_attn_image_to_token{nullptr};
  torch::nn::LayerNorm norm1{nullptr}, norm2{nullptr}, norm3{nullptr}, norm4{nullptr};
  MLPBlock mlp{nullptr};
};
TORCH_MODULE(TwoWayAttentionBlock);

struct TwoWayTransformerImpl : torch::nn::Module {
  TwoWayTransformerImpl(int depth, int64_t embedding_dim, int64_t num_heads, int64_t mlp_dim, int64_t downsample_rate);
  // image_embedding, image_pe [B,C,h,w]; point_embedding [B,N,C] -> (queries [B,N,C], keys [B,hw,C]).
  std::pair<torch::Tensor, torch::Tensor> forward(const torch::Tensor& image_embedding, const torch::Tensor& image_pe,
                                                  const torch::Tensor& point_embedding);
  torch::nn::ModuleList layers;
  DecoderAttention final_attn_token_to_image{nullptr};
  torch::nn::LayerNorm norm_final_attn{nullptr};
};
TORCH_MODULE(TwoWayTransformer);

}  // namespace cls::sam
