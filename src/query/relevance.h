#pragma once
// Per-Gaussian scores and per-view relevance maps of text queries (paper 3.3, "Open-Vocabulary
// Querying"; LangSplat's relevancy).
#include <ATen/core/Tensor.h>

#include <functional>
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

// Rows (last dimension) scaled to unit length; zero rows stay zero (their cosine with anything is 0).
at::Tensor unit_rows(const at::Tensor& x);

// Cosine of every pixel's feature with each prototype: features H x W x D, prototypes K x D -> K x H x W.
at::Tensor cosine_maps(const at::Tensor& features, const at::Tensor& prototypes);

// LangSplat's relevancy: for each pixel, min over canonical phrases c of
// softmax(10 * [cos(f, q), cos(f, c)])[0]; features H x W x D, query D, canonical M x D -> H x W.
at::Tensor langsplat_relevancy(const at::Tensor& features, const at::Tensor& query, const at::Tensor& canonical);

// LangSplat's canonical phrases.
const std::vector<std::string>& canonical_phrases();  // "object", "things", "stuff", "texture"

// ---- the building blocks of the above, usable without a whole LanguageModel --------------------

// A function of a batch of latents, B x L -> B x (values per latent): the decoder (B x D, e.g.
// Autoencoder::decode), its hidden layers (B x H) or DecodedCosines (B x P).
using LatentDecoder = std::function<at::Tensor(const at::Tensor&)>;

// The reduced QR factorisation of a linear last layer, weight = Q R (Q: D x k with orthonormal columns,
// R: k x H, k = min(D, H)) and bias = Q c + e (e orthogonal to Q's columns), in double: what
// DecodedCosines needs of a decoder. Q and e stay on the CPU (they project the directions, once per
// DecodedCosines); R and c go to the weight's device as float32.
struct LinearHeadFactors {
  at::Tensor q, e;  // D x k, D: double, CPU
  at::Tensor r, c;  // k x H, k: float32, on the weight's device
  double e_squared = 0;
};
// weight D x H, bias D or undefined (zero); throws cls::Error for other shapes.
LinearHeadFactors factor_linear_head(const at::Tensor& weight, const at::Tensor& bias);

// A latent decoder whose last layer is linear: decode(z) = hidden(z) weight^T + bias (the autoencoder's,
// linear_head_decoder; any output normalisation after it leaves cosines unchanged), the last layer held
// factorised, so that the DecodedCosines of every view and frame share one factorisation.
struct LinearHeadDecoder {
  LatentDecoder hidden;    // B x L -> B x H: every layer before the last
  LinearHeadFactors last;  // factor_linear_head(weight, bias) of the last layer
};
// The autoencoder's decoder in that form. It refers to `autoencoder` (its hidden layers by reference),
// which must outlive it and not be assigned another model or trained meanwhile: make it where it is used.
LinearHeadDecoder linear_head_decoder(const Autoencoder& autoencoder);

// Cosines of decoded latents with fixed directions, without forming the D-d features. With the last
// layer's factors (LinearHeadFactors) and u = R h + c:
//   <p, W h + b> = <Q^T p, u> + <p, e>,   |W h + b|^2 = |u|^2 + |e|^2,
// so a latent costs k x H multiply-adds after the hidden layers instead of D x H: 256 x 256 instead of
// 512 x 256 for the 128 -> 256 -> 512 decoder.
class DecodedCosines {
 public:
  // directions: P x D (any lengths; a zero direction gives cosine 0). Throws cls::Error for a shape that
  // does not fit the decoder.
  DecodedCosines(LinearHeadDecoder decoder, const at::Tensor& directions);
  // B x L latents -> B x P cosines (float32, on the weight's device); 0 where decode(z) = 0.
  at::Tensor operator()(const at::Tensor& latents) const;

 private:
  LinearHeadDecoder decoder_;        // u = h R^T + c with its last layer's factors
  at::Tensor q_directions_, e_dot_;  // P x k (Q^T p, p unit), P (<p, e>)
};

// Pixels decoded per call of the decoder (bounds the MLP's intermediate memory). On the CPU 8192 x 512
// floats = 16 MB (render_decoded's full features; relevance_maps' largest are 8192 x 256): the largest
// tensor of a call stays under glibc's 32 MB mmap ceiling, so the chunks reuse
// freed heap instead of mapping and faulting in fresh pages per call (65,536 pixels: 128 MB, and a
// third of a 1080p map's CPU time went to the kernel; docs/benchmarks.md). On a GPU the cost per call is
// the launches and their waits: 262,144 pixels decode a 1080p map in 8 calls, about 1 GB each in
// relevance_maps (latents, hidden layer, R h) and 0.5 GB more of features in render_decoded
// (2.8x the maps per second of 8,192 on an H100; docs/benchmarks.md, "GPU, third round").
constexpr int64_t kDecodeChunkPixels = 1 << 13;
constexpr int64_t kDecodeChunkPixelsGpu = 1 << 18;
// The chunk for latents on `device`: kDecodeChunkPixels on the CPU, kDecodeChunkPixelsGpu elsewhere.
int64_t decode_chunk_pixels(const at::Device& device);

