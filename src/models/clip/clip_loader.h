#pragma once
// A CLIP model from a weight file in the reference (OpenAI/OpenCLIP state_dict) names: safetensors,
// torch.save zip or an OpenAI JIT .pt archive (read as a container), via models/weights.
// Names and shapes are checked from the file's header before any tensor is read.
#include <optional>
#include <string>

#include "models/clip/clip_config.h"
#include "models/clip/clip_model.h"

namespace cls {
class WeightFile;
}

namespace cls::clip {

// `config` absent: sizes inferred from the shapes like build_model() (heads = width / 64).
ClipModel load_clip_model(const WeightFile& weights, Activation activation,
                          const std::optional<ClipConfig>& config = std::nullopt, const ClipOptions& options = {});
ClipModel load_clip_model(const std::string& path, Activation activation,
                          const std::optional<ClipConfig>& config = std::nullopt, const ClipOptions& options = {});

}  // namespace cls::clip
