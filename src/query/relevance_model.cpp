// The LanguageModel forms of the relevance functions (kept apart from relevance.cpp so that the
// building blocks link without the autoencoder's implementation).
#include <ATen/core/grad_mode.h>

#include <string>

#include "core/error.h"
#include "query/relevance.h"

namespace cls {
namespace {

const at::Tensor& level_latents(const LanguageModel& model, int level) {
  if (level < 1 || level > 3) throw Error("language model: level must be 1, 2 or 3, got " + std::to_string(level));
  const at::Tensor& latents = model.latents[static_cast<size_t>(level - 1)];
  if (!latents.defined()) throw Error("language model: no latents for level " + std::to_string(level));
  return latents;
}

}  // namespace

LinearHeadDecoder linear_head_decoder(const Autoencoder& autoencoder) {
  return {[&autoencoder](const at::Tensor& z) { return autoencoder.decode_hidden(z); },
          factor_linear_head(autoencoder.output_weight(), autoencoder.output_bias())};
}

DecodedView render_decoded(const LanguageModel& model, int level, const SceneView& view) {
  return render_decoded(model.gaussians, level_latents(model, level),
                        [&model](const at::Tensor& z) { return model.autoencoder.decode(z); }, view.camera, view.pose);
}

RelevanceMaps relevance_maps(const LanguageModel& model, int level, const SceneView& view, const at::Tensor& queries,
                             const at::Tensor& canonical) {
  return relevance_maps(model.gaussians, level_latents(model, level), linear_head_decoder(model.autoencoder),
                        view.camera, view.pose, queries, canonical);
}

}  // namespace cls
