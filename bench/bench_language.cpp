// Language-field costs (docs/benchmarks.md):
// 1. training, ms per iteration with 128 channels: rasterize_features forward + a loss (--loss: L1 against a
//    random latent map, or the paper's loss from seg maps) + backward into the per-Gaussian latents
//    (geometry frozen, paper 3.3); --blend-cache on reads the view's recorded blend weights (rasterize.h's
//    BlendCache, recorded in the warm-up iteration) as train-language does on the CPU (the sparse field's cosine
//    loss in one pass with its map: sparse_cosine_loss_recorded), separate the same with the map made and
//    taken by the loss in passes of their own, off blends every iteration;
// 2. querying, relevance maps per second at 1080p: render 128 channels, then every pixel's cosine of its
//    decoded feature (shared autoencoder, 128 -> 256 -> 512) with one query feature, as `query` takes it
//    (DecodedCosines: the hidden layer, then the last layer's triangular factor; src/query/relevance.h).
// --matmul-precision highest,high times the decode with float32 products and again with TF32 (CUDA), and
// prints how far the second's cosines are from the first's.
// Scenes are random (seeded) Gaussians spread over the view frustum, as bench_splat's.
// Usage: bench_language [--threads N] [--device cpu|cuda] [--train-scenes 200000@800x600,50000@480x360] ...
// On CUDA every timed body ends with a device synchronisation, so the wall times are the GPU's.
#include <ATen/ATen.h>
#include <ATen/CPUGeneratorImpl.h>
#include <ATen/Parallel.h>
#include <ATen/core/grad_mode.h>
#include <torch/cuda.h>
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "bench_timer.h"
#include "core/args.h"
#include "core/error.h"
#include "core/heap_reuse.h"
#include "core/strings.h"
#include "language/autoencoder.h"
#include "language/language_loss.h"
#include "language/sparse_field.h"
#include "language/sparse_loss.h"
#include "query/relevance.h"
#include "splat/compute_device.h"
#include "splat/rasterize.h"

