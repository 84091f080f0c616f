#pragma once
// CLIP ViT weight layouts. Canonical names are OpenAI's CLIP.state_dict() keys, which OpenCLIP
// shares (visual.transformer.resblocks.N.attn.in_proj_weight, visual.proj, text_projection, ...).
// Hugging Face transformers CLIPModel checkpoints (split q/k/v projections, pre_layrnorm,
// nn.Linear projections stored transposed) and OpenAI's TorchScript archives are mapped onto them.
#include <string>
#include <vector>

#include "models/weights/weight_layout.h"

namespace cls {

// The sizes that determine CLIP's tensor shapes (clip/model.py CLIP.__init__ arguments).
struct ClipArch {
  std::string name;  // "ViT-B-32", "ViT-B-16", "ViT-L-14" or "custom"
  int embed_dim = 512;
  int image_resolution = 224;
  int vision_layers = 12;
  int vision_width = 768;
  int vision_patch_size = 16;
  int context_length = 77;
  int vocab_size = 49408;
  int transformer_width = 512;
  int transformer_layers = 12;
};

// "ViT-B-32" | "ViT-B-16" | "ViT-L-14" ('/' for '-' accepted); cls::Error otherwise.
ClipArch clip_arch(const std::string& name);

// Every tensor of CLIP.state_dict() for the architecture, in state_dict order.
std::vector<ExpectedTensor> clip_expected_tensors(const ClipArch& a);

// OpenAI/OpenCLIP and Hugging Face layouts.
std::vector<KeyLayout> clip_layouts();

// Reads any supported container and maps it to the canonical names; all problems at once as a
// cls::Error naming the file and the tensors.
WeightFile load_clip_checkpoint(const std::string& path, const ClipArch& arch);

}  // namespace cls
