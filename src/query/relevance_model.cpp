// The LanguageModel forms of the relevance functions (kept apart from relevance.cpp so that the
// building blocks link without the autoencoder's implementation).
#include <ATen/core/grad_mode.h>
#include <torch/types.h>

#include <algorithm>
#include <string>

#include "core/error.h"
#include "query/relevance.h"

namespace cls {
namespace {

void check_level(const LanguageModel& model, int level) {
  if (level < 1 || level > 3) throw Error("language model: level must be 1, 2 or 3, got " + std::to_string(level));
  if (!model.has_level(level)) throw Error("language model: no field at level " + std::to_string(level));
}

const at::Tensor& level_latents(const LanguageModel& model, int level) {
  check_level(model, level);
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
  if (model.is_sparse()) {
    check_level(model, level);
    const SparseLevel& s = model.sparse[size_t(level - 1)];
    return render_decoded(model.gaussians, scattered_weights(s), [&s](const at::Tensor& w) { return torch::matmul(w, s.codebook); },
                          view.camera, view.pose);
  }
  const Autoencoder& ae = model.dense_autoencoder("render_decoded");
  return render_decoded(model.gaussians, level_latents(model, level), [&ae](const at::Tensor& z) { return ae.decode(z); },
                        view.camera, view.pose);
}

RelevanceMaps relevance_maps(const LanguageModel& model, int level, const SceneView& view, const at::Tensor& queries,
                             const at::Tensor& canonical) {
  if (model.is_sparse()) {
    check_level(model, level);
    return relevance_maps(model.gaussians, model.sparse[size_t(level - 1)], view.camera, view.pose, queries, canonical);
  }
  return relevance_maps(model.gaussians, level_latents(model, level), linear_head_decoder(*model.autoencoder),
                        view.camera, view.pose, queries, canonical);
}

at::Tensor gaussian_cosines(const LanguageModel& model, int level, const at::Tensor& directions) {
  at::NoGradGuard no_grad;
  if (model.is_sparse()) {
    check_level(model, level);
    return sparse_cosines(model.sparse[size_t(level - 1)], directions);
  }
  const at::Tensor& z = level_latents(model, level);
  const int64_t N = z.size(0);
  const DecodedCosines cosines(linear_head_decoder(*model.autoencoder), directions);
  at::Tensor out = torch::empty({N, directions.size(0)}, torch::kFloat32);
  constexpr int64_t kChunk = 1 << 16;  // Gaussians per call: bounds the hidden layer's memory
  for (int64_t b = 0; b < N; b += kChunk) {
    const int64_t e = std::min(N, b + kChunk);
    out.slice(0, b, e).copy_(cosines(z.slice(0, b, e)).cpu());
  }
  return out;
}

}  // namespace cls
