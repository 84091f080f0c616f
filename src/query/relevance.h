#pragma once
// Per-Gaussian scores and per-view relevance maps of text queries (paper 3.3, "Open-Vocabulary
// Querying"; LangSplat's relevancy).
#include <ATen/core/Tensor.h>

#include <vector>

#include "language/language_model.h"
#include "scene/scene.h"

namespace cls {

// s_i = <q, g_i> / (|q| |g_i|) for every Gaussian: latents N x L, query L -> N (0 where |g_i| = 0).
at::Tensor gaussian_scores(const at::Tensor& latents, const at::Tensor& query_latent);

// The level's latents rendered for a view (geometry of the model) and decoded per pixel:
// H x W x D float32 (D = the autoencoder's input size), plus the rendered alpha H x W.
struct DecodedView {
  at::Tensor features;  // H x W x D
  at::Tensor alpha;     // H x W
};
DecodedView render_decoded(const LanguageModel& model, int level, const SceneView& view);

// Cosine of every pixel's feature with each prototype: features H x W x D, prototypes K x D -> K x H x W.
at::Tensor cosine_maps(const at::Tensor& features, const at::Tensor& prototypes);

// LangSplat's relevancy: for each pixel, min over canonical phrases c of
// softmax(10 * [cos(f, q), cos(f, c)])[0]; features H x W x D, query D, canonical M x D -> H x W.
at::Tensor langsplat_relevancy(const at::Tensor& features, const at::Tensor& query, const at::Tensor& canonical);

// LangSplat's canonical phrases.
const std::vector<std::string>& canonical_phrases();  // "object", "things", "stuff", "texture"

}  // namespace cls
