#include "models/sam/sam_config.h"

#include <nlohmann/json.hpp>

#include "core/atomic_file.h"
#include "core/error.h"

namespace cls::sam {

SamConfig sam_config_by_name(const std::string& name) {
  SamConfig c;
  static_cast<SamArch&>(c) = sam_arch(name);
  return c;
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
    c.image_size = j.at("img_size").get<int>();
    c.patch_size = j.at("patch_size").get<int>();
    c.encoder_embed_dim = j.at("embed_dim").get<int>();
    c.encoder_depth = j.at("depth").get<int>();
    c.encoder_num_heads = j.at("num_heads").get<int>();
    c.global_attn_indexes = j.at("global_attn_indexes").get<std::vector<int>>();
    c.window_size = j.at("window_size").get<int>();
    c.use_rel_pos = j.at("use_rel_pos").get<bool>();
    c.mlp_ratio = j.at("mlp_ratio").get<float>();
    c.qkv_bias = j.at("qkv_bias").get<bool>();
    c.prompt_embed_dim = j.at("prompt_embed_dim").get<int>();
    c.mask_in_chans = j.at("mask_in_chans").get<int>();
    c.decoder_depth = j.at("decoder_transformer_depth").get<int>();
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
  if (c.patch_size <= 0 || c.image_size % c.patch_size != 0 || c.encoder_embed_dim % c.encoder_num_heads != 0)
    fail(path, "inconsistent SAM config (img_size/patch_size/embed_dim/num_heads)");
  // The neck's output is the prompt embedding: the official code builds both from one number.
  if (j.contains("out_chans") && j["out_chans"] != c.prompt_embed_dim)
    fail(path, "out_chans must equal prompt_embed_dim");
  return c;
}

}  // namespace cls::sam
