#pragma once
// Hyper-parameters of a Segment Anything model (build_sam.py's _build_sam arguments). Presets for the
// official ViT-B/L/H checkpoints; from_json reads the fixture's config.json layout.
#include <string>
#include <vector>

namespace cls::sam {

struct SamConfig {
  // ImageEncoderViT
  int img_size = 1024;
  int patch_size = 16;
  int in_chans = 3;
  int embed_dim = 768;
  int depth = 12;
  int num_heads = 12;
  double mlp_ratio = 4.0;
  bool qkv_bias = true;
  bool use_abs_pos = true;
  bool use_rel_pos = true;
  int window_size = 14;
  std::vector<int> global_attn_indexes{2, 5, 8, 11};
  int out_chans = 256;  // neck output = prompt embedding dim
  // PromptEncoder / MaskDecoder
  int prompt_embed_dim = 256;
  int mask_in_chans = 16;
  int decoder_transformer_depth = 2;
  int decoder_mlp_dim = 2048;
  int decoder_num_heads = 8;
  int attention_downsample_rate = 2;
  int num_multimask_outputs = 3;
  int iou_head_depth = 3;
  int iou_head_hidden_dim = 256;
  // Sam
  float pixel_mean[3] = {123.675f, 116.28f, 103.53f};
  float pixel_std[3] = {58.395f, 57.12f, 57.375f};
  float mask_threshold = 0.0f;

  int embedding_size() const { return img_size / patch_size; }  // 64: side of the image embedding
};

SamConfig sam_vit_b();
SamConfig sam_vit_l();
SamConfig sam_vit_h();
// "vit_b", "vit_l", "vit_h"; throws cls::Error otherwise.
SamConfig sam_config_by_name(const std::string& name);
// The fixture layout (tests/fixtures/sam/config.json): flat keys as in build_sam; throws cls::Error
// naming the file on a missing or mistyped key.
SamConfig sam_config_from_json_file(const std::string& path);

}  // namespace cls::sam
