#include "models/clip/clip_loader.h"

#include "core/error.h"
#include "models/weights/clip_weights.h"
#include "models/weights/weight_layout.h"

namespace cls::clip {

ClipModel load_clip_model(const WeightFile& weights, Activation activation, const std::optional<ClipConfig>& config,
                          const ClipOptions& options) {
  if (config) {
    ClipConfig c = *config;
    c.activation = activation;
    return ClipModel(c, weights, options);
  }
  std::map<std::string, std::vector<int64_t>> shapes;
  for (const std::string& name : weights.names()) shapes[name] = weights.info(name).shape;
  try {
    return ClipModel(infer_clip_config(shapes, activation), weights, options);
  } catch (const Error&) {
    // Not canonical names (or not a complete canonical set): try the known architectures.
  }
  for (const char* preset : {"ViT-B-32", "ViT-B-16", "ViT-L-14"}) {
    const ClipArch arch = clip_arch(preset);
    if (map_weights(weights, clip_expected_tensors(arch), clip_layouts()).report.ok())
      return ClipModel(clip_config(arch, activation), weights, options);
  }
  // Report against the closest preset, naming every problem.
  return ClipModel(clip_preset("ViT-B-16", activation), weights, options);
}

ClipModel load_clip_model(const std::string& path, Activation activation, const std::optional<ClipConfig>& config,
                          const ClipOptions& options) {
  return load_clip_model(load_weight_file(path), activation, config, options);
}

}  // namespace cls::clip
