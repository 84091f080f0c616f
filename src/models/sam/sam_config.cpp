#include "models/sam/sam_config.h"

#include <nlohmann/json.hpp>

#include "core/atomic_file.h"
#include "core/error.h"

namespace cls::sam {

namespace {
SamConfig official(int embed_dim, int depth, int num_heads, std::vector<int> global_attn_indexes) {
  SamConfig c;
  c.embed_dim = embed_dim;
  c.depth = depth;
  c.num_heads = num_heads;
  c.global_attn_indexes = std::move(global_attn_indexes);
  return c;
}
}  // namespace

SamConfig sam_vit_b() { return official(768, 12, 12, {2, 5, 8, 11}); }
SamConfig sam_vit_l() { return official(1024, 24, 16, {5, 11, 17, 23}); }
SamConfig sam_vit_h() { return official(1280, 32, 16, {7, 15, 23, 31}); }

SamConfig sam_config_by_name(const std::string& name) {
  if (name == "vit_b") return sam_vit_b();
  if (name == "vit_l") return sam_vit_l();
  if (name == "vit_h") return sam_vit_h();
  throw Error("unknown SAM model '" + name + "' (expected vit_b, vit_l or vit_h)");
}

SamConfig sam_config_from_json_file(const std::string& path) {
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(read_text_file(path));
  } catch (const nlohmann::json::exception& e) {
    fail(path, std::string("not valid JSON: ") + e.what());
  }
  SamConfig c;
  try {
    c.img_size = j.at("img_size").get<int>();
    c.patch_size = j.at("patch_size").get<int>();
    c.embed_dim = j.at("embed_dim").get<int>();
    c.depth = j.at("depth").get<int>();
    c.num_heads = j.at("num_heads").get<int>();
    c.global_attn_indexes = j.at("global_attn_indexes").get<std::vector<int>>();
    c.window_size = j.at("window_size").get<int>();
    c.use_rel_pos = j.at("use_rel_pos").get<bool>();
    c.mlp_ratio = j.at("mlp_ratio").get<double>();
    c.qkv_bias = j.at("qkv_bias").get<bool>();
    c.out_chans = j.at("out_chans").get<int>();
    c.prompt_embed_dim = j.at("prompt_embed_dim").get<int>();
    c.mask_in_chans = j.at("mask_in_chans").get<int>();
    c.decoder_transformer_depth = j.at("decoder_transformer_depth").get<int>();
    c.decoder_mlp_dim = j.at("decoder_mlp_dim").get<int>();
    c.decoder_num_heads = j.at("decoder_num_heads").get<int>();
    c.iou_head_depth = j.at("iou_head_depth").get<int>();
    c.iou_head_hidden_dim = j.at("iou_head_hidden_dim").get<int>();
    c.num_multimask_outputs = j.at("num_multimask_outputs").get<int>();
    const auto mean = j.at("pixel_mean").get<std::vector<double>>();
    const auto std_ = j.at("pixel_std").get<std::vector<double>>();
    if (mean.size() != 3 || std_.size() != 3) fail(path, "pixel_mean/pixel_std need 3 values");
    for (int k = 0; k < 3; ++k) c.pixel_mean[k] = float(mean[k]), c.pixel_std[k] = float(std_[k]);
    if (j.contains("mask_threshold")) c.mask_threshold = j.at("mask_threshold").get<float>();
  } catch (const nlohmann::json::exception& e) {
    fail(path, std::string("bad SAM config: ") + e.what());
  }
  if (c.patch_size <= 0 || c.img_size % c.patch_size != 0 || c.embed_dim % c.num_heads != 0)
    fail(path, "inconsistent SAM config (img_size/patch_size/embed_dim/num_heads)");
  return c;
}

}  // namespace cls::sam
