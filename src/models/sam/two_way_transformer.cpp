#include "models/sam/two_way_transformer.h"

#include <cmath>

namespace cls::sam {

DecoderAttentionImpl::DecoderAttentionImpl(int64_t dim, int64_t num_heads_, int64_t downsample_rate) : num_heads(num_heads_) {
  const int64_t internal = dim / downsample_rate;
  q_proj = register_module("q_proj", torch::nn::Linear(dim, internal));
  k_proj = register_module("k_proj", torch::nn::Linear(dim, internal));
  v_proj = register_module("v_proj", torch::nn::Linear(dim, internal));
  out_proj = register_module("out_proj", torch::nn::Linear(internal, dim));
}

namespace {
torch::Tensor separate_heads(const torch::Tensor& x, int64_t num_heads) {
  const int64_t b = x.size(0), n = x.size(1), c = x.size(2);
  return x.reshape({b, n, num_heads, c / num_heads}).transpose(1, 2);  // B x heads x N x C/heads
}
torch::Tensor recombine_heads(const torch::Tensor& x) {
  const int64_t b = x.size(0), h = x.size(1), n = x.size(2), c = x.size(3);
  return x.transpose(1, 2).reshape({b, n, h * c});
}
}  // namespace

torch::Tensor DecoderAttentionImpl::forward(const torch::Tensor& q_in, const torch::Tensor& k_in, const torch::Tensor& v_in) {
  const auto q = separate_heads(q_proj(q_in), num_heads);
  const auto k = separate_heads(k_proj(k_in), num_heads);
  const auto v = separate_heads(v_proj(v_in), num_heads);
  const int64_t c_per_head = q.size(3);
  auto attn = torch::matmul(q, k.permute({0, 1, 3, 2}));
  attn = attn / std::sqrt(double(c_per_head));
  attn = torch::softmax(attn, -1);
  return out_proj(recombine_heads(torch::matmul(attn, v)));
}

TwoWayAttentionBlockImpl::TwoWayAttentionBlockImpl(int64_t dim, int64_t num_heads, int64_t mlp_dim, int64_t downsample_rate,
                                                   bool skip_first_layer_pe_)
    : skip_first_layer_pe(skip_first_layer_pe_) {
  self_attn = register_module("self_attn", DecoderAttention(dim, num_heads));
  norm1 = register_module("norm1", torch::nn::LayerNorm(torch::nn::LayerNormOptions({dim})));
  cross_attn_token_to_image = register_module("cross_attn_token_to_image", DecoderAttention(dim, num_heads, downsample_rate));
  norm2 = register_module("norm2", torch::nn::LayerNorm(torch::nn::LayerNormOptions({dim})));
  mlp = register_module("mlp", MLPBlock(dim, mlp_dim, Activation::ReLU));
  norm3 = register_module("norm3", torch::nn::LayerNorm(torch::nn::LayerNormOptions({dim})));
  norm4 = register_module("norm4", torch::nn::LayerNorm(torch::nn::LayerNormOptions({dim})));
  cross_attn_image_to_token = register_module("cross_attn_image_to_token", DecoderAttention(dim, num_heads, downsample_rate));
}

void TwoWayAttentionBlockImpl::forward(torch::Tensor& queries, torch::Tensor& keys, const torch::Tensor& query_pe,
                                       const torch::Tensor& key_pe) {
  // Self attention (the first layer replaces the queries: no residual, no PE).
  if (skip_first_layer_pe) {
    queries = self_attn(queries, queries, queries);
  } else {
    const auto q = queries + query_pe;
    queries = queries + self_attn(q, q, queries);
  }
  queries = norm1(queries);
  // Tokens attend to the image.
  auto q = queries + query_pe;
  auto k = keys + key_pe;
  queries = norm2(queries + cross_attn_token_to_image(q, k, keys));
  queries = norm3(queries + mlp(queries));
  // The image attends to the tokens.
  q = queries + query_pe;
  k = keys + key_pe;
  keys = norm4(keys + cross_attn_image_to_token(k, q, queries));
}

TwoWayTransformerImpl::TwoWayTransformerImpl(int depth, int64_t dim, int64_t num_heads, int64_t mlp_dim, int64_t downsample_rate) {
  for (int i = 0; i < depth; ++i) layers->push_back(TwoWayAttentionBlock(dim, num_heads, mlp_dim, downsample_rate, i == 0));
  register_module("layers", layers);
  final_attn_token_to_image = register_module("final_attn_token_to_image", DecoderAttention(dim, num_heads, downsample_rate));
  norm_final_attn = register_module("norm_final_attn", torch::nn::LayerNorm(torch::nn::LayerNormOptions({dim})));
}

std::pair<torch::Tensor, torch::Tensor> TwoWayTransformerImpl::forward(const torch::Tensor& image_embedding,
                                                                       const torch::Tensor& image_pe,
                                                                       const torch::Tensor& point_embedding) {
  const auto keys_pe = image_pe.flatten(2).permute({0, 2, 1});
  auto keys = image_embedding.flatten(2).permute({0, 2, 1});
  auto queries = point_embedding;
  for (const auto& layer : *layers) layer->as<TwoWayAttentionBlock>()->forward(queries, keys, point_embedding, keys_pe);
  const auto q = queries + point_embedding;
  const auto k = keys + keys_pe;
  queries = norm_final_attn(queries + final_attn_token_to_image(q, k, keys));
  return {queries, keys};
}

}  // namespace cls::sam
