#include "models/sam/image_encoder.h"

#include <ATen/Parallel.h>

#include <algorithm>
#include <cmath>

#include "models/parallel_linear.h"

namespace cls::sam {

namespace F = torch::nn::functional;
using torch::indexing::Slice;

std::pair<torch::Tensor, std::pair<int64_t, int64_t>> window_partition(const torch::Tensor& x_in, int64_t ws) {
  const int64_t B = x_in.size(0), H = x_in.size(1), W = x_in.size(2), C = x_in.size(3);
  const int64_t pad_h = (ws - H % ws) % ws, pad_w = (ws - W % ws) % ws;
  torch::Tensor x = x_in;
  if (pad_h > 0 || pad_w > 0) x = F::pad(x, F::PadFuncOptions({0, 0, 0, pad_w, 0, pad_h}));
  const int64_t Hp = H + pad_h, Wp = W + pad_w;
  x = x.view({B, Hp / ws, ws, Wp / ws, ws, C});
  auto windows = x.permute({0, 1, 3, 2, 4, 5}).contiguous().view({-1, ws, ws, C});
  return {windows, {Hp, Wp}};
}

torch::Tensor window_unpartition(const torch::Tensor& windows, int64_t ws, std::pair<int64_t, int64_t> pad_hw,
                                 std::pair<int64_t, int64_t> hw) {
  const auto [Hp, Wp] = pad_hw;
  const auto [H, W] = hw;
  const int64_t B = windows.size(0) / (Hp * Wp / ws / ws);
  auto x = windows.view({B, Hp / ws, Wp / ws, ws, ws, -1});
  x = x.permute({0, 1, 3, 2, 4, 5}).contiguous().view({B, Hp, Wp, -1});
  if (Hp > H || Wp > W) x = x.index({Slice(), Slice(0, H), Slice(0, W), Slice()}).contiguous();
  return x;
}

torch::Tensor get_rel_pos(int64_t q_size, int64_t k_size, const torch::Tensor& rel_pos) {
  const int64_t max_rel_dist = 2 * std::max(q_size, k_size) - 1;
  torch::Tensor resized = rel_pos;
  if (rel_pos.size(0) != max_rel_dist) {
    resized = F::interpolate(rel_pos.reshape({1, rel_pos.size(0), -1}).permute({0, 2, 1}),
                             F::InterpolateFuncOptions()
                                 .size(std::vector<int64_t>{max_rel_dist})
                                 .mode(torch::kLinear)
                                 .align_corners(false));
    resized = resized.reshape({-1, max_rel_dist}).permute({1, 0});
  }
  // Scale the coordinates with the shorter length when q and k differ (reference: float coords, .long()).
  const double q_scale = std::max(double(k_size) / double(q_size), 1.0);
  const double k_scale = std::max(double(q_size) / double(k_size), 1.0);
  std::vector<int64_t> index(size_t(q_size * k_size));
  for (int64_t i = 0; i < q_size; ++i)
    for (int64_t j = 0; j < k_size; ++j)
      index[size_t(i * k_size + j)] = int64_t(i * q_scale - j * k_scale + (k_size - 1) * k_scale);
  const auto idx = torch::from_blob(index.data(), {q_size, k_size}, torch::kLong).to(rel_pos.device());
  return resized.index({idx});
}

torch::Tensor add_decomposed_rel_pos(const torch::Tensor& attn, const torch::Tensor& q, const torch::Tensor& Rh,
                                     const torch::Tensor& Rw, std::pair<int64_t, int64_t> q_hw,
                                     std::pair<int64_t, int64_t> k_hw) {
  const auto [q_h, q_w] = q_hw;
  const auto [k_h, k_w] = k_hw;
  const int64_t B = q.size(0), dim = q.size(2);
  const auto r_q = q.reshape({B, q_h, q_w, dim});
  const auto rel_h = torch::einsum("bhwc,hkc->bhwk", {r_q, Rh});
  const auto rel_w = torch::einsum("bhwc,wkc->bhwk", {r_q, Rw});
  return (attn.view({B, q_h, q_w, k_h, k_w}) + rel_h.unsqueeze(4) + rel_w.unsqueeze(3)).view({B, q_h * q_w, k_h * k_w});
}

ViTAttentionImpl::ViTAttentionImpl(int64_t dim, int64_t num_heads_, bool qkv_bias, bool use_rel_pos_,
                                   std::pair<int64_t, int64_t> input_size)
    : num_heads(num_heads_), use_rel_pos(use_rel_pos_) {
  const int64_t head_dim = dim / num_heads;
  scale = std::pow(double(head_dim), -0.5);
  qkv = register_module("qkv", torch::nn::Linear(torch::nn::LinearOptions(dim, dim * 3).bias(qkv_bias)));
  proj = register_module("proj", torch::nn::Linear(dim, dim));
  if (use_rel_pos) {
    rel_pos_h = register_parameter("rel_pos_h", torch::zeros({2 * input_size.first - 1, head_dim}));
    rel_pos_w = register_parameter("rel_pos_w", torch::zeros({2 * input_size.second - 1, head_dim}));
  }
}

torch::Tensor ViTAttentionImpl::forward(const torch::Tensor& x) {
  const int64_t B = x.size(0), H = x.size(1), W = x.size(2), N = H * W;
  // qkv: [3, B*nHead, H*W, head_dim]
  const auto qkv_ = parallel_rows_linear(x, qkv->weight, qkv->bias)
                        .reshape({B, N, 3, num_heads, -1})
                        .permute({2, 0, 3, 1, 4})
                        .reshape({3, B * num_heads, N, -1});
  const auto q = qkv_[0], k = qkv_[1], v = qkv_[2];
  torch::Tensor Rh, Rw;
  if (use_rel_pos) Rh = get_rel_pos(H, H, rel_pos_h), Rw = get_rel_pos(W, W, rel_pos_w);
  // Bands of whole query rows (W tokens each) of `heads` heads: heads * rows * W * N floats at most,
  // the block budget shared by the threads that take bands side by side (split_over_threads).
  const bool split = split_over_threads(q);
  const int64_t budget = kCpuBlockBytes / (split ? at::get_num_threads() : 1);
  const int64_t row_bytes = W * N * int64_t(sizeof(float));
  const int64_t rows = std::clamp<int64_t>(budget / row_bytes, 1, H);
  const int64_t heads = rows < H ? 1 : std::max<int64_t>(1, budget / (H * row_bytes));
  const int64_t BH = q.size(0), row_bands = (H + rows - 1) / rows, bands = (BH + heads - 1) / heads * row_bands;
  auto out = torch::empty_like(q);
  const auto kt = k.transpose(-2, -1);
  const auto band = [&](int64_t i) {
    const int64_t h0 = i / row_bands * heads, h1 = std::min(BH, h0 + heads);
    const int64_t y0 = i % row_bands * rows, y1 = std::min(H, y0 + rows);
    const auto qb = q.slice(0, h0, h1).slice(1, y0 * W, y1 * W);
    auto attn = torch::matmul(qb * scale, kt.slice(0, h0, h1));
    if (use_rel_pos) attn = add_decomposed_rel_pos(attn, qb, Rh.slice(0, y0, y1), Rw, {y1 - y0, W}, {H, W});
    out.slice(0, h0, h1).slice(1, y0 * W, y1 * W).copy_(torch::matmul(attn.softmax(-1), v.slice(0, h0, h1)));
  };
  if (split) {
    at::parallel_for(0, bands, 1, [&](int64_t b0, int64_t b1) {
      torch::NoGradGuard no_grad;  // the worker threads' own grad mode
      for (int64_t i = b0; i < b1; ++i) band(i);
    });
  } else {
    for (int64_t i = 0; i < bands; ++i) band(i);
  }
  const auto heads_joined = out.view({B, num_heads, H, W, -1}).permute({0, 2, 3, 1, 4}).reshape({B, H, W, -1});
  return parallel_rows_linear(heads_joined, proj->weight, proj->bias);
}

ViTBlockImpl::ViTBlockImpl(const SamConfig& cfg, int64_t window_size_) : window_size(window_size_) {
  const int64_t dim = cfg.encoder_embed_dim;
  const auto ln = torch::nn::LayerNormOptions({dim}).eps(1e-6);
  norm1 = register_module("norm1", torch::nn::LayerNorm(ln));
  const int64_t grid = cfg.image_embedding_size();
  const auto input_size = window_size == 0 ? std::make_pair(grid, grid) : std::make_pair(window_size, window_size);
  attn = register_module("attn", ViTAttention(dim, cfg.encoder_num_heads, cfg.qkv_bias, cfg.use_rel_pos, input_size));
  norm2 = register_module("norm2", torch::nn::LayerNorm(ln));
  mlp = register_module("mlp", MLPBlock(dim, int64_t(dim * cfg.mlp_ratio), Activation::GELU));
}

torch::Tensor ViTBlockImpl::forward(const torch::Tensor& x) {
  auto h = norm1(x);
  if (window_size > 0) {
    const int64_t H = h.size(1), W = h.size(2);
    auto [windows, pad_hw] = window_partition(h, window_size);
    h = window_unpartition(attn(windows), window_size, pad_hw, {H, W});
  } else {
    h = attn(h);
  }
  auto y = x + h;
  return y + mlp(norm2(y));
}

PatchEmbedImpl::PatchEmbedImpl(int64_t patch_size, int64_t in_chans, int64_t embed_dim) {
  proj = register_module("proj", torch::nn::Conv2d(torch::nn::Conv2dOptions(in_chans, embed_dim, patch_size).stride(patch_size)));
}

torch::Tensor PatchEmbedImpl::forward(const torch::Tensor& x) { return proj(x).permute({0, 2, 3, 1}); }

ImageEncoderViTImpl::ImageEncoderViTImpl(const SamConfig& cfg) {
  patch_embed = register_module("patch_embed", PatchEmbed(cfg.patch_size, cfg.in_chans, cfg.encoder_embed_dim));
  const int64_t grid = cfg.image_embedding_size();
  if (cfg.use_abs_pos) pos_embed = register_parameter("pos_embed", torch::zeros({1, grid, grid, int64_t(cfg.encoder_embed_dim)}));
  for (int i = 0; i < cfg.encoder_depth; ++i) {
    const bool global = std::find(cfg.global_attn_indexes.begin(), cfg.global_attn_indexes.end(), i) != cfg.global_attn_indexes.end();
    blocks->push_back(ViTBlock(cfg, global ? 0 : cfg.window_size));
  }
  register_module("blocks", blocks);
  using torch::nn::Conv2dOptions;
  neck->push_back(torch::nn::Conv2d(Conv2dOptions(cfg.encoder_embed_dim, cfg.prompt_embed_dim, 1).bias(false)));
  neck->push_back(LayerNorm2d(cfg.prompt_embed_dim));
  neck->push_back(torch::nn::Conv2d(Conv2dOptions(cfg.prompt_embed_dim, cfg.prompt_embed_dim, 3).padding(1).bias(false)));
  neck->push_back(LayerNorm2d(cfg.prompt_embed_dim));
  register_module("neck", neck);
}

torch::Tensor ImageEncoderViTImpl::forward(const torch::Tensor& input) {
  auto x = patch_embed(input);
  if (pos_embed.defined()) x = x + pos_embed;
  {
    // The blocks' GEMMs run on LibTorch's threads (parallel_rows_linear, attention bands), each BLAS
    // call on its calling thread.
    const auto blas = blas_threads_for_split(x);
    for (const auto& blk : *blocks) x = blk->as<ViTBlock>()->forward(x);
  }
  return neck->forward(x.permute({0, 3, 1, 2}));
}

}  // namespace cls::sam
