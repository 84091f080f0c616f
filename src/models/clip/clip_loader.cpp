#include "models/clip/clip_loader.h"

#include <ATen/ATen.h>

#include "models/weights/weight_file.h"

namespace cls::clip {

ClipModel load_clip_model(const WeightFile& weights, Activation activation, const std::optional<ClipConfig>& config,
                          const ClipOptions& options) {
  std::map<std::string, StoredTensor> stored;
  std::map<std::string, std::vector<int64_t>> shapes;
  for (const std::string& name : weights.names()) {
    const TensorInfo& info = weights.info(name);
    stored[name] = {info.shape, at::isFloatingType(info.dtype)};
    shapes[name] = info.shape;
  }
  ClipConfig c = config ? *config : infer_clip_config(shapes, activation);
  c.activation = activation;
  check_clip_weights(c, stored, weights.source());
  std::map<std::string, at::Tensor> state;
  for (const std::string& name : weights.names()) {
    if (name == "input_resolution" || name == "context_length" || name == "vocab_size") continue;
    state[name] = weights.get(name);
  }
  return ClipModel(c, state, options, weights.source());
}

ClipModel load_clip_model(const std::string& path, Activation activation, const std::optional<ClipConfig>& config,
                          const ClipOptions& options) {
  return load_clip_model(load_weight_file(path), activation, config, options);
}

}  // namespace cls::clip
