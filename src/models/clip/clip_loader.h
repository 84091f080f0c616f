#pragma once
// A CLIP model from a weight file: safetensors, torch.save zip or an OpenAI JIT .pt archive (read
// as a container, never run), in the OpenAI/OpenCLIP or Hugging Face key layout (models/weights).
// Names and shapes are checked from the file's header before any tensor is read.
#include <optional>
#include <string>

#include "models/clip/clip_config.h"
#include "models/clip/clip_model.h"

namespace cls::clip {

// `config` absent: sizes inferred like build_model() (heads = width / 64) from canonical names, or
// else the preset (ViT-B-32/B-16/L-14) whose layout matches the file exactly.
ClipModel load_clip_model(const WeightFile& weights, Activation activation,
                          const std::optional<ClipConfig>& config = std::nullopt, const ClipOptions& options = {});
ClipModel load_clip_model(const std::string& path, Activation activation,
                          const std::optional<ClipConfig>& config = std::nullopt, const ClipOptions& options = {});

}  // namespace cls::clip
