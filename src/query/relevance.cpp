#include "query/relevance.h"

#include <ATen/core/grad_mode.h>
#include <torch/types.h>

#include <string>

#include "core/error.h"
#include "models/parallel_linear.h"
#include "splat/rasterize.h"

namespace cls {
namespace {

std::string shape_of(const at::Tensor& t) { return t.defined() ? c10::str(t.sizes()) : "undefined"; }

void check_features(const at::Tensor& features, const char* fn) {
  if (!features.defined() || features.dim() != 3)
    throw Error(std::string(fn) + ": features must be H x W x D, got " + shape_of(features));
}

void check_rows(const at::Tensor& rows, int64_t dim, const char* fn, const char* what) {
  if (!rows.defined() || rows.dim() != 2 || rows.size(1) != dim)
    throw Error(std::string(fn) + ": " + what + " must be K x " + std::to_string(dim) + ", got " + shape_of(rows));
}

}  // namespace

at::Tensor unit_rows(const at::Tensor& x) {
  const at::Tensor n = x.norm(2, {-1}, /*keepdim=*/true);
  return torch::where(n > 0, x / n, torch::zeros_like(x));
}

at::Tensor gaussian_scores(const at::Tensor& latents, const at::Tensor& query_latent) {
  if (!latents.defined() || latents.dim() != 2)
    throw Error("gaussian_scores: latents must be N x L, got " + shape_of(latents));
  if (!query_latent.defined() || query_latent.dim() != 1 || query_latent.size(0) != latents.size(1))
    throw Error("gaussian_scores: query latent must have " + std::to_string(latents.size(1)) + " values, got " +
                shape_of(query_latent));
  at::NoGradGuard no_grad;
  // s_i = <q, g_i> / (|q| |g_i|) (paper 3.3), in double so that the ranking of near-equal scores is stable.
  const at::Tensor g = latents.to(torch::kFloat64), q = query_latent.to(latents.device(), torch::kFloat64);
  const at::Tensor dot = g.matmul(q);
  const at::Tensor denom = g.norm(2, {1}) * q.norm();
  return torch::where(denom > 0, dot / denom, torch::zeros_like(dot)).to(torch::kFloat32);
}

at::Tensor cosine_maps(const at::Tensor& features, const at::Tensor& prototypes) {
  check_features(features, "cosine_maps");
  const int64_t H = features.size(0), W = features.size(1), D = features.size(2);
  check_rows(prototypes, D, "cosine_maps", "prototypes");
  at::NoGradGuard no_grad;
  const at::Tensor f = unit_rows(features.reshape({H * W, D}).to(torch::kFloat32));
  const at::Tensor p = unit_rows(prototypes.to(features.device(), torch::kFloat32));
  return p.matmul(f.t()).reshape({prototypes.size(0), H, W});
}

at::Tensor relevancy_from_cosines(const at::Tensor& query_cos, const at::Tensor& canonical_cos) {
  if (!query_cos.defined() || !canonical_cos.defined() || canonical_cos.dim() != query_cos.dim() + 1 ||
      canonical_cos.sizes().slice(0, query_cos.dim()) != query_cos.sizes() || canonical_cos.size(-1) == 0)
    throw Error("langsplat relevancy: canonical cosines must be (query shape) x M with M > 0, got " +
                shape_of(canonical_cos) + " for " + shape_of(query_cos));
  // OpenCLIPNetwork.get_relevancy: sims = stack(repeated positive, negatives) (... x M x 2),
  // softmax(10 * sims) over the pair, keep the pair whose positive probability is smallest. As
  // softmax(10 [a, b])[0] = sigmoid(10 (a - b)) grows with a - b, that pair is the most similar phrase's:
  // sigmoid(10 (q - max_m c_m)), a pass over the cosines instead of a softmax per pair (which took more
  // than the cosines of a 1080p map; docs/benchmarks.md). The test holds it to the softmax form.
  return torch::sigmoid(10.0 * (query_cos - std::get<0>(canonical_cos.max(-1))));
}

at::Tensor langsplat_relevancy(const at::Tensor& features, const at::Tensor& query, const at::Tensor& canonical) {
  check_features(features, "langsplat_relevancy");
  const int64_t D = features.size(2);
  if (!query.defined() || query.dim() != 1 || query.size(0) != D)
    throw Error("langsplat_relevancy: query must have " + std::to_string(D) + " values, got " + shape_of(query));
  check_rows(canonical, D, "langsplat_relevancy", "canonical phrases");
  if (canonical.size(0) == 0) throw Error("langsplat_relevancy: no canonical phrases");
  at::NoGradGuard no_grad;
  const at::Tensor cos = cosine_maps(features, torch::cat({query.reshape({1, D}), canonical}, 0));  // (1+M) x H x W
  return relevancy_from_cosines(cos[0], cos.slice(0, 1).permute({1, 2, 0}));
}

const std::vector<std::string>& canonical_phrases() {
  static const std::vector<std::string> phrases{"object", "things", "stuff", "texture"};
  return phrases;
}

LinearHeadFactors factor_linear_head(const at::Tensor& W, const at::Tensor& bias) {
  if (!W.defined() || W.dim() != 2)
    throw Error("relevance: the decoder's last layer must have a D x H weight, got " + shape_of(W));
  const int64_t D = W.size(0);
  if (bias.defined() && (bias.dim() != 1 || bias.size(0) != D))
    throw Error("relevance: the decoder's last bias must have " + std::to_string(D) + " values, got " + shape_of(bias));
  at::NoGradGuard no_grad;
  const auto cpu_double = torch::dtype(torch::kFloat64).device(torch::kCPU);
  const at::Tensor w = W.detach().to(cpu_double);
  const at::Tensor b = bias.defined() ? bias.detach().to(cpu_double) : torch::zeros({D}, cpu_double);
  const auto [q, r] = at::linalg_qr(w, "reduced");  // q: D x k, r: k x H
  const at::Tensor c = q.t().matmul(b);
  LinearHeadFactors f;
  f.q = q;
  f.e = b - q.matmul(c);
  const auto on_device = W.options().dtype(torch::kFloat32);
  f.r = r.to(on_device);
  f.c = c.to(on_device);
  f.e_squared = f.e.dot(f.e).item<double>();
  return f;
}

DecodedCosines::DecodedCosines(LinearHeadDecoder decoder, const at::Tensor& directions)
    : decoder_(std::move(decoder)) {
  if (!decoder_.hidden) throw Error("relevance: the decoder has no hidden-layer function");
  const LinearHeadFactors& f = decoder_.last;
  if (!f.q.defined() || !f.r.defined()) throw Error("relevance: the decoder's last layer is not factorised");
  const int64_t D = f.q.size(0);
  if (!directions.defined() || directions.dim() != 2 || directions.size(1) != D)
    throw Error("relevance: the decoder gives " + std::to_string(D) + "-d features, the text features are " +
                shape_of(directions) + " (another feature provider?)");
  at::NoGradGuard no_grad;
  const at::Tensor p = unit_rows(directions.detach().to(f.q.options()));
  q_directions_ = p.matmul(f.q).to(f.r.options());
  e_dot_ = p.matmul(f.e).to(f.r.options());
}

at::Tensor DecodedCosines::operator()(const at::Tensor& latents) const {
  at::NoGradGuard no_grad;
  const LinearHeadFactors& f = decoder_.last;
  const at::Tensor h = decoder_.hidden(latents).to(f.r.device(), torch::kFloat32);
  if (h.dim() != 2 || h.size(0) != latents.size(0) || h.size(1) != f.r.size(1))
    throw Error("relevance: the decoder's hidden layers gave " + shape_of(h) + " for " + shape_of(latents) +
                " latents; its last layer takes " + std::to_string(f.r.size(1)) + " values");
  const auto blas = blas_threads_for_split(h);
  const at::Tensor u = parallel_rows_linear(h, f.r, f.c);                  // B x k
  const at::Tensor dots = parallel_rows_linear(u, q_directions_, e_dot_);  // B x P
  const at::Tensor norm = (u.norm(2, {1}, /*keepdim=*/true).square() + f.e_squared).sqrt();  // one pass over u
  return torch::where(norm > 0, dots / norm, torch::zeros_like(dots));
}

int64_t decode_chunk_pixels(const at::Device& device) {
  return device.is_cpu() ? kDecodeChunkPixels : kDecodeChunkPixelsGpu;
}

RenderedLatents render_latents(const GaussianModel& gaussians, const at::Tensor& latents, const PinholeCamera& camera,
                               const Pose& pose) {
  if (!latents.defined() || latents.dim() != 2 || latents.size(0) != gaussians.size())
    throw Error("render_latents: latents must be " + std::to_string(gaussians.size()) + " x L, got " +
                shape_of(latents));
  at::NoGradGuard no_grad;
  const at::Tensor means = gaussians.means.contiguous();
  RasterizeSettings settings;
  settings.camera = camera;
  settings.pose = pose;
  const RasterizeOutput out =
      rasterize_features(means, gaussians.scales().contiguous(), gaussians.quats.contiguous(),
                         gaussians.opacities().contiguous(), latents.to(means.device(), means.scalar_type()).contiguous(),
                         at::Tensor(), settings);
  return {out.image, out.alpha};
}

namespace {

// Calls `decode` (the decoder, or DecodedCosines) on the rendered latents (P x L) of the pixels with
// alpha > 0, chunk by chunk, and hands each chunk to `sink(rows, values)`: the pixel indices (int64) and
// their values (B x D features or B x P cosines, float32). The other pixels' latents are exactly zero
// (nothing was blended over the zero background, so alpha is 0 only there), so decode(0) is computed once
// and handed over as one row for all of them: values has one row per index, or one row for every index.
// Views with sky or ground cost only their covered pixels.
template <class Sink>
void decode_covered(const at::Tensor& latents, const at::Tensor& alpha, const LatentDecoder& decode, int64_t chunk,
                    Sink&& sink) {
  if (chunk == 0) chunk = decode_chunk_pixels(latents.device());
  if (chunk < 0) throw Error("decoding rendered latents: the chunk size must be positive (or 0: the device's)");
  auto checked = [&](const at::Tensor& d, int64_t rows) {
    if (!d.defined() || d.dim() != 2 || d.size(0) != rows)
      throw Error("decoding rendered latents: the decoder returned " + shape_of(d) + " for " + std::to_string(rows) +
                  " latents");
    return d.to(latents.device(), torch::kFloat32);
  };
  const at::Tensor covered = alpha.reshape({-1}) > 0;
  const at::Tensor rows = covered.nonzero().squeeze(1), empty_rows = covered.logical_not().nonzero().squeeze(1);
  for (int64_t b = 0; b < rows.size(0); b += chunk) {
    const at::Tensor r = rows.slice(0, b, std::min(rows.size(0), b + chunk));
    sink(r, checked(decode(latents.index_select(0, r)), r.size(0)));
  }
  if (empty_rows.size(0) > 0) sink(empty_rows, checked(decode(torch::zeros({1, latents.size(1)}, latents.options())), 1));
}

}  // namespace

DecodedView render_decoded(const GaussianModel& gaussians, const at::Tensor& latents, const LatentDecoder& decode,
                           const PinholeCamera& camera, const Pose& pose, int64_t chunk_pixels) {
  const RenderedLatents r = render_latents(gaussians, latents, camera, pose);
  at::NoGradGuard no_grad;
  const int64_t H = r.latents.size(0), W = r.latents.size(1), L = r.latents.size(2);
  const at::Tensor flat = r.latents.reshape({H * W, L});
  at::Tensor features;
  decode_covered(flat, r.alpha, decode, chunk_pixels, [&](const at::Tensor& rows, const at::Tensor& d) {
    if (!features.defined()) features = torch::empty({H * W, d.size(1)}, d.options());
    if (d.size(1) != features.size(1)) throw Error("render_decoded: the decoder's output size changed between chunks");
    features.index_copy_(0, rows, d.expand({rows.size(0), d.size(1)}));
  });
  if (!features.defined()) features = torch::empty({0, 0}, flat.options().dtype(torch::kFloat32));
  return {features.reshape({H, W, features.size(1)}), r.alpha.to(torch::kFloat32)};
}

namespace {

// A sparse level splatted for a camera and pose, no gradients: `raster` (rasterize_sparse_features' inputs but
// the gradient's means2d) on the level's weights, indices and codebook size, on the Gaussians' device and dtype.
template <class Raster>
RasterizeOutput splat_sparse(const char* what, const GaussianModel& gaussians, const SparseLevel& level,
                             const PinholeCamera& camera, const Pose& pose, Raster&& raster) {
  if (!level.defined() || level.size() != gaussians.size())
    throw Error(std::string(what) + ": the sparse level must have one row per Gaussian (" +
                std::to_string(gaussians.size()) + ")");
  at::NoGradGuard no_grad;
  const at::Tensor means = gaussians.means.contiguous();
  RasterizeSettings settings;
  settings.camera = camera;
  settings.pose = pose;
  return raster(means, gaussians.scales().contiguous(), gaussians.quats.contiguous(), gaussians.opacities().contiguous(),
                level.weights.to(means.device(), means.scalar_type()).contiguous(),
                level.indices.to(means.device()).contiguous(), static_cast<int>(level.codebook.size(0)), settings);
}

}  // namespace

RenderedLatents render_sparse(const GaussianModel& gaussians, const SparseLevel& level, const PinholeCamera& camera,
                              const Pose& pose) {
  const RasterizeOutput out =
      splat_sparse("render_sparse", gaussians, level, camera, pose,
                   [](const auto& m, const auto& s, const auto& q, const auto& o, const auto& w, const auto& i, int c,
                      const RasterizeSettings& settings) {
                     return rasterize_sparse_features(m, s, q, o, w, i, c, at::Tensor(), settings);
                   });
  return {out.image, out.alpha};
}

RenderedCosines render_sparse_cosines(const GaussianModel& gaussians, const SparseLevel& level,
                                      const PinholeCamera& camera, const Pose& pose, const at::Tensor& directions) {
  const RasterizeOutput out = splat_sparse(
      "render_sparse_cosines", gaussians, level, camera, pose,
      [&](const auto& m, const auto& s, const auto& q, const auto& o, const auto& w, const auto& i, int c,
          const RasterizeSettings& settings) {
        if (!directions.defined() || directions.dim() != 2 || directions.size(1) != level.codebook.size(1))
          throw Error("render_sparse_cosines: the codebook's bases are " + std::to_string(level.codebook.size(1)) +
                      "-d, the directions " + shape_of(directions) + " (another feature provider?)");
        // a_p = B p / |p| (in double, as DecodedCosines' projections), and R of B^T = Q R: |w B| = |R w|
        const at::Tensor book = level.codebook.detach().to(torch::kCPU, torch::kFloat64);
        const at::Tensor in_basis = unit_rows(directions.detach().to(torch::kCPU, torch::kFloat64)).matmul(book.t());
        const at::Tensor factor = factor_linear_head(book.t().contiguous(), at::Tensor()).r;
        return rasterize_sparse_cosines(m, s, q, o, w, i, c, in_basis.to(m.options()), factor.to(m.options()),
                                        settings);
      });
  return {out.image, out.alpha};
}

LinearHeadDecoder codebook_decoder(const at::Tensor& codebook) {
  return {[](const at::Tensor& w) { return w; }, factor_linear_head(codebook.t().contiguous(), at::Tensor())};
}

namespace {

void check_queries(const at::Tensor& queries, const at::Tensor& canonical) {
  if (!queries.defined() || queries.dim() != 2 || !canonical.defined() || canonical.dim() != 2 ||
      canonical.size(0) == 0 || canonical.size(1) != queries.size(1))
    throw Error("relevance_maps: queries K x D and canonical M x D (M > 0) expected, got " + shape_of(queries) +
                " and " + shape_of(canonical));
}

// The maps of K queries from the cosines of every pixel (H W x P, float32) with the queries, then the
// canonical phrases.
RelevanceMaps maps_of_cosines(const at::Tensor& cos, int64_t K, const at::Tensor& alpha) {
  const int64_t H = alpha.size(0), W = alpha.size(1);
  const at::Tensor canonical_cos = cos.slice(1, K);  // H W x M
  std::vector<at::Tensor> relevancy;
  for (int64_t k = 0; k < K; ++k) relevancy.push_back(relevancy_from_cosines(cos.select(1, k), canonical_cos));
  RelevanceMaps out;
  out.cosine = cos.slice(1, 0, K).t().reshape({K, H, W}).contiguous();
  out.relevancy = K > 0 ? torch::stack(relevancy, 0).reshape({K, H, W}) : torch::empty({0, H, W}, cos.options());
  out.alpha = alpha.to(torch::kFloat32);
  return out;
}

// The maps of the queries (the first K directions of `cosines`) from rendered latents.
RelevanceMaps maps_of_rendered(const RenderedLatents& r, const DecodedCosines& cosines, int64_t K,
                               const at::Tensor& canonical, int64_t chunk_pixels) {
  at::NoGradGuard no_grad;
  const int64_t H = r.latents.size(0), W = r.latents.size(1), L = r.latents.size(2);
  const int64_t P = K + canonical.size(0);
  const at::Tensor flat = r.latents.reshape({H * W, L});
  at::Tensor cos = torch::empty({H * W, P}, flat.options().dtype(torch::kFloat32));
  decode_covered(flat, r.alpha, std::cref(cosines), chunk_pixels, [&](const at::Tensor& rows, const at::Tensor& c) {
    cos.index_copy_(0, rows, c.expand({rows.size(0), P}));
  });
  return maps_of_cosines(cos, K, r.alpha);
}

}  // namespace

RelevanceMaps relevance_maps(const GaussianModel& gaussians, const at::Tensor& latents, const LinearHeadDecoder& decoder,
                             const PinholeCamera& camera, const Pose& pose, const at::Tensor& queries,
                             const at::Tensor& canonical, int64_t chunk_pixels) {
  check_queries(queries, canonical);
  const DecodedCosines cosines(decoder, torch::cat({queries, canonical}, 0));
  return maps_of_rendered(render_latents(gaussians, latents, camera, pose), cosines, queries.size(0), canonical,
                          chunk_pixels);
}

RelevanceMaps relevance_maps(const GaussianModel& gaussians, const SparseLevel& level, const PinholeCamera& camera,
                             const Pose& pose, const at::Tensor& queries, const at::Tensor& canonical,
                             int64_t chunk_pixels) {
  check_queries(queries, canonical);
  const at::Tensor directions = torch::cat({queries, canonical}, 0);
  if (gaussians.means.device().is_cpu()) {  // the cosines taken in the rasterizer's tiles
    const RenderedCosines r = render_sparse_cosines(gaussians, level, camera, pose, directions);
    return maps_of_cosines(r.cosine.reshape({-1, directions.size(0)}).to(torch::kFloat32), queries.size(0), r.alpha);
  }
  const DecodedCosines cosines(codebook_decoder(level.codebook.to(gaussians.means.device())), directions);
  return maps_of_rendered(render_sparse(gaussians, level, camera, pose), cosines, queries.size(0), canonical,
                          chunk_pixels);
}

}  // namespace cls
