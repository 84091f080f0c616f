#include "models/clip/clip_model.h"

#include <ATen/ATen.h>
#include <ATen/Parallel.h>

#include <cmath>
#include <limits>
#include <sstream>

#include "core/error.h"
#include "models/parallel_linear.h"
#include "models/weights/clip_weights.h"
#include "models/weights/weight_layout.h"

namespace cls::clip {
namespace {

std::string shape_str(at::IntArrayRef s) {
  std::ostringstream o;
  o << '[';
  for (size_t i = 0; i < s.size(); ++i) o << (i ? ", " : "") << s[i];
  o << ']';
  return o.str();
}

// The reference LayerNorm subclass: computed in fp32, cast back.
at::Tensor layer_norm(const at::Tensor& x, const at::Tensor& w, const at::Tensor& b) {
  return at::layer_norm(x.to(at::kFloat), {x.size(-1)}, w, b, 1e-5).to(x.scalar_type());
}

// nn.MultiheadAttention (batch-first here): packed q,k,v projection, heads split contiguously,
// softmax(q k^T / sqrt(hd) + mask) v, out_proj. On the CPU the sequences are shared among LibTorch's
// threads (models/parallel_linear.h).
at::Tensor multi_head_attention(const at::Tensor& x, const at::Tensor& in_w, const at::Tensor& in_b,
                                const at::Tensor& out_w, const at::Tensor& out_b, int heads,
                                const at::Tensor& mask) {
  const int64_t n = x.size(0), l = x.size(1), w = x.size(2), hd = w / heads;
  const at::Tensor qkv = parallel_rows_linear(x, in_w, in_b).view({n, l, 3, heads, hd}).permute({2, 0, 3, 1, 4});
  const auto attend = [&](int64_t s0, int64_t s1) {  // sequences [s0, s1)
    const at::Tensor q = qkv[0].slice(0, s0, s1) * (1.0 / std::sqrt(static_cast<double>(hd)));
    at::Tensor scores = at::matmul(q, qkv[1].slice(0, s0, s1).transpose(-2, -1));  // [s, heads, l, l]
    if (mask.defined()) scores = scores + mask;
    const at::Tensor attn = at::softmax(scores, -1);
    return at::matmul(attn, qkv[2].slice(0, s0, s1)).permute({0, 2, 1, 3}).reshape({s1 - s0, l, w});
  };
  at::Tensor out;
  if (split_over_threads(qkv) && n > 1) {
    out = at::empty({n, l, w}, x.options());
    at::parallel_for(0, n, 1, [&](int64_t s0, int64_t s1) {
      at::NoGradGuard no_grad;  // the worker threads' own grad mode
      out.slice(0, s0, s1).copy_(attend(s0, s1));
    });
  } else {
    out = attend(0, n);
  }
  return parallel_rows_linear(out, out_w, out_b);
}

}  // namespace

at::Tensor l2_normalize(const at::Tensor& f) { return f / f.norm(2, -1, true); }

namespace {

WeightFile as_weight_file(const std::map<std::string, at::Tensor>& state, const std::string& source) {
  WeightFile w(source);
  for (const auto& [name, t] : state) {
    if (t.defined()) w.add(name, t);
    else fail(source, "tensor '" + name + "' is undefined");
  }
  return w;
}

}  // namespace

ClipModel::ClipModel(const ClipConfig& config, const std::map<std::string, at::Tensor>& state,
                     const ClipOptions& options, const std::string& source)
    : ClipModel(config, as_weight_file(state, source), options) {}

ClipModel::ClipModel(const ClipConfig& config, const WeightFile& weights, const ClipOptions& options)
    : config_(config), options_(options) {
  const std::string& source = weights.source();
  const ClipArch& arch = config.arch;
  if (config.vision_heads <= 0 || arch.vision_width % config.vision_heads != 0 ||
      config.transformer_heads <= 0 || arch.transformer_width % config.transformer_heads != 0)
    fail(source, "CLIP config: widths must be divisible by the head counts");
  if (options.device.is_cpu() && options.dtype == at::kHalf)
    fail(source, "CLIP: float16 compute is only supported on CUDA; use float32 on the CPU");
  if (options.dtype != at::kFloat && options.dtype != at::kHalf && options.dtype != at::kBFloat16)
    fail(source, "CLIP: compute dtype must be float32, float16 or bfloat16");
  // Names and shapes first, nothing is read before this passes.
  const WeightFile state = map_weights_strict(weights, clip_expected_tensors(arch), clip_layouts(),
                                              "CLIP " + arch.name);

  const auto on_device = at::TensorOptions().device(options.device);
  auto take = [&](const std::string& name) {
    return state.get(name).to(on_device.dtype(options.dtype)).contiguous();
  };
  // LayerNorm parameters stay fp32 (the reference LayerNorm computes in fp32).
  auto take_f32 = [&](const std::string& name) { return state.get(name).to(on_device.dtype(at::kFloat)).contiguous(); };
  auto blocks = [&](const std::string& prefix, int layers) {
    std::vector<Block> out;
    for (int i = 0; i < layers; ++i) {
      const std::string b = prefix + std::to_string(i) + ".";
      out.push_back({take_f32(b + "ln_1.weight"), take_f32(b + "ln_1.bias"), take(b + "attn.in_proj_weight"),
                     take(b + "attn.in_proj_bias"), take(b + "attn.out_proj.weight"),
                     take(b + "attn.out_proj.bias"), take_f32(b + "ln_2.weight"), take_f32(b + "ln_2.bias"),
                     take(b + "mlp.c_fc.weight"), take(b + "mlp.c_fc.bias"), take(b + "mlp.c_proj.weight"),
                     take(b + "mlp.c_proj.bias")});
    }
    return out;
  };
  conv1_w_ = take("visual.conv1.weight");
  class_embedding_ = take("visual.class_embedding");
  visual_pos_ = take("visual.positional_embedding");
  ln_pre_w_ = take_f32("visual.ln_pre.weight");
  ln_pre_b_ = take_f32("visual.ln_pre.bias");
  visual_blocks_ = blocks("visual.transformer.resblocks.", arch.vision_layers);
  ln_post_w_ = take_f32("visual.ln_post.weight");
  ln_post_b_ = take_f32("visual.ln_post.bias");
  visual_proj_ = take("visual.proj");
  token_embedding_ = take("token_embedding.weight");
  text_pos_ = take("positional_embedding");
  text_blocks_ = blocks("transformer.resblocks.", arch.transformer_layers);
  ln_final_w_ = take_f32("ln_final.weight");
  ln_final_b_ = take_f32("ln_final.bias");
  text_projection_ = take("text_projection");
  logit_scale_ = std::exp(state.get("logit_scale").to(at::kFloat).item<float>());
  // build_attention_mask(): -inf strictly above the diagonal.
  causal_mask_ = at::full({arch.context_length, arch.context_length},
                          -std::numeric_limits<float>::infinity(), on_device.dtype(options.dtype))
                     .triu_(1);
}

at::Tensor ClipModel::run_blocks(at::Tensor x, const std::vector<Block>& blocks, int heads, const at::Tensor& mask,
                                 const std::string& prefix, ClipTrace* trace) const {
  // The blocks' GEMMs run on LibTorch's threads, each BLAS call on its calling thread.
  const auto blas = blas_threads_for_split(x);
  for (size_t i = 0; i < blocks.size(); ++i) {
    const Block& b = blocks[i];
    const std::string name = prefix + std::to_string(i);
    const at::Tensor h1 = layer_norm(x, b.ln_1_w, b.ln_1_b);
    const at::Tensor attn = multi_head_attention(h1, b.in_proj_w, b.in_proj_b, b.out_proj_w, b.out_proj_b, heads, mask);
    x = x + attn;
    const at::Tensor h2 = layer_norm(x, b.ln_2_w, b.ln_2_b);
    at::Tensor m = parallel_rows_linear(h2, b.c_fc_w, b.c_fc_b);
    m = config_.activation == Activation::Gelu ? at::gelu(m) : m * at::sigmoid(1.702 * m);
    m = parallel_rows_linear(m, b.c_proj_w, b.c_proj_b);
    x = x + m;
    if (trace) {
      (*trace)[name + ".ln_1"] = h1;
      (*trace)[name + ".attn"] = attn;
      (*trace)[name + ".ln_2"] = h2;
      (*trace)[name + ".mlp"] = m;
      (*trace)[name] = x;
    }
  }
  return x;
}

at::Tensor ClipModel::encode_image(const at::Tensor& images, ClipTrace* trace) const {
  const int64_t r = config_.arch.image_resolution;
  if (images.dim() != 4 || images.size(1) != 3 || images.size(2) != r || images.size(3) != r)
    throw Error("CLIP encode_image: expected images [N, 3, " + std::to_string(r) + ", " + std::to_string(r) +
                "], got " + shape_str(images.sizes()));
  const at::Tensor in = images.to(conv1_w_.options());
  const at::Tensor patches = at::conv2d(in, conv1_w_, {}, config_.arch.vision_patch_size);  // [N, W, g, g]
  if (trace) (*trace)["visual.conv1"] = patches;
  const int64_t n = in.size(0), w = config_.arch.vision_width;
  at::Tensor x = patches.reshape({n, w, -1}).permute({0, 2, 1});  // [N, g*g, W], row-major grid
  x = at::cat({class_embedding_.view({1, 1, w}).expand({n, 1, w}), x}, 1) + visual_pos_;
  x = layer_norm(x, ln_pre_w_, ln_pre_b_);
  if (trace) (*trace)["visual.ln_pre"] = x;
  x = run_blocks(x, visual_blocks_, config_.vision_heads, at::Tensor(), "visual.transformer.resblocks.", trace);
  const at::Tensor pooled = layer_norm(x.select(1, 0), ln_post_w_, ln_post_b_);
  if (trace) (*trace)["visual.ln_post"] = pooled;
  return at::matmul(pooled, visual_proj_);
}

at::Tensor ClipModel::encode_text(const at::Tensor& tokens, ClipTrace* trace) const {
  if (tokens.dim() != 2 || tokens.size(1) != config_.arch.context_length)
    throw Error("CLIP encode_text: expected tokens [B, " + std::to_string(config_.arch.context_length) + "], got " +
                shape_str(tokens.sizes()));
  const at::Tensor ids = tokens.to(token_embedding_.device(), at::kLong);
  if (ids.numel() > 0 && (ids.min().item<int64_t>() < 0 || ids.max().item<int64_t>() >= config_.arch.vocab_size))
    throw Error("CLIP encode_text: token id outside [0, " + std::to_string(config_.arch.vocab_size) + ")");
  const int64_t b = ids.size(0);
  at::Tensor x = at::embedding(token_embedding_, ids);  // [B, L, W]
  if (trace) (*trace)["token_embedding"] = x;
  x = x + text_pos_;
  x = run_blocks(x, text_blocks_, config_.transformer_heads, causal_mask_, "transformer.resblocks.", trace);
  x = layer_norm(x, ln_final_w_, ln_final_b_);
  if (trace) (*trace)["ln_final"] = x;
  // Pool at the first position of the largest id (the end-of-text token).
  const at::Tensor eot = ids.argmax(-1);
  const at::Tensor rows = at::arange(b, ids.options()) * x.size(1) + eot;
  const at::Tensor pooled = x.reshape({-1, x.size(2)}).index_select(0, rows);
  if (trace) (*trace)["text_pooled"] = pooled;
  return at::matmul(pooled, text_projection_);
}

at::Tensor ClipModel::logits_per_image(const at::Tensor& image_features, const at::Tensor& text_features) const {
  const at::Tensor img = l2_normalize(image_features.to(at::kFloat));
  const at::Tensor txt = l2_normalize(text_features.to(at::kFloat));
  return logit_scale_ * at::matmul(img, txt.t());
}

}  // namespace cls::clip
