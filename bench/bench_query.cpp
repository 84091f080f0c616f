// Query speed: relevance maps (cosine + LangSplat relevancy of one text) per second for one view,
// at the bundled example's resolution (480x360) and at 1080p, on the CPU or a GPU. A relevance map = splat
// the 128-d latents (rasterize_features), decode every pixel with the shared autoencoder's decoder
// (default layout 128 -> 256 -> 512, random weights: the speed does not depend on them), cosine with
// [text; 4 canonical phrases], relevancy (relevance_maps in src/query/relevance.h), as `query` makes them.
// On CUDA (--device cuda) the model, latents and decoder live on the GPU and each timed map ends with a
// device synchronisation.
// --field sparse times the sparse field instead (language/sparse_field.h, issue 36): K random softmax-like
// weights over a random L x 512 codebook per Gaussian, splatted sparsely, the cosines through the codebook's
// factors: on the CPU inside the rasterizer's tiles (render_sparse_cosines, timed alone as the "render"), on a GPU
// from the rendered L-channel weight map. Both fields then time the per-Gaussian scores of one text at one level
// over all Gaussians (dense: the latent cosine `query` takes, gaussian_scores; sparse: sparse_cosines, the
// feature cosine).
// Usage: bench_query [--threads N] [--gaussians N] [--iters N] [--sizes 480x360,1920x1080] [--device cpu]
//                    [--field dense|sparse] [--codebook-size 64] [--top-k 4]
// Figures go to docs/benchmarks.md.
#include <ATen/Parallel.h>
#include <omp.h>
#include <torch/cuda.h>
#include <torch/torch.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <sstream>
#include <vector>

#include "bench_timer.h"
#include "core/args.h"
#include "core/error.h"
#include "core/heap_reuse.h"
#include "language/sparse_field.h"
#include "query/relevance.h"
#include "splat/compute_device.h"