// rasterize_features of `latents` (N x L, one row per Gaussian of `gaussians`) for a camera and pose
// on a zero background, no gradients: image H x W x L, alpha H x W.
struct RenderedLatents {
  at::Tensor latents;  // H x W x L
  at::Tensor alpha;    // H x W
};
RenderedLatents render_latents(const GaussianModel& gaussians, const at::Tensor& latents,
                               const PinholeCamera& camera, const Pose& pose);

// render_latents followed by `decode` per chunk of the pixels with alpha > 0; the others hold exactly zero
// latents (nothing blended over the zero background) and get decode(0), computed once. Features H x W x D
// (float32), alpha. chunk_pixels 0: decode_chunk_pixels of the latents' device.
DecodedView render_decoded(const GaussianModel& gaussians, const at::Tensor& latents, const LatentDecoder& decode,
                           const PinholeCamera& camera, const Pose& pose, int64_t chunk_pixels = 0);

// LangSplat's relevancy from cosines: query_cos (...), canonical_cos (..., M) -> (...):
// min_c softmax(10 * [query_cos, canonical_cos_c])[0] (OpenCLIPNetwork.get_relevancy).
at::Tensor relevancy_from_cosines(const at::Tensor& query_cos, const at::Tensor& canonical_cos);

// Both maps of K queries for one view, computed chunk by chunk with DecodedCosines, so that no decoded
// feature is formed (what `query`, `render` and `evaluate` use; equal to cosine_maps / langsplat_relevancy
// of render_decoded up to rounding): queries K x D, canonical M x D (feature space) -> cosine and
// relevancy K x H x W. chunk_pixels 0: decode_chunk_pixels of the latents' device.
struct RelevanceMaps {
  at::Tensor cosine;     // K x H x W
  at::Tensor relevancy;  // K x H x W
  at::Tensor alpha;      // H x W, the rendered alpha
};
RelevanceMaps relevance_maps(const GaussianModel& gaussians, const at::Tensor& latents, const LinearHeadDecoder& decoder,
                             const PinholeCamera& camera, const Pose& pose, const at::Tensor& queries,
                             const at::Tensor& canonical, int64_t chunk_pixels = 0);

// ---- the sparse field (language/sparse_field.h) ------------------------------------------------
// Its weights splatted (K per Gaussian) into an L-channel map (rasterize_sparse_features), no gradients.
RenderedLatents render_sparse(const GaussianModel& gaussians, const SparseLevel& level, const PinholeCamera& camera,
                              const Pose& pose);
// The cosines of the rendered weights' features (weights times the codebook) with P directions (P x D), taken in
// the rasterizer's tiles (rasterize_sparse_cosines) without the L-channel map (0 where nothing is blended). CPU
// only (cls::Error on a GPU's Gaussians).
struct RenderedCosines {
  at::Tensor cosine;  // H x W x P
  at::Tensor alpha;   // H x W
};
RenderedCosines render_sparse_cosines(const GaussianModel& gaussians, const SparseLevel& level,
                                      const PinholeCamera& camera, const Pose& pose, const at::Tensor& directions);
// The codebook (L x D) as a decoder of rendered weights: no hidden layer, the last layer the codebook's
// transpose without bias, so DecodedCosines costs L x L per pixel (|B^T w| through B^T's QR factors).
LinearHeadDecoder codebook_decoder(const at::Tensor& codebook);
// relevance_maps of a sparse level: the rendered weights' cosines with the queries, never forming D-d features:
// on the CPU in the rasterizer's tiles (render_sparse_cosines), elsewhere from the rendered weight map through
// DecodedCosines (chunk_pixels as above; the CPU path has no chunks).
RelevanceMaps relevance_maps(const GaussianModel& gaussians, const SparseLevel& level, const PinholeCamera& camera,
                             const Pose& pose, const at::Tensor& queries, const at::Tensor& canonical,
                             int64_t chunk_pixels = 0);

// Cosine of every Gaussian's feature at a level (1..3) of either field with each direction: directions P x D ->
// N x P float32 (CPU). Dense: the decoded latent (DecodedCosines); sparse: sparse_cosines.
at::Tensor gaussian_cosines(const LanguageModel& model, int level, const at::Tensor& directions);
// The same for a language model's level (1..3) and a scene view.
RelevanceMaps relevance_maps(const LanguageModel& model, int level, const SceneView& view, const at::Tensor& queries,
                             const at::Tensor& canonical);

}  // namespace cls