namespace cls {
namespace {

using bench::Clock;

struct Scene {
  at::Tensor means, scales, quats, opacities;  // activated parameters
  RasterizeSettings settings;
};

// Gaussians between z = 3 and 15 inside the frustum, screen sigmas log-uniform in [0.5, 8] px,
// opacities in [0.1, 0.9] (bench_splat's scene, as tensors).
Scene make_scene(int64_t n, int width, int height, uint64_t seed, const at::Device& device) {
  at::Generator gen = at::detail::createCPUGenerator(seed);
  const double f = 0.8 * width;
  Scene s;
  s.settings.camera.fx = s.settings.camera.fy = f;
  s.settings.camera.cx = 0.5 * width, s.settings.camera.cy = 0.5 * height;
  s.settings.camera.width = width, s.settings.camera.height = height;
  const at::Tensor z = 3 + 12 * at::rand({n}, gen);
  const at::Tensor x = (at::rand({n}, gen) - 0.5) * z * (width / f);
  const at::Tensor y = (at::rand({n}, gen) - 0.5) * z * (height / f);
  s.means = at::stack({x, y, z}, 1).contiguous();
  s.scales = ((z / f * 0.5).unsqueeze(1) * at::pow(16.0, at::rand({n, 3}, gen))).contiguous();
  const at::Tensor q = at::rand({n, 4}, gen) - 0.5;
  s.quats = (q / q.norm(2, {1}, true)).contiguous();
  s.opacities = 0.1 + 0.8 * at::rand({n}, gen);
  for (at::Tensor* t : {&s.means, &s.scales, &s.quats, &s.opacities}) *t = t->to(device);
  return s;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const size_t m = v.size() / 2;
  return v.size() % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

struct Timing {
  double wall_ms = 0, cpu_ms = 0;  // medians per iteration
  double cache_mb = 0;             // the blend cache's memory (--blend-cache on)
};

// `t` with the memory of the scene's blend cache, if any.
Timing with_cache_size(Timing t, const Scene& s) {
  if (s.settings.blend_cache) t.cache_mb = double(blend_cache_bytes(*s.settings.blend_cache)) / (1 << 20);
  return t;
}

template <class F>
Timing time_it(int repeats, const at::Device& device, const F& body) {
  const auto run = [&] {
    body();
    if (device.is_cuda()) torch::cuda::synchronize();
  };
  run();  // warm-up
  std::vector<double> wall, cpu;
  for (int r = 0; r < repeats; ++r) {
    const double c0 = bench::cpu_seconds();
    const auto t0 = Clock::now();
    run();
    wall.push_back(1e3 * bench::seconds_since(t0));
    cpu.push_back(1e3 * (bench::cpu_seconds() - c0));
  }
  return {median(wall), median(cpu)};
}

struct SceneSpec {
  int64_t gaussians;
  int width, height;
};

std::vector<SceneSpec> parse_scenes(const std::string& text) {
  std::vector<SceneSpec> specs;
  if (text == "none") return specs;
  for (const std::string& item : split_commas(text)) {
    SceneSpec s{};
    char at_sign = 0, x = 0;
    std::stringstream is(item);
    if (!(is >> s.gaussians >> at_sign >> s.width >> x >> s.height) || at_sign != '@' || x != 'x' ||
        s.gaussians <= 0 || s.width <= 0 || s.height <= 0)
      throw UsageError("bench_language: scenes are N@WxH, comma-separated, got '" + item + "'");
    specs.push_back(s);
  }
  return specs;
}

// Seg maps as the features stage writes them, for the paper's loss: SAM segments of 40 x 40 px blocks,
// CityGML regions of 80 x 80 px blocks on the left 60 % of the view (the covered part), random latents.
struct SegTargets {
  std::vector<int32_t> sam, gml;
  at::Tensor sam_table, gml_table, coverage;
};

SegTargets make_seg_targets(int width, int height, int channels, at::Generator& gen, const at::Device& device) {
  SegTargets t;
  const int covered = width * 6 / 10, sam_cols = (width + 39) / 40, gml_cols = (covered + 79) / 80;
  t.coverage = at::zeros({height, width});
  t.coverage.slice(1, 0, covered).fill_(1);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      t.sam.push_back(y / 40 * sam_cols + x / 40);
      t.gml.push_back(x < covered ? y / 80 * gml_cols + x / 80 : -1);
    }
  t.sam_table = at::rand({int64_t(t.sam.back()) + 1, channels}, gen).to(device);
  t.gml_table = at::rand({int64_t((height - 1) / 80 * gml_cols + (covered - 1) / 80) + 1, channels}, gen).to(device);
  t.coverage = t.coverage.to(device);
  return t;
}

// One language-training iteration's rasterizer work: forward, the loss, backward. Losses: "l1" (the mean
// L1 against a random latent map; the figures before the paper's loss was timed), "seg" (the paper's
// loss from seg maps, as train-language computes it: language_loss_from_seg) and "dense" (the same loss
// from gathered H x W x L targets, language_loss: the reference, and what the GPU ran before seg_loss_cuda).
// The sparse field's iterations (issue 36): "sparse" (top-K softmax of N x L logits splatted sparsely, times an
// L x 512 codebook, the paper's loss from seg maps against 512-d targets, backward into logits and codebook)
// and "sparse-warmup" (its first iterations: the softmax over all L bases splatted densely); "sparse-cosine" and
// "sparse-cosine-warmup": the same with the cosine distance (sparse_loss.h, --sparse-distance cosine).
Timing bench_sparse_training(const SceneSpec& spec, int bases, int top_k, bool warmup, bool cosine, bool blend_cache,
                             bool fused, int repeats, const at::Device& device) {
  Scene s = make_scene(spec.gaussians, spec.width, spec.height, 42, device);
  if (blend_cache) s.settings.blend_cache = make_blend_cache();
  at::Generator gen = at::detail::createCPUGenerator(7);
  const at::Tensor logits = at::rand({spec.gaussians, bases}, gen).to(device).requires_grad_(true);
  const at::Tensor codebook = at::rand({bases, 512}, gen).to(device).requires_grad_(true);
  const SegTargets seg = make_seg_targets(spec.width, spec.height, 512, gen, device);
  const auto seg_map = [&](const std::vector<int32_t>& ids) {
    return at::from_blob(const_cast<int32_t*>(ids.data()), {spec.height, spec.width}, at::kInt);
  };
  const LanguageLossWeights weights;
  return with_cache_size(time_it(repeats, device, [&] {
    const SegMapTarget sam{seg_map(seg.sam), seg.sam_table}, gml{seg_map(seg.gml), seg.gml_table};
    at::Tensor map;
    LanguageLoss loss;
    if (warmup) {
      map = rasterize_features(s.means, s.scales, s.quats, s.opacities, at::softmax(logits, 1), at::Tensor(), s.settings).image;
    } else {
      const SparseWeights w = top_k_softmax(logits, top_k);
      if (fused && cosine && blend_cache_bytes(*s.settings.blend_cache) > 0)  // as train-language
        loss = sparse_cosine_loss_recorded(s.means, s.scales, s.quats, s.opacities, w.weights, w.indices, s.settings,
                                           codebook, sam, gml, seg.coverage, weights);
      else
        map = rasterize_sparse_features(s.means, s.scales, s.quats, s.opacities, w.weights, w.indices, bases,
                                        at::Tensor(), s.settings).image;
    }
    if (map.defined())
      loss = cosine ? sparse_cosine_loss(map, codebook, sam, gml, seg.coverage, weights)
                    : language_loss_from_seg(at::matmul(map, codebook), sam, gml, seg.coverage, weights);
    loss.total.backward();
    logits.mutable_grad().zero_();
    codebook.mutable_grad().zero_();
  }), s);
}

Timing bench_training(const SceneSpec& spec, int channels, const std::string& loss_kind, bool blend_cache, int repeats,
                      const at::Device& device) {
  Scene s = make_scene(spec.gaussians, spec.width, spec.height, 42, device);
  if (blend_cache) s.settings.blend_cache = make_blend_cache();
  at::Generator gen = at::detail::createCPUGenerator(7);
  const at::Tensor latents = at::rand({spec.gaussians, channels}, gen).to(device).requires_grad_(true);
  const at::Tensor target = loss_kind == "l1" ? at::rand({spec.height, spec.width, channels}, gen).to(device) : at::Tensor();
  const SegTargets seg = make_seg_targets(spec.width, spec.height, channels, gen, device);
  const auto seg_map = [&](const std::vector<int32_t>& ids) {
    return at::from_blob(const_cast<int32_t*>(ids.data()), {spec.height, spec.width}, at::kInt);
  };
  const LanguageLossWeights weights;
  return with_cache_size(time_it(repeats, device, [&] {
    const RasterizeOutput out =
        rasterize_features(s.means, s.scales, s.quats, s.opacities, latents, at::Tensor(), s.settings);
    if (loss_kind == "l1") {
      (out.image - target).abs().mean().backward();
    } else if (loss_kind == "seg") {
      language_loss_from_seg(out.image, {seg_map(seg.sam), seg.sam_table}, {seg_map(seg.gml), seg.gml_table},
                             seg.coverage, weights)
          .total.backward();
    } else {
      LanguageLossInputs in;
      in.rendered = out.image;
      in.sam = gather_latent_target(seg.sam.data(), spec.height, spec.width, seg.sam_table, "SAM seg map");
      in.gml = gather_latent_target(seg.gml.data(), spec.height, spec.width, seg.gml_table, "CityGML seg map");
      in.coverage = seg.coverage;
      language_loss(in, weights).total.backward();
    }
    latents.mutable_grad().zero_();
  }), s);
}

int bench_main(int argc, char** argv) {
  Args args("bench_language", "Language-field training ms/iteration and 1080p relevance-map FPS (CPU or CUDA)", "");
  int threads = 2, channels = 128, chunk_pixels = 65536, repeats = 3, bases = 64, top_k = 4;
  std::string train_scene_text = "200000@800x600,50000@480x360", query_scene_text = "200000@1920x1080";
  std::string device_name = "cpu";
  std::vector<std::string> losses = {"l1"}, precisions = {"highest"}, blend_caches = {"off", "on"};
  args.bind("threads", threads, "OpenMP / ATen threads")
      .bind("channels", channels, "latent channels")
      .bind("train-scenes", train_scene_text, "training scenes, N@WxH comma-separated, or none")
      .bind("loss", losses, "training losses to time, comma-separated: l1, seg (train-language's), dense; sparse, "
                            "sparse-warmup (the sparse field's iterations, 512-d targets), sparse-cosine, "
                            "sparse-cosine-warmup (the same with --sparse-distance cosine)")
      .bind("blend-cache", blend_caches, "training, comma-separated: off (blend every iteration), on (read the blend "
                                         "weights recorded in the warm-up as train-language does on the CPU: the "
                                         "sparse cosine loss in one pass with its map), separate (the same, map and "
                                         "loss in passes of their own; for other losses the same as on)")
      .bind("codebook-size", bases, "sparse: bases L")
      .bind("top-k", top_k, "sparse: weights per Gaussian K")
      .bind("query-scene", query_scene_text, "the relevance-map scene, N@WxH, or none")
      .bind("chunk", chunk_pixels, "pixels decoded per autoencoder call")
      .bind("matmul-precision", precisions, "float32 product precisions to time the decode with, comma-separated "
                                            "(highest, high: TF32 on CUDA, medium)")
      .bind("repeats", repeats, "timed repeats (after one warm-up); the median is reported")
      .bind("device", device_name, "cpu or cuda (needs a CUDA build)");
  if (!args.parse(argc, argv)) return 0;
  const at::Device device = compute_device(device_name);
  omp_set_num_threads(threads);
  at::set_num_threads(threads);
  repeats = std::max(1, repeats);
  const std::vector<SceneSpec> train_scenes = parse_scenes(train_scene_text);
  const std::vector<SceneSpec> query_scenes = parse_scenes(query_scene_text);  // checked before the timing
  for (const std::string& l : losses)
    if (l != "l1" && l != "seg" && l != "dense" && l != "sparse" && l != "sparse-warmup" && l != "sparse-cosine" &&
        l != "sparse-cosine-warmup")
      throw UsageError("bench_language: --loss takes l1, seg, dense, sparse, sparse-warmup, sparse-cosine or "
                       "sparse-cosine-warmup, got '" + l + "'");
  for (const std::string& b : blend_caches)
    if (b != "off" && b != "on" && b != "separate")
      throw UsageError("bench_language: --blend-cache takes off, on and separate, got '" + b + "'");
  for (const std::string& b : blend_caches)
    if (device.is_cuda() && b != "off")
      throw UsageError("bench_language: --blend-cache " + b + " is for the CPU (pass --blend-cache off on CUDA)");
  for (const std::string& p : precisions)
    if (p != "highest" && p != "high" && p != "medium")
      throw UsageError("bench_language: --matmul-precision takes highest, high or medium, got '" + p + "'");

  std::printf("device %s, threads %d, %d channels, median of %d repeats after one warm-up\n", device.str().c_str(),
              threads, channels, repeats);
  for (const SceneSpec& spec : train_scenes)
    for (const std::string& loss : losses)
      for (const std::string& cache : blend_caches) {
        const bool on = cache != "off";
        const Timing t = loss.rfind("sparse", 0) == 0
                             ? bench_sparse_training(spec, bases, top_k, loss.find("warmup") != std::string::npos,
                                                     loss.find("cosine") != std::string::npos, on, cache == "on",
                                                     repeats, device)
                             : bench_training(spec, channels, loss, on, repeats, device);
        char size[32] = "";
        if (on) std::snprintf(size, sizeof size, " (%.1f MiB)", t.cache_mb);
        std::printf("training  %7lld Gaussians %4dx%-4d  %9.1f ms/iteration (wall)  CPU %9.1f ms  CPU/threads %9.1f ms"
                    "  loss %s, blend cache %s%s\n",
                    static_cast<long long>(spec.gaussians), spec.width, spec.height, t.wall_ms, t.cpu_ms,
                    t.cpu_ms / threads, loss.c_str(), cache.c_str(), size);
        std::fflush(stdout);
      }

  // Relevance map: render, decode per pixel (chunks), cosine with a query feature.
  if (query_scenes.empty()) return 0;
  const SceneSpec q = query_scenes.front();
  const Scene s = make_scene(q.gaussians, q.width, q.height, 43, device);
  at::Generator gen = at::detail::createCPUGenerator(8);
  AutoencoderConfig config;
  config.encoder_dims.back() = channels;
  Autoencoder ae(config, 1);
  ae.to(device);
  at::Tensor latents = at::rand({q.gaussians, channels}, gen);
  latents = (latents / latents.norm(2, {1}, true)).to(device);
  at::Tensor query = at::randn({config.input_dim}, gen);
  query = (query / query.norm()).to(device);
  const int64_t chunk = std::max(1, chunk_pixels);
  at::Tensor rendered, relevance;
  const Timing render = time_it(repeats, device, [&] {
    at::NoGradGuard no_grad;
    rendered = rasterize_features(s.means, s.scales, s.quats, s.opacities, latents, at::Tensor(), s.settings).image;
  });
  const DecodedCosines cosines(linear_head_decoder(ae), query.reshape({1, -1}));
  // Each precision of float32 products in turn (PyTorch's names: "high" lets CUDA use TF32 tensor cores);
  // a later one's maps are compared with the first one's.
  at::Tensor first;
  for (const std::string& precision : precisions) {
    at::globalContext().setFloat32MatmulPrecision(precision);
    const Timing decode = time_it(repeats, device, [&] {
      at::NoGradGuard no_grad;
      const at::Tensor pixels = rendered.reshape({-1, channels});
      relevance = at::empty({pixels.size(0)}, pixels.options());
      for (int64_t begin = 0; begin < pixels.size(0); begin += chunk) {
        const int64_t end = std::min(pixels.size(0), begin + chunk);
        relevance.slice(0, begin, end).copy_(cosines(pixels.slice(0, begin, end)).squeeze(1));
      }
    });
    const double total_wall = render.wall_ms + decode.wall_ms, total_cpu = render.cpu_ms + decode.cpu_ms;
    std::printf("query     %7lld Gaussians %4dx%-4d  render %9.1f ms  decode+cosine %9.1f ms  (CPU %9.1f / %9.1f ms)"
                "  matmul precision %s\n",
                static_cast<long long>(q.gaussians), q.width, q.height, render.wall_ms, decode.wall_ms, render.cpu_ms,
                decode.cpu_ms, precision.c_str());
    std::printf("query     relevance maps: %.3f FPS (wall), %.3f FPS (CPU/threads estimate)", 1e3 / total_wall,
                1e3 / (total_cpu / threads));
    if (first.defined())
      std::printf("; cosines differ from the %s ones by at most %.2e", precisions[0].c_str(),
                  (relevance - first).abs().max().item<double>());
    else
      first = relevance.clone();
    std::printf("\n");
    std::fflush(stdout);
  }
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
