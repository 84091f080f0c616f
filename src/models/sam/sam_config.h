#pragma once
// Hyper-parameters of a Segment Anything model (build_sam.py's _build_sam arguments). Presets for the
// official ViT-B/L/H checkpoints (sam_arch); sam_config_from_json_file reads the fixture's config.json layout.
#include <string>
#include <vector>

#include "models/weights/sam_weights.h"

namespace cls::sam {

// The architecture (shared with the weight layouts, so expected tensor names and shapes come from
// the same numbers the model is built from) plus what only the running model needs.
struct SamConfig : SamArch {
  // ImageEncoderViT switches the official checkpoints all set.
  int in_chans = 3;
  bool qkv_bias = true;
  bool use_abs_pos = true;
  bool use_rel_pos = true;
  // Sam
  float pixel_mean[3] = {123.675f, 116.28f, 103.53f};
  float pixel_std[3] = {58.395f, 57.12f, 57.375f};
  float mask_threshold = 0.0f;
};

// "vit_b", "vit_l", "vit_h" (the official checkpoints; see sam_arch); cls::Error otherwise.
SamConfig sam_config_by_name(const std::string& name);
// The fixture layout (tests/fixtures/sam/config.json): flat keys as in build_sam; throws cls::Error
// naming the file on a missing or mistyped key.
SamConfig sam_config_from_json_file(const std::string& path);

}  // namespace cls::sam
