#include "models/weights/sam_weights.h"

#include <algorithm>
#include <cctype>
#include <regex>

#include "core/error.h"

namespace cls {

SamArch sam_arch(const std::string& name) {
  std::string n;
  for (const char ch : name) n += ch == '-' ? '_' : static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  if (n.rfind("sam_", 0) == 0) n = n.substr(4);
  SamArch c;
  if (n == "vit_b") {
    c.encoder_embed_dim = 768, c.encoder_depth = 12, c.encoder_num_heads = 12, c.global_attn_indexes = {2, 5, 8, 11};
  } else if (n == "vit_l") {
    c.encoder_embed_dim = 1024, c.encoder_depth = 24, c.encoder_num_heads = 16, c.global_attn_indexes = {5, 11, 17, 23};
  } else if (n == "vit_h") {
    c.encoder_embed_dim = 1280, c.encoder_depth = 32, c.encoder_num_heads = 16, c.global_attn_indexes = {7, 15, 23, 31};
  } else {
    throw Error("unknown SAM model '" + name + "' (known: vit_b, vit_l, vit_h)");
  }
  c.name = n;
  return c;
}

std::vector<ExpectedTensor> sam_expected_tensors(const SamArch& c) {
  std::vector<ExpectedTensor> t;
  auto add = [&](const std::string& name, std::vector<int64_t> shape) { t.push_back({name, std::move(shape)}); };
  auto norm = [&](const std::string& name, int64_t dim) {
    add(name + ".weight", {dim});
    add(name + ".bias", {dim});
  };
  auto linear = [&](const std::string& name, int64_t out, int64_t in) {
    add(name + ".weight", {out, in});
    add(name + ".bias", {out});
  };
  // Image encoder (ImageEncoderViT).
  const int64_t d = c.encoder_embed_dim, grid = c.image_embedding_size(), p = c.patch_size;
  const int64_t head_dim = d / c.encoder_num_heads, hidden = static_cast<int64_t>(d * c.mlp_ratio);
  const int64_t e = c.prompt_embed_dim;
  add("image_encoder.pos_embed", {1, grid, grid, d});
  add("image_encoder.patch_embed.proj.weight", {d, 3, p, p});
  add("image_encoder.patch_embed.proj.bias", {d});
  for (int i = 0; i < c.encoder_depth; ++i) {
    const std::string b = "image_encoder.blocks." + std::to_string(i);
    const bool global = std::count(c.global_attn_indexes.begin(), c.global_attn_indexes.end(), i) > 0;
    const int64_t span = global ? grid : c.window_size;  // rel_pos covers 2*size-1 offsets
    norm(b + ".norm1", d);
    add(b + ".attn.rel_pos_h", {2 * span - 1, head_dim});
    add(b + ".attn.rel_pos_w", {2 * span - 1, head_dim});
    linear(b + ".attn.qkv", 3 * d, d);
    linear(b + ".attn.proj", d, d);
    norm(b + ".norm2", d);
    linear(b + ".mlp.lin1", hidden, d);
    linear(b + ".mlp.lin2", d, hidden);
  }
  add("image_encoder.neck.0.weight", {e, d, 1, 1});
  norm("image_encoder.neck.1", e);
  add("image_encoder.neck.2.weight", {e, e, 3, 3});
  norm("image_encoder.neck.3", e);
  // Prompt encoder.
  add("prompt_encoder.pe_layer.positional_encoding_gaussian_matrix", {2, e / 2});
  for (int i = 0; i < 4; ++i) add("prompt_encoder.point_embeddings." + std::to_string(i) + ".weight", {1, e});
  add("prompt_encoder.not_a_point_embed.weight", {1, e});
  const int64_t m = c.mask_in_chans;
  add("prompt_encoder.mask_downscaling.0.weight", {m / 4, 1, 2, 2});
  add("prompt_encoder.mask_downscaling.0.bias", {m / 4});
  norm("prompt_encoder.mask_downscaling.1", m / 4);
  add("prompt_encoder.mask_downscaling.3.weight", {m, m / 4, 2, 2});
  add("prompt_encoder.mask_downscaling.3.bias", {m});
  norm("prompt_encoder.mask_downscaling.4", m);
  add("prompt_encoder.mask_downscaling.6.weight", {e, m, 1, 1});
  add("prompt_encoder.mask_downscaling.6.bias", {e});
  add("prompt_encoder.no_mask_embed.weight", {1, e});
  // Mask decoder (TwoWayTransformer + heads).
  const int64_t inner = e / c.attention_downsample_rate;
  auto attention = [&](const std::string& name, int64_t internal) {
    linear(name + ".q_proj", internal, e);
    linear(name + ".k_proj", internal, e);
    linear(name + ".v_proj", internal, e);
    linear(name + ".out_proj", e, internal);
  };
  for (int i = 0; i < c.decoder_depth; ++i) {
    const std::string l = "mask_decoder.transformer.layers." + std::to_string(i);
    attention(l + ".self_attn", e);
    norm(l + ".norm1", e);
    attention(l + ".cross_attn_token_to_image", inner);
    norm(l + ".norm2", e);
    linear(l + ".mlp.lin1", c.decoder_mlp_dim, e);
    linear(l + ".mlp.lin2", e, c.decoder_mlp_dim);
    norm(l + ".norm3", e);
    norm(l + ".norm4", e);
    attention(l + ".cross_attn_image_to_token", inner);
  }
  attention("mask_decoder.transformer.final_attn_token_to_image", inner);
  norm("mask_decoder.transformer.norm_final_attn", e);
  const int64_t tokens = c.num_multimask_outputs + 1;
  add("mask_decoder.iou_token.weight", {1, e});
  add("mask_decoder.mask_tokens.weight", {tokens, e});
  add("mask_decoder.output_upscaling.0.weight", {e, e / 4, 2, 2});
  add("mask_decoder.output_upscaling.0.bias", {e / 4});
  norm("mask_decoder.output_upscaling.1", e / 4);
  add("mask_decoder.output_upscaling.3.weight", {e / 4, e / 8, 2, 2});
  add("mask_decoder.output_upscaling.3.bias", {e / 8});
  for (int64_t k = 0; k < tokens; ++k) {
    const std::string h = "mask_decoder.output_hypernetworks_mlps." + std::to_string(k) + ".layers.";
    linear(h + "0", e, e);
    linear(h + "1", e, e);
    linear(h + "2", e / 8, e);
  }
  for (int k = 0; k < c.iou_head_depth; ++k) {
    const bool last = k == c.iou_head_depth - 1;
    linear("mask_decoder.iou_prediction_head.layers." + std::to_string(k), last ? tokens : c.iou_head_hidden_dim,
           k == 0 ? e : c.iou_head_hidden_dim);
  }
  return t;
}

// transformers' SamModel names. Their converter renames official keys by substring, in this
// order; we apply the same renames to our canonical names (and the MLP-head index shift).
std::string sam_official_to_hf(const std::string& official) {
  static const std::vector<std::pair<std::string, std::string>> kRenames = {
      {"iou_prediction_head.layers.0", "iou_prediction_head.proj_in"},
      {"iou_prediction_head.layers.1", "iou_prediction_head.layers.0"},
      {"iou_prediction_head.layers.2", "iou_prediction_head.proj_out"},
      {"mask_decoder.output_upscaling.0", "mask_decoder.upscale_conv1"},
      {"mask_decoder.output_upscaling.1", "mask_decoder.upscale_layer_norm"},
      {"mask_decoder.output_upscaling.3", "mask_decoder.upscale_conv2"},
      {"mask_downscaling.0", "mask_embed.conv1"},
      {"mask_downscaling.1", "mask_embed.layer_norm1"},
      {"mask_downscaling.3", "mask_embed.conv2"},
      {"mask_downscaling.4", "mask_embed.layer_norm2"},
      {"mask_downscaling.6", "mask_embed.conv3"},
      {"point_embeddings", "point_embed"},
      {"pe_layer.positional_encoding_gaussian_matrix", "shared_embedding.positional_embedding"},
      {"image_encoder", "vision_encoder"},
      {"neck.0", "neck.conv1"},
      {"neck.1", "neck.layer_norm1"},
      {"neck.2", "neck.conv2"},
      {"neck.3", "neck.layer_norm2"},
      {"patch_embed.proj", "patch_embed.projection"},
      {".norm", ".layer_norm"},
      {"blocks", "layers"},
  };
  std::string key = official;
  for (const auto& [from, to] : kRenames) {
    for (size_t at = key.find(from); at != std::string::npos; at = key.find(from, at + to.size()))
      key.replace(at, from.size(), to);
  }
  static const std::regex hyper(R"(output_hypernetworks_mlps\.(\d+)\.layers\.([012])\.)");
  std::smatch m;
  if (std::regex_search(key, m, hyper)) {
    const std::string layer = m[2].str();
    const std::string repl = layer == "0" ? "proj_in." : layer == "1" ? "layers.0." : "proj_out.";
    key.replace(static_cast<size_t>(m.position(0)), static_cast<size_t>(m.length(0)),
                "output_hypernetworks_mlps." + m[1].str() + "." + repl);
  }
  return key;
}

std::vector<KeyLayout> sam_layouts() {
  KeyLayout official{"official",
                     [](const std::string& c) { return TensorRecipe{{c}, TensorRecipe::Op::Same}; },
                     [](const std::string& s) { return s == "pixel_mean" || s == "pixel_std"; }};
  // The positional-encoding matrix is shared in SamModel: saved as
  // shared_image_embedding.positional_embedding and/or prompt_encoder.shared_embedding.*.
  KeyLayout hf{"huggingface",
               [](const std::string& c) {
                 if (c == "prompt_encoder.pe_layer.positional_encoding_gaussian_matrix")
                   return TensorRecipe{{"shared_image_embedding.positional_embedding"},
                                       TensorRecipe::Op::Same,
                                       {"prompt_encoder.shared_embedding.positional_embedding"}};
                 return TensorRecipe{{sam_official_to_hf(c)}, TensorRecipe::Op::Same};
               },
               [](const std::string& s) {
                 return s == "prompt_encoder.shared_embedding.positional_embedding" || s == "pixel_mean" ||
                        s == "pixel_std";
               }};
  return {official, hf};
}

WeightFile load_sam_checkpoint(const std::string& path, const SamArch& arch) {
  return map_weights_strict(load_weight_file(path), sam_expected_tensors(arch), sam_layouts(),
                            "SAM " + arch.name);
}

}  // namespace cls
