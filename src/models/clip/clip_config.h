#pragma once
// CLIP ViT hyperparameters: the tensor sizes (ClipArch, models/weights/clip_weights.h, which also
// holds the ViT-B-32/B-16/L-14 presets and the expected state_dict) plus what the weights do not
// store: head counts and the MLP activation.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "models/weights/clip_weights.h"

namespace cls::clip {

// OpenAI's checkpoints use QuickGELU x*sigmoid(1.702x); OpenCLIP's laion ones exact (erf) GELU.
enum class Activation { QuickGelu, Gelu };

struct ClipConfig {
  ClipArch arch;
  int vision_heads = 12;      // reference: vision_width / 64
  int transformer_heads = 8;  // build_model(): transformer_width / 64
  Activation activation = Activation::Gelu;

  int grid_size() const { return arch.image_resolution / arch.vision_patch_size; }
  int vision_tokens() const { return grid_size() * grid_size() + 1; }
};

// The sizes with the reference's head rule (width / 64, at least 1).
ClipConfig clip_config(const ClipArch& arch, Activation activation);
// Presets "ViT-B-32", "ViT-B-16", "ViT-L-14" (also with '/').
ClipConfig clip_preset(const std::string& name, Activation activation);
// The fixture/OpenCLIP-style config.json (keys as in CLIP.__init__, "activation": "gelu"|"quick_gelu",
// optional "vision_heads"/"transformer_heads"); throws cls::Error naming the file.
ClipConfig read_clip_config(const std::string& path);
// build_model(): sizes inferred from canonical state_dict shapes (name -> shape).
ClipConfig infer_clip_config(const std::map<std::string, std::vector<int64_t>>& shapes, Activation activation);

Activation parse_activation(const std::string& name);  // "gelu" | "quick_gelu"
const char* activation_name(Activation a);

}  // namespace cls::clip
