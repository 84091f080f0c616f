#include "models/sam/two_way_transformer.h"

#include <cmath>

#include "core/error.h"

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

namespace {
// A [heads*dh, C] projection weight as [heads, dh, C] (row h*dh + d is head h's channel d).
torch::Tensor per_head(const torch::Tensor& w, int64_t heads) { return w.view({heads, w.size(0) / heads, w.size(1)}); }
}  // namespace

torch::Tensor DecoderAttentionImpl::tokens_to_image(const torch::Tensor& q_in, const torch::Tensor& k_in,
                                                    const torch::Tensor& v_in) {
  const int64_t B = q_in.size(0), T = q_in.size(1), Bi = k_in.size(0), C = k_in.size(2);
  const auto q = separate_heads(q_proj(q_in), num_heads);  // [B,h,T,dh]
  const int64_t dh = q.size(3);
  const auto Wk = per_head(k_proj->weight, num_heads), Wv = per_head(v_proj->weight, num_heads);
  // q.b_k is the same for every key of a query, and softmax ignores it: k_proj's bias drops out.
  const auto qk = torch::einsum("bhtd,hdc->bhtc", {q, Wk});  // [B,h,T,C]
  // Rows (prompt, head, token) against the Bi image batches: one shared image takes every row.
  const int64_t rows = B * num_heads * T / Bi;
  auto attn = torch::bmm(qk.reshape({Bi, rows, C}), k_in.transpose(1, 2));
  attn = torch::softmax(attn / std::sqrt(double(dh)), -1);
  // Each softmax row sums to one, so v_proj's bias passes through unchanged.
  const auto px = torch::bmm(attn, v_in).view({B, num_heads, T, C});
  const auto o = torch::einsum("bhtc,hdc->bhtd", {px, Wv}) + v_proj->bias.view({1, num_heads, 1, dh});
  return out_proj(recombine_heads(o));
}

torch::Tensor DecoderAttentionImpl::tokens_to_projected_image(const torch::Tensor& q_in, const torch::Tensor& k,
                                                              const torch::Tensor& v) {
  const int64_t B = q_in.size(0), T = q_in.size(1), N = k.size(0), I = k.size(1), dh = I / num_heads;
  // Every prompt's tokens against the one image, a product per head: [h, B*T, dh] x [h, dh, N].
  const auto q = q_proj(q_in).view({B * T, num_heads, dh}).transpose(0, 1);
  auto attn = torch::bmm(q, k.view({N, num_heads, dh}).permute({1, 2, 0}));
  attn = torch::softmax(attn / std::sqrt(double(dh)), -1);
  const auto o = torch::bmm(attn, v.view({N, num_heads, dh}).transpose(0, 1));  // [h, B*T, dh]
  return out_proj(o.transpose(0, 1).reshape({B, T, I}));
}

// The tokens' values through out_proj, per head: out_proj(concat_h P_h V_h) = sum_h P_h (V_h W_o,h^T)
// + b_o with W_o,h = out_proj.weight[:, h*dh:(h+1)*dh]. v [B,h,T,dh] -> [B, h*T, C].
torch::Tensor DecoderAttentionImpl::values_through_out_proj(const torch::Tensor& v) const {
  const int64_t B = v.size(0), dh = v.size(3), C = out_proj->weight.size(0);
  const auto Wo = out_proj->weight.view({C, num_heads, dh}).permute({1, 2, 0});  // [h, dh, C]
  return torch::einsum("bhtd,hdc->bhtc", {v, Wo}).reshape({B, -1, C});
}

// The image's attention to the tokens, from scores [B, h*T, N] (each position's softmax runs over a
// prompt's T tokens of one head, dim 2 of [B, h, T, N], so it is vectorised over the N positions):
// sum_(h,t) P[b, (h,t), n] u[b, (h,t), :] + b_o, with u the values through out_proj.
torch::Tensor DecoderAttentionImpl::attend_to_tokens(const torch::Tensor& scores, const torch::Tensor& v_in,
                                                     torch::Tensor into) {
  const int64_t B = v_in.size(0), T = v_in.size(1), C = v_in.size(2), N = scores.size(2);
  const int64_t dh = out_proj->weight.size(1) / num_heads;
  const auto attn = torch::softmax(scores.view({B, num_heads, T, N}) / std::sqrt(double(dh)), 2).view({B, num_heads * T, N});
  const auto u = values_through_out_proj(separate_heads(v_proj(v_in), num_heads));  // [B, h*T, C]
  if (into.defined()) {
    if (into.sizes() != torch::IntArrayRef{B, N, C} || !into.is_contiguous())
      throw Error("SAM decoder attention: the tensor to add to must be a contiguous [B, N, C]");
    into.add_(out_proj->bias);
  } else {
    into = out_proj->bias.expand({B, N, C}).clone(at::MemoryFormat::Contiguous);  // never a view of the bias
  }
  return into.baddbmm_(attn.transpose(1, 2), u);
}

torch::Tensor DecoderAttentionImpl::projected_image_to_tokens(const torch::Tensor& q, const torch::Tensor& k_in,
                                                              const torch::Tensor& v_in, torch::Tensor into) {
  const int64_t N = q.size(0), I = q.size(1), dh = I / num_heads, B = k_in.size(0), T = k_in.size(1);
  // Every prompt's tokens against every position, a product per head: [h, B*T, dh] x [h, dh, N].
  const auto k = k_proj(k_in).view({B * T, num_heads, dh}).transpose(0, 1);
  const auto scores = torch::bmm(k, q.view({N, num_heads, dh}).permute({1, 2, 0}));  // [h, B*T, N]
  return attend_to_tokens(scores.view({num_heads, B, T, N}).transpose(0, 1).reshape({B, num_heads * T, N}), v_in,
                          std::move(into));
}

