#pragma once
// CLIP ViT hyperparameters (openai/CLIP clip/model.py CLIP.__init__ arguments) and the presets
// CityLangSplat uses.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace cls::clip {

// OpenAI's checkpoints use QuickGELU x*sigmoid(1.702x); OpenCLIP's laion ones exact (erf) GELU.
enum class Activation { QuickGelu, Gelu };

struct ClipConfig {
  int embed_dim = 512;
  int image_resolution = 224;
  int vision_layers = 12;
  int vision_width = 768;
  int vision_patch_size = 16;
  int vision_heads = 12;      // reference: vision_width / 64
  int context_length = 77;
  int vocab_size = 49408;
  int transformer_width = 512;
  int transformer_heads = 8;  // build_model(): transformer_width / 64
  int transformer_layers = 12;
  Activation activation = Activation::Gelu;

  int grid_size() const { return image_resolution / vision_patch_size; }
  int vision_tokens() const { return grid_size() * grid_size() + 1; }
};

// Presets: "ViT-B-32", "ViT-B-16", "ViT-L-14" (also with '/'), with the activation given.
ClipConfig clip_preset(const std::string& name, Activation activation);
// The fixture/OpenCLIP-style config.json (keys as in CLIP.__init__, "activation": "gelu"|"quick_gelu",
// optional "vision_heads"/"transformer_heads"); throws cls::Error naming the file.
ClipConfig read_clip_config(const std::string& path);
// build_model(): sizes inferred from the state dict shapes (name -> shape); heads = width / 64.
ClipConfig infer_clip_config(const std::map<std::string, std::vector<int64_t>>& shapes, Activation activation);

Activation parse_activation(const std::string& name);  // "gelu" | "quick_gelu"
const char* activation_name(Activation a);

}  // namespace cls::clip
