#pragma once
// SAM (segment-anything) weight layouts. Canonical names are the official Sam.state_dict() keys
// (image_encoder.blocks.N.attn.qkv.weight, rel_pos_h/w, prompt_encoder.*, mask_decoder.*); Hugging
// Face transformers SamModel checkpoints (vision_encoder.layers.N.layer_norm1, mask_embed.conv1,
// upscale_conv1, proj_in/proj_out ...) are mapped onto them.
#include <string>
#include <vector>

#include "models/weights/weight_layout.h"

namespace cls {

struct SamArch {
  std::string name;            // "vit_b", "vit_l", "vit_h" or "custom"
  int image_size = 1024;
  int patch_size = 16;
  int encoder_embed_dim = 768;
  int encoder_depth = 12;
  int encoder_num_heads = 12;
  std::vector<int> global_attn_indexes = {2, 5, 8, 11};
  int window_size = 14;
  float mlp_ratio = 4.f;
  int prompt_embed_dim = 256;  // = neck out_chans = decoder transformer_dim
  int mask_in_chans = 16;
  int decoder_depth = 2;
  int decoder_num_heads = 8;
  int decoder_mlp_dim = 2048;
  int attention_downsample_rate = 2;
  int num_multimask_outputs = 3;
  int iou_head_depth = 3;
  int iou_head_hidden_dim = 256;

  int image_embedding_size() const { return image_size / patch_size; }  // 64
};

// "vit_b" | "vit_l" | "vit_h" (also "sam_vit_b", "ViT-B" ...); cls::Error for anything else.
SamArch sam_arch(const std::string& name);

// Every tensor of Sam.state_dict() for the config, in state_dict order.
std::vector<ExpectedTensor> sam_expected_tensors(const SamArch& c);

// The official and the Hugging Face layouts.
std::vector<KeyLayout> sam_layouts();
// The Hugging Face name of an official key (the inverse of what the loader does), e.g.
// "image_encoder.blocks.0.norm1.weight" -> "vision_encoder.layers.0.layer_norm1.weight".
std::string sam_official_to_hf(const std::string& official);

// Reads any supported container and maps it to the official names; all problems at once as a
// cls::Error naming the file and the tensors.
WeightFile load_sam_checkpoint(const std::string& path, const SamArch& arch);

}  // namespace cls