namespace cls {
namespace {

using bench::Clock;

// Gaussians spread over the view frustum (z in [3, 15]) of a camera with fx = 0.8 * width, screen
// sigmas log-uniform in [0.5, 8] px at the reference width 800 (as bench_splat), opacities in [0.1, 0.9].
GaussianModel make_model(int n, int latent) {
  std::mt19937 rng(42);
  std::uniform_real_distribution<float> U(0, 1);
  GaussianModel g = make_gaussians(n, 0);
  auto means = g.means.accessor<float, 2>();
  auto ls = g.log_scales.accessor<float, 2>();
  auto q = g.quats.accessor<float, 2>();
  auto op = g.opacity_logits.accessor<float, 2>();
  const float aspect = 0.75f, f = 0.8f;  // fx / width
  for (int i = 0; i < n; ++i) {
    const float z = 3 + 12 * U(rng);
    means[i][0] = (U(rng) - 0.5f) * z / f;
    means[i][1] = (U(rng) - 0.5f) * z * aspect / f;
    means[i][2] = z;
    for (int k = 0; k < 3; ++k) ls[i][k] = std::log(z / (f * 800) * 0.5f * std::pow(16.0f, U(rng)));
    float qn = 0, v[4];
    for (float& x : v) x = U(rng) - 0.5f, qn += x * x;
    for (int k = 0; k < 4; ++k) q[i][k] = v[k] / std::sqrt(qn);
    const float o = 0.1f + 0.8f * U(rng);
    op[i][0] = std::log(o / (1 - o));
  }
  (void)latent;
  return g;
}

int bench_main(int argc, char** argv) {
  Args args("bench_query", "relevance maps per second (render latents + decode + cosine/relevancy), CPU or CUDA", "");
  int threads = 2, gaussians = 200000, iters = 2;
  int64_t chunk = 0;
  std::string sizes_text = "480x360,1920x1080", device_name = "cpu", field = "dense";
  int codebook_size = 64, top_k = 4;
  args.bind("threads", threads, "threads (OpenMP rasterizer and LibTorch)")
      .bind("gaussians", gaussians, "number of Gaussians")
      .bind("iters", iters, "timed views per size (after one warm-up)")
      .bind("sizes", sizes_text, "view sizes WxH, comma-separated")
      .bind("chunk", chunk, "pixels decoded per decoder call (0: the device's, " + std::to_string(kDecodeChunkPixels) +
                                " on the CPU, " + std::to_string(kDecodeChunkPixelsGpu) + " on a GPU)")
      .bind("device", device_name, "cpu or cuda (needs a CUDA build)")
      .bind("field", field, "dense (128-d latents and the autoencoder's decoder) or sparse (top-K over a codebook)")
      .bind("codebook-size", codebook_size, "sparse: bases L")
      .bind("top-k", top_k, "sparse: weights per Gaussian K");
  if (!args.parse(argc, argv)) return 0;
  if (field != "dense" && field != "sparse") throw UsageError("--field must be dense or sparse");
  const bool sparse = field == "sparse";
  omp_set_num_threads(threads);
  at::set_num_threads(threads);
  torch::NoGradGuard no_grad;
  std::setvbuf(stdout, nullptr, _IOLBF, 0);
  const int latent = 128;
  const at::Device device = compute_device(device_name);
  GaussianModel g = make_model(gaussians, latent);
  for (at::Tensor* t : {&g.means, &g.log_scales, &g.quats, &g.opacity_logits}) *t = t->to(device);
  torch::manual_seed(1);
  const at::Tensor latents = torch::rand({g.size(), latent}).to(device);
  Autoencoder ae(AutoencoderConfig{}, 1);
  ae.to(device);
  const LinearHeadDecoder decoder = linear_head_decoder(ae);
  SparseLevel level;
  if (sparse) {
    level.indices = torch::randint(0, codebook_size, {g.size(), top_k}, torch::kInt32).to(device);
    level.weights = torch::softmax(torch::randn({g.size(), top_k}), 1).to(device);
    level.codebook = torch::randn({codebook_size, 512}).to(device);
  }
  const at::Tensor queries = torch::randn({1, 512}).to(device), canonical = torch::randn({4, 512}).to(device);
  const bool in_tiles = sparse && device.is_cpu();  // relevance_maps takes the cosines in the rasterizer's tiles
  const auto sync = [&] {
    if (device.is_cuda()) torch::cuda::synchronize();
  };
  if (sparse)
    std::printf("%lld Gaussians, sparse field: K %d of L %d bases (512-d), 1 text + 4 canonical phrases, %d threads, "
                "%s, chunks of %lld pixels\n",
                static_cast<long long>(g.size()), top_k, codebook_size, threads, device.str().c_str(),
                static_cast<long long>(chunk > 0 ? chunk : decode_chunk_pixels(device)));
  else
    std::printf("%lld Gaussians, latent %d, decoder %d -> 256 -> 512, 1 text + 4 canonical phrases, %d threads, %s, "
                "chunks of %lld pixels\n",
                static_cast<long long>(g.size()), latent, latent, threads, device.str().c_str(),
                static_cast<long long>(chunk > 0 ? chunk : decode_chunk_pixels(device)));

  std::stringstream sizes(sizes_text);
  for (std::string size; std::getline(sizes, size, ',');) {
    int W = 0, H = 0;
    if (std::sscanf(size.c_str(), "%dx%d", &W, &H) != 2 || W <= 0 || H <= 0) throw UsageError("--sizes: bad size " + size);
    PinholeCamera cam{0.8 * W, 0.8 * W, 0.5 * W, 0.5 * H, W, H};
    Pose pose;  // identity: the Gaussians were placed in this camera's frustum
    double render_s = 0, total_s = 0, map_cpu = 0;
    for (int it = -1; it < iters; ++it) {
      const auto t0 = Clock::now();
      // the render timed alone for the split
      const at::Tensor alpha = in_tiles ? render_sparse_cosines(g, level, cam, pose, torch::cat({queries, canonical})).alpha
                               : sparse ? render_sparse(g, level, cam, pose).alpha
                                        : render_latents(g, latents, cam, pose).alpha;
      sync();
      const double tr = bench::seconds_since(t0);
      const double c1 = bench::cpu_seconds();
      const auto t1 = Clock::now();
      const RelevanceMaps m = sparse ? relevance_maps(g, level, cam, pose, queries, canonical, chunk)
                                     : relevance_maps(g, latents, decoder, cam, pose, queries, canonical, chunk);
      sync();
      const double tm = bench::seconds_since(t1);
      const double c2 = bench::cpu_seconds();
      if (it >= 0) render_s += tr / iters, total_s += tm / iters, map_cpu += (c2 - c1) / iters;
      if (it == 0) std::printf("  %dx%d: mean alpha %.2f\n", W, H, alpha.mean().item<double>());
      (void)m;
    }
    std::printf("%5dx%-5d relevance map %8.1f ms wall (%s %7.1f ms, %s %7.1f ms)"
                "  %.3f maps/s  CPU %8.1f ms  (~%.3f maps/s on %d idle cores)\n",
                W, H, 1e3 * total_s, in_tiles ? "render with the cosines" : "render latents", 1e3 * render_s,
                in_tiles ? "relevancy" : "decode + cosine + relevancy", 1e3 * (total_s - render_s), 1 / total_s,
                1e3 * map_cpu, threads / map_cpu, threads);
  }
  // Per-Gaussian scores of one text at one level (what a selection, a 3D label or the viewer's answer costs).
  const at::Tensor query_latent = sparse ? at::Tensor() : ae.encode(queries)[0];
  double best = 1e30;
  for (int it = 0; it < std::max(3, iters); ++it) {
    const auto t0 = Clock::now();
    const at::Tensor scores = sparse ? sparse_cosines(level, queries) : gaussian_scores(latents, query_latent);
    sync();
    best = std::min(best, bench::seconds_since(t0));
    (void)scores;
  }
  std::printf("per-Gaussian scores, one text, one level, %lld Gaussians: %.1f ms (best of %d)\n",
              static_cast<long long>(g.size()), 1e3 * best, std::max(3, iters));
  return 0;
}

}  // namespace
}  // namespace cls

int main(int argc, char** argv) {
  cls::reuse_freed_memory();  // as the CLI does
  try {
    return cls::bench_main(argc, argv);
  } catch (const cls::Error& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
}
