#pragma once
// SAM's two-way transformer (segment_anything/modeling/transformer.py): tokens attend to the image
// embedding and the image embedding attends back to the tokens, in every block.
#include <torch/torch.h>

#include "models/sam/sam_layers.h"

namespace cls::sam {

// What every prompt without mask input shares of an image: the first block's projected image side,
// each [N, C / downsample_rate], and the image and its positional encoding as the transformer takes
// them. A predictor computes it once per image (TwoWayTransformerImpl::share_image), and each prompt
// only attends.
// Per prompt the first block's scores and token values then cost N x C/r x T multiply-adds instead
// of the folded N x C x heads x T (16x fewer for ViT-B).
struct SharedImageSide {
  torch::Tensor key, value;  // tokens to image: k_proj(src + pe), v_proj(src)
  torch::Tensor query;       // image to tokens: q_proj(src + pe)
  torch::Tensor image, pe;   // src and its positional encoding, contiguous [N, C]
  bool defined() const { return key.defined(); }
};

// Attention with q/k/v projected down to dim / downsample_rate (transformer.py Attention).
struct DecoderAttentionImpl : torch::nn::Module {
  DecoderAttentionImpl(int64_t embedding_dim, int64_t num_heads, int64_t downsample_rate = 1);
  // The reference's order: project q, k and v, attend, project out. q [B,Nq,C], k and v [B,Nk,C].
  torch::Tensor forward(const torch::Tensor& q, const torch::Tensor& k, const torch::Tensor& v);
  // The same attention where one side is a handful of tokens (T, about 7) and the other the image
  // embedding (N = 4096 positions). The image-side projections are folded into the tokens' per head:
  // scores q.(W x + b) = (W^T q).x + q.b, and sum_n p_n (W_v x_n + b_v) = W_v (sum_n p_n x_n) + b_v,
  // likewise out_proj through the values of image_to_tokens. So nothing of size N x C is projected:
  // for ViT-B the transformer does about a third of the multiply-adds of the reference's order. The
  // image side may have batch 1 for B prompts that share it (no mask input); it is never copied.
  // tokens_to_image: q [B,T,C] tokens; k, v [B or 1, N, C] image -> [B,T,C].
  torch::Tensor tokens_to_image(const torch::Tensor& q, const torch::Tensor& k, const torch::Tensor& v);
  // image_to_tokens: q [B or 1, N, C] image; k, v [B,T,C] tokens -> [B,N,C]. With `into` (a
  // contiguous [B,N,C] tensor the caller owns, e.g. the block's residual) the result is added to it
  // in place and returned: no [B,N,C] pass for the bias or for the residual sum.
  torch::Tensor image_to_tokens(const torch::Tensor& q, const torch::Tensor& k, const torch::Tensor& v,
                                torch::Tensor into = {});
  // The same two with the image side already projected for every prompt (SharedImageSide): the
  // reference's order. tokens_to_projected_image: q [B,T,C]; k, v [N, C/r] -> [B,T,C].
  torch::Tensor tokens_to_projected_image(const torch::Tensor& q, const torch::Tensor& k, const torch::Tensor& v);
  // projected_image_to_tokens: q [N, C/r]; k, v [B,T,C] tokens -> [B,N,C] (out_proj folded as above).
  torch::Tensor projected_image_to_tokens(const torch::Tensor& q, const torch::Tensor& k, const torch::Tensor& v,
                                          torch::Tensor into = {});
  // The tokens' values v [B,h,T,dh] through out_proj, per head: [B, h*T, C] (image_to_tokens).
  torch::Tensor values_through_out_proj(const torch::Tensor& v) const;
  // The image-to-tokens attention from its scores [B, h*T, N] and the tokens' values v_in [B,T,C],
  // added to `into` as image_to_tokens says.
  torch::Tensor attend_to_tokens(const torch::Tensor& scores, const torch::Tensor& v_in, torch::Tensor into);
  int64_t num_heads;
  torch::nn::Linear q_proj{nullptr}, k_proj{nullptr}, v_proj{nullptr}, out_proj{nullptr};
};
TORCH_MODULE(DecoderAttention);

struct TwoWayAttentionBlockImpl : torch::nn::Module {
  TwoWayAttentionBlockImpl(int64_t embedding_dim, int64_t num_heads, int64_t mlp_dim, int64_t downsample_rate,
                           bool skip_first_layer_pe);
  // Updates queries [B,Nq,C] and keys [B,HW,C] in place of the reference's returned pair; keys may
  // come in with batch 1 (shared by every prompt) and leave with batch B. `shared`, when given, is
  // the projected image side of these keys (first block only). keys_owned: keys is the previous
  // block's output, which this block may overwrite (the first block's keys are the caller's).
  void forward(torch::Tensor& queries, torch::Tensor& keys, const torch::Tensor& query_pe, const torch::Tensor& key_pe,
               const SharedImageSide* shared, bool keys_owned);
  bool skip_first_layer_pe;
  DecoderAttention self_attn{nullptr}, cross_attn_token_to_image{nullptr}, cross_attn_image_to_token{nullptr};
  torch::nn::LayerNorm norm1{nullptr}, norm2{nullptr}, norm3{nullptr}, norm4{nullptr};
  MLPBlock mlp{nullptr};
};
TORCH_MODULE(TwoWayAttentionBlock);

struct TwoWayTransformerImpl : torch::nn::Module {
  TwoWayTransformerImpl(int depth, int64_t embedding_dim, int64_t num_heads, int64_t mlp_dim, int64_t downsample_rate);
  // image_embedding, image_pe [B or 1,C,h,w]; point_embedding [B,N,C] -> (queries [B,N,C], keys [B,hw,C]).
  // `shared`: share_image of the image (batch 1), or null; with it, image_embedding and image_pe are
  // not read (they may be undefined).
  std::pair<torch::Tensor, torch::Tensor> forward(const torch::Tensor& image_embedding, const torch::Tensor& image_pe,
                                                  const torch::Tensor& point_embedding,
                                                  const SharedImageSide* shared = nullptr);
  // The first block's SharedImageSide for image_embedding and image_pe [1,C,h,w].
  SharedImageSide share_image(const torch::Tensor& image_embedding, const torch::Tensor& image_pe);
  torch::nn::ModuleList layers;
  DecoderAttention final_attn_token_to_image{nullptr};
  torch::nn::LayerNorm norm_final_attn{nullptr};
};
TORCH_MODULE(TwoWayTransformer);

}  // namespace cls::sam