torch::Tensor DecoderAttentionImpl::image_to_tokens(const torch::Tensor& q_in, const torch::Tensor& k_in,
                                                    const torch::Tensor& v_in, torch::Tensor into) {
  const int64_t Bi = q_in.size(0), N = q_in.size(1), C = q_in.size(2), B = k_in.size(0), T = k_in.size(1);
  const auto k = separate_heads(k_proj(k_in), num_heads);  // [B,h,T,dh]
  const int64_t dh = k.size(3), ht = num_heads * T;
  const auto kq = torch::einsum("bhtd,hdc->bhtc", {k, per_head(q_proj->weight, num_heads)}).reshape({B, ht, C});
  const auto kb = torch::einsum("bhtd,hd->bht", {k, q_proj->bias.view({num_heads, dh})}).reshape({B, ht, 1});
  if (Bi == B) return attend_to_tokens(torch::baddbmm(kb, kq, q_in.transpose(1, 2)), v_in, std::move(into));
  // One image for every prompt: [B*h*T, N] in one product.
  const auto scores = torch::addmm(kb.reshape({B * ht, 1}), kq.reshape({B * ht, C}), q_in[0].t());
  return attend_to_tokens(scores.view({B, ht, N}), v_in, std::move(into));
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
                                       const torch::Tensor& key_pe, const SharedImageSide* shared, bool keys_owned) {
  // Self attention (the first layer replaces the queries: no residual, no PE).
  if (skip_first_layer_pe) {
    queries = self_attn(queries, queries, queries);
  } else {
    const auto q = queries + query_pe;
    queries = queries + self_attn(q, q, queries);
  }
  queries = norm1(queries);
  // Tokens attend to the image. Both cross-attentions take keys + key_pe of the keys entering the block.
  const auto k = shared ? torch::Tensor() : keys + key_pe;
  auto q = queries + query_pe;
  queries = norm2(queries + (shared ? cross_attn_token_to_image->tokens_to_projected_image(q, shared->key, shared->value)
                                    : cross_attn_token_to_image->tokens_to_image(q, k, keys)));
  queries = norm3(queries + mlp(queries));
  // The image attends to the tokens.
  q = queries + query_pe;
  // keys + attention, summed in place: into the keys themselves when this block owns them (nothing
  // reads them after this), else into a copy.
  const int64_t B = queries.size(0), N = keys.size(1), C = keys.size(2);
  const auto& residual = shared ? shared->image : keys;
  auto into = keys_owned && keys.size(0) == B && keys.is_contiguous() ? keys
                                                                      : residual.expand({B, N, C}).clone(at::MemoryFormat::Contiguous);
  keys = norm4(shared ? cross_attn_image_to_token->projected_image_to_tokens(shared->query, q, queries, std::move(into))
                      : cross_attn_image_to_token->image_to_tokens(k, q, queries, std::move(into)));
}

TwoWayTransformerImpl::TwoWayTransformerImpl(int depth, int64_t dim, int64_t num_heads, int64_t mlp_dim, int64_t downsample_rate) {
  for (int i = 0; i < depth; ++i) layers->push_back(TwoWayAttentionBlock(dim, num_heads, mlp_dim, downsample_rate, i == 0));
  register_module("layers", layers);
  final_attn_token_to_image = register_module("final_attn_token_to_image", DecoderAttention(dim, num_heads, downsample_rate));
  norm_final_attn = register_module("norm_final_attn", torch::nn::LayerNorm(torch::nn::LayerNormOptions({dim})));
}

std::pair<torch::Tensor, torch::Tensor> TwoWayTransformerImpl::forward(const torch::Tensor& image_embedding,
                                                                       const torch::Tensor& image_pe,
                                                                       const torch::Tensor& point_embedding,
                                                                       const SharedImageSide* shared) {
  // Contiguous: every block and the final attention add it to the keys.
  const auto keys_pe = shared ? shared->pe.unsqueeze(0) : image_pe.flatten(2).permute({0, 2, 1}).contiguous();
  auto keys = shared ? shared->image.unsqueeze(0) : image_embedding.flatten(2).permute({0, 2, 1});
  auto queries = point_embedding;
  for (size_t i = 0; i < layers->size(); ++i)
    layers[i]->as<TwoWayAttentionBlock>()->forward(queries, keys, point_embedding, keys_pe, i == 0 ? shared : nullptr,
                                                   /*keys_owned=*/i > 0);
  const auto q = queries + point_embedding;
  const auto k = keys + keys_pe;
  queries = norm_final_attn(queries + final_attn_token_to_image->tokens_to_image(q, k, keys));
  return {queries, keys};
}

SharedImageSide TwoWayTransformerImpl::share_image(const torch::Tensor& image_embedding, const torch::Tensor& image_pe) {
  const auto keys = image_embedding.flatten(2).permute({0, 2, 1})[0].contiguous();  // [N, C]
  const auto pe = image_pe.flatten(2).permute({0, 2, 1})[0].contiguous();
  const auto k = keys + pe;
  const auto& first = layers[0]->as<TwoWayAttentionBlock>();
  return {first->cross_attn_token_to_image->k_proj(k), first->cross_attn_token_to_image->v_proj(keys),
          first->cross_attn_image_to_token->q_proj(k), keys, pe};
}

}  // namespace cls::sam
