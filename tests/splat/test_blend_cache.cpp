// Recorded blend weights (rasterize.h's BlendCache, rasterize_cpu.h's BlendWeights): the forward and the
// features' backward read from them equal the walk's, to the bit on one thread (the recorded weights are the
// forward's own and the walk's backward without geometry takes them front to back with the same arithmetic),
// within rounding on more threads (the order in which threads add a Gaussian's sums); and a cache refuses the
// calls it was not recorded for.
#include <gtest/gtest.h>
#include <torch/torch.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <random>
#include <string>
#include <type_traits>
#include <vector>

#include "core/error.h"
#include "omp_threads.h"
#include "splat/rasterize.h"
#include "splat/rasterize_cpu.h"
#include "splat/reference_render.h"
#include "splat/view_blend_caches.h"
#include "splat_scene.h"
#include "torch_scene.h"

namespace cls {
namespace {

// A scene with many overlapping Gaussians (transmittance stops included) over several tiles, edge tiles too.
TorchScene crowded_scene(int channels, torch::Dtype dtype) { return torch_scene(false, channels, 61, dtype, 90, 70, 45); }

struct Rendered {
  RasterizeOutput out;
  torch::Tensor grad;  // the features' (dense N x C or sparse N x K)
};

// One forward and backward of `values` (sparse with `indices`) under `settings`, the loss <image, w>.
Rendered render(const TorchScene& t, const torch::Tensor& values, const torch::Tensor& indices, int channels,
                const torch::Tensor& w, const RasterizeSettings& settings) {
  const torch::Tensor v = values.detach().requires_grad_(true);
  Rendered r;
  r.out = indices.defined()
              ? rasterize_sparse_features(t.means, t.scales, t.quats, t.opacities, v, indices, channels, {}, settings)
              : rasterize_features(t.means, t.scales, t.quats, t.opacities, v, {}, settings);
  (r.out.image * w).sum().backward();
  r.grad = v.grad();
  return r;
}

TEST(BlendCache, RecordedWeightsGiveTheWalksImagesAndGradients) {
  for (CpuKernels k : available_cpu_kernels())
  for (torch::Dtype dtype : {torch::kFloat64, torch::kFloat32})
  for (const char* kind : {"dense", "sparse", "rgb", "one"})
  for (int threads : {1, 2, 3}) {
    const test::ScopedCpuKernels use(k);
    const test::ScopedOmpThreads use_threads(threads);
    const std::string what = std::string(cpu_kernels_name(k)) + (dtype == torch::kFloat64 ? " double " : " float ") + kind;
    // RGB and one channel: the walk's fixed-channel builds
    const bool sparse = std::string(kind) == "sparse", fixed = std::string(kind) == "rgb" || std::string(kind) == "one";
    const int C = std::string(kind) == "rgb" ? 3 : std::string(kind) == "one" ? 1 : 24;
    TorchScene t = crowded_scene(C, dtype);
    torch::manual_seed(62);
    const int64_t n = t.means.size(0);
    const int K = 3;
    torch::Tensor indices;
    if (sparse) indices = torch::randint(0, C, {n, K}, torch::kInt32);
    auto values = [&] { return torch::randn({n, sparse ? K : C}, torch::kFloat64).to(dtype); };
    const torch::Tensor w = torch::randn({t.settings.camera.height, t.settings.camera.width, C}, torch::kFloat64).to(dtype);
    RasterizeSettings cached = t.settings;
    if (sparse) cached.background = torch::Tensor();  // (with one, as dense features have: both kinds covered)
    RasterizeSettings walked = cached;
    cached.blend_cache = make_blend_cache();
    ASSERT_EQ(blend_cache_bytes(*cached.blend_cache), 0u);
    // The first call records (and blends as the walk does), the later ones read: each of other values.
    for (int call = 0; call < 3; ++call) {
      const torch::Tensor x = values();
      const Rendered a = render(t, x, indices, C, w, walked), b = render(t, x, indices, C, w, cached);
      const std::string which = what + (call == 0 ? ", recording call" : ", recorded call");
      ASSERT_GT(a.out.alpha.max().item<double>(), 0.5) << "the scene must cover pixels";
      ASSERT_GT(a.grad.abs().max().item<double>(), 0.0);
      EXPECT_TRUE(torch::equal(a.out.alpha, b.out.alpha)) << which;
      EXPECT_TRUE(torch::equal(a.out.depth, b.out.depth)) << which;
      EXPECT_TRUE(torch::equal(a.out.radii, b.out.radii)) << which;
      // Run-time channel counts share the walk's sums to the bit; fixed ones differ by rounding.
      const double tol = fixed || threads > 1 ? (dtype == torch::kFloat64 ? 1e-12 : 1e-5) : 0.0;
      const double image_tol = fixed ? tol : 0.0;
      EXPECT_LE((a.out.image - b.out.image).abs().max().item<double>(), image_tol) << which;
      EXPECT_LE((a.grad - b.grad).abs().max().item<double>(), tol * a.grad.abs().max().item<double>()) << which;
    }
    EXPECT_GT(blend_cache_bytes(*cached.blend_cache), 0u) << what;
  }
}

// The recorded weights against the double reference renderer (every pixel blends all Gaussians): with
// Gaussian g's features the unit vector e_g its image holds each pixel's weight alpha_g T_g at channel g. Each
// (Gaussian, pixel) the reference blends is one lane of one recorded entry, of the same weight.
TEST(BlendCache, RecordedWeightsAreTheReferencesBlendWeights) {
  const test::RandomScene s = test::random_scene(90, 70, 45, 1, false, 61, 0.7);
  test::SceneArrays<double> arrays = test::scene_arrays<double>(s);
  arrays.features.assign(size_t(s.n) * s.n, 0.0);
  for (int g = 0; g < s.n; ++g) arrays.features[size_t(g) * s.n + g] = 1.0;
  SplatInputs<double> in = arrays.inputs(s, false);
  in.channels = s.n;
  const ReferenceImage ref = reference_render(s.cam, in);
  const size_t n_pix = size_t(s.cam.width) * s.cam.height;
  std::vector<double> image(n_pix * s.n), alpha(n_pix), depth(n_pix);
  SplatForwardState<double> st;
  BlendWeights<double> bw;
  rasterize_forward_cpu(s.cam, in, image.data(), alpha.data(), depth.data(), st, &bw);
  std::vector<double> recorded(n_pix * s.n, 0.0);  // pixel x Gaussian
  std::vector<int> seen(n_pix * s.n, 0);
  const int L = BlendWeights<double>::kLanes, tiles_x = s.cam.tiles_x();
  ASSERT_EQ(bw.tiles.size(), size_t(tiles_x) * s.cam.tiles_y());
  for (size_t tile = 0; tile < bw.tiles.size(); ++tile) {
    const auto& rec = bw.tiles[tile];
    for (int q = 0; q < BlendWeights<double>::kSubTiles; ++q)
      for (int e = rec.begin[q]; e < rec.end[q]; ++e)
        for (int l = 0; l < L; ++l) {
          const double w = rec.weights[size_t(e) * L + l];
          if (w == 0) continue;
          const int x = int(tile) % tiles_x * 16 + q % 4 * 4 + l % 4, y = int(tile) / tiles_x * 16 + q / 4 * 4 + l / 4;
          ASSERT_TRUE(x < s.cam.width && y < s.cam.height) << "a weight outside the image";
          const size_t at = (size_t(y) * s.cam.width + x) * s.n + rec.ids[rec.slot[e]];
          recorded[at] = w;
          ++seen[at];
        }
  }
  size_t blended = 0;
  for (size_t i = 0; i < recorded.size(); ++i) {
    blended += ref.image[i] != 0;
    EXPECT_LE(seen[i], 1) << "pixel " << i / s.n << ", Gaussian " << i % s.n << " recorded twice";
    EXPECT_NEAR(recorded[i], ref.image[i], 1e-12) << "pixel " << i / s.n << ", Gaussian " << i % s.n;
  }
  EXPECT_GT(blended, 10 * n_pix / 16) << "a crowded scene";
  for (size_t p = 0; p < n_pix; ++p) {
    EXPECT_EQ(1.0 - bw.final_T[p], alpha[p]);
    EXPECT_EQ(bw.depth[p], depth[p]);
  }
}

TEST(BlendCache, RefusesWhatItWasNotRecordedFor) {
  TorchScene t = crowded_scene(5, torch::kFloat32);
  RasterizeSettings settings = t.settings;
  settings.background = torch::Tensor();  // (of the features' width, not SH's)
  settings.blend_cache = make_blend_cache();
  auto draw = [&](const TorchScene& scene, const RasterizeSettings& s) {
    return rasterize_features(scene.means, scene.scales, scene.quats, scene.opacities, scene.values, {}, s);
  };
  auto refused = [&](auto&& call, const std::string& expected) {
    try {
      call();
      ADD_FAILURE() << "accepted; expected an error saying " << expected;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
    }
  };
  {  // a geometry gradient, before anything is recorded
    TorchScene g = t;
    g.means = g.means.detach().requires_grad_(true);
    refused([&] { draw(g, settings); }, "frozen Gaussians");
  }
  {  // geometry it could not recognise by its memory
    TorchScene g = t;
    g.means = t.means.t().contiguous().t();
    refused([&] { draw(g, settings); }, "contiguous");
  }
  refused([&] { rasterize_sh(t.means, t.scales, t.quats, t.opacities, torch::zeros({t.means.size(0), 16, 3}), 3, {}, settings); },
          "not SH");
  draw(t, settings);  // records
  EXPECT_NO_THROW(draw(t, settings));
  RasterizeSettings moved = settings;
  moved.pose.t.x += 0.01;
  refused([&] { draw(t, moved); }, "another camera");
  TorchScene copy = t;
  copy.means = t.means.clone();
  refused([&] { draw(copy, settings); }, "other Gaussians");
  TorchScene as_double = t;
  for (torch::Tensor* p : {&as_double.means, &as_double.scales, &as_double.quats, &as_double.opacities, &as_double.values})
    *p = p->to(torch::kFloat64);
  refused([&] { draw(as_double, settings); }, "another dtype");
  t.scales.mul_(1.0f);  // in place: the Gaussians may have changed
  refused([&] { draw(t, settings); }, "changed since");
}

// Pixels nothing is blended into carry no gradient to any Gaussian, even an infinite one (a loss divided by
// alpha), on the recorded path as on the walk.
TEST(BlendCache, UncoveredPixelsReachNoGaussian) {
  for (bool sparse : {false, true}) {
    TorchScene t = torch_scene(false, 6, 63, torch::kFloat32);  // few Gaussians: uncovered pixels
    RasterizeSettings walked = t.settings;
    walked.background = torch::Tensor();
    RasterizeSettings cached = walked;
    cached.blend_cache = make_blend_cache();
    const int64_t n = t.means.size(0);
    torch::manual_seed(64);
    const torch::Tensor indices = sparse ? torch::randint(0, 6, {n, 2}, torch::kInt32) : torch::Tensor();
    const torch::Tensor x = sparse ? torch::randn({n, 2}) : t.values;
    const torch::Tensor alpha = render(t, x, indices, 6, torch::zeros({34, 36, 6}), walked).out.alpha;
    const torch::Tensor uncovered = (alpha == 0).unsqueeze(2).expand({-1, -1, 6});
    ASSERT_GT(uncovered.sum().item<int64_t>(), 0) << "the scene must leave pixels uncovered";
    const torch::Tensor w = torch::where(uncovered, torch::full_like(uncovered, INFINITY, torch::kFloat),
                                         torch::randn({34, 36, 6}));
    render(t, x, indices, 6, w, cached);  // records
    const Rendered a = render(t, x, indices, 6, w, walked), b = render(t, x, indices, 6, w, cached);
    EXPECT_TRUE(torch::isfinite(a.grad).all().item<bool>()) << (sparse ? "sparse" : "dense");
    EXPECT_TRUE(torch::equal(a.grad, b.grad)) << (sparse ? "sparse" : "dense");
  }
}

// The cosines of the sparse field's relevance maps (rasterize_sparse_cosines) read from the cache: the walk's.
TEST(BlendCache, CosinesFromRecordedWeightsAreTheWalks) {
  constexpr int C = 20, P = 3, K = 3;
  TorchScene t = crowded_scene(C, torch::kFloat32);
  torch::manual_seed(65);
  const int64_t n = t.means.size(0);
  const torch::Tensor weights = torch::rand({n, K}), indices = torch::randint(0, C, {n, K}, torch::kInt32);
  const torch::Tensor directions = torch::randn({P, C}), factor = torch::randn({C, C}).triu();
  RasterizeSettings walked = t.settings;
  walked.background = torch::Tensor();
  RasterizeSettings cached = walked;
  cached.blend_cache = make_blend_cache();
  auto cosines = [&](const RasterizeSettings& s) {
    return rasterize_sparse_cosines(t.means, t.scales, t.quats, t.opacities, weights, indices, C, directions, factor, s);
  };
  const RasterizeOutput a = cosines(walked);
  ASSERT_GT(a.image.abs().max().item<double>(), 0.1);
  for (int call = 0; call < 2; ++call) {  // recording, then recorded
    const RasterizeOutput b = cosines(cached);
    EXPECT_TRUE(torch::equal(a.image, b.image)) << "call " << call;
    EXPECT_TRUE(torch::equal(a.alpha, b.alpha)) << "call " << call;
    EXPECT_TRUE(torch::equal(a.depth, b.depth)) << "call " << call;
    EXPECT_TRUE(torch::equal(a.radii, b.radii)) << "call " << call;
  }
}

// A loss taken tile by tile (rasterize_recorded_loss_cpu): 1/2 |image - target|^2, so dL/dimage = image - target
// depends on the image the pass gave it. Counts the calls per pixel and keeps the image rows it was given.
template <class T>
struct SquaredLoss : TileLoss<T> {
  SquaredLoss(const std::vector<T>& target_, int channels) : target(target_), C(channels), image(target_.size()),
                                                             calls(target_.size() / channels) {}
  void tile(const int64_t* pixels, int rows, const T* rows_image, T* dL_dimage) override {
    for (int r = 0; r < rows; ++r) {
      const int64_t p = pixels[r];
      ++calls[p];
      for (int c = 0; c < C; ++c) {
        image[p * C + c] = rows_image[r * C + c];
        dL_dimage[r * C + c] = rows_image[r * C + c] - target[p * C + c];
      }
    }
  }
  const std::vector<T>& target;
  int C;
  std::vector<T> image;
  std::vector<std::atomic<int>> calls;
};

// The pass of forward, loss and backward over each tile in turn gives every pixel to the loss once, with the
// recorded forward's image row, and the recorded backward's gradient of the loss's dL/dimage: to the bit on one
// thread, within rounding on more (the order threads add a Gaussian's sums). Dense and sparse features.
template <class T>
void check_loss_pass(bool sparse, int threads) {
  const test::ScopedOmpThreads use_threads(threads);
  constexpr int C = 12, K = 3;
  const test::RandomScene s = test::random_scene(45, 90, 70, C, false, 66, 0.7);
  test::SceneArrays<T> arrays = test::scene_arrays<T>(s);
  SplatInputs<T> in = arrays.inputs(s, false);
  std::mt19937 rng(67);
  std::normal_distribution<double> normal;
  std::vector<int32_t> index;
  std::vector<T> values;
  if (sparse) {
    for (int i = 0; i < s.n * K; ++i) index.push_back(int32_t(rng() % C)), values.push_back(T(normal(rng)));
    in.features = values.data(), in.feature_index = index.data(), in.nnz = K;
  }
  const size_t n_pix = size_t(s.cam.width) * s.cam.height, n_values = size_t(s.n) * (sparse ? K : C);
  std::vector<T> image(n_pix * C), alpha(n_pix), depth(n_pix), target(n_pix * C);
  for (T& t : target) t = T(normal(rng));
  SplatForwardState<T> st;
  BlendWeights<T> bw;
  const SplatCamera<T> cam = test::cast_camera<T>(s.cam);
  rasterize_forward_cpu(cam, in, image.data(), alpha.data(), depth.data(), st, &bw);
  // the three steps
  rasterize_forward_recorded_cpu(bw, in, image.data(), alpha.data(), depth.data());
  std::vector<T> dL_dimage(n_pix * C), separate(n_values, T(0)), fused(n_values, T(0));
  for (size_t i = 0; i < dL_dimage.size(); ++i) dL_dimage[i] = image[i] - target[i];
  rasterize_backward_recorded_cpu(bw, in, dL_dimage.data(), separate.data());
  // the pass
  SquaredLoss<T> loss(target, C);
  rasterize_recorded_loss_cpu(bw, in, loss, fused.data());
  for (size_t p = 0; p < n_pix; ++p) ASSERT_EQ(loss.calls[p], 1) << "pixel " << p;
  EXPECT_EQ(loss.image, image) << "the loss is given the recorded forward's image";
  T largest = 0, error = 0;
  for (size_t i = 0; i < n_values; ++i)
    largest = std::max(largest, std::abs(separate[i])), error = std::max(error, std::abs(fused[i] - separate[i]));
  ASSERT_GT(largest, T(0));
  const T tol = threads == 1 ? T(0) : (std::is_same_v<T, double> ? T(1e-12) : T(1e-5));
  EXPECT_LE(error, tol * largest) << (sparse ? "sparse" : "dense");
  in.background = arrays.background.data();
  EXPECT_THROW(rasterize_recorded_loss_cpu(bw, in, loss, fused.data()), std::invalid_argument) << "a background";
}

TEST(BlendCache, LossPassIsTheRecordedForwardTheLossAndTheRecordedBackward) {
  for (CpuKernels k : available_cpu_kernels())
  for (bool sparse : {false, true})
  for (int threads : {1, 3}) {
    const test::ScopedCpuKernels use(k);
    check_loss_pass<double>(sparse, threads);
    check_loss_pass<float>(sparse, threads);
  }
}

// The budget: a view's cache is kept while the kept ones fit in it, and a view that did not fit gets no cache
// from then on (it blends every iteration); a budget of 0 gives no caches.
TEST(ViewBlendCaches, KeepWhatFitsTheBudgetFirstComeFirstKept) {
  TorchScene t = crowded_scene(4, torch::kFloat32);
  auto iterate = [&](ViewBlendCaches& caches, int view) {
    RasterizeSettings s = t.settings;
    s.pose.t.x += 0.05 * view;  // each view its own camera
    s.blend_cache = caches.settings_for(view);
    const bool had = s.blend_cache != nullptr;
    rasterize_features(t.means, t.scales, t.quats, t.opacities, t.values, {}, s);
    caches.recorded(view);
    return had;
  };
  ViewBlendCaches probe(1, size_t(1) << 40);
  iterate(probe, 0);
  const size_t one = probe.bytes();
  ASSERT_GT(one, 0u);
  ViewBlendCaches caches(3, one + one / 2);  // room for one view's weights (the views' sizes are alike)
  EXPECT_TRUE(iterate(caches, 0));
  EXPECT_EQ(caches.kept_views(), 1);
  EXPECT_TRUE(iterate(caches, 1));  // recorded, then dropped: it does not fit
  EXPECT_EQ(caches.kept_views(), 1);
  EXPECT_LE(caches.bytes(), one + one / 2);
  EXPECT_FALSE(iterate(caches, 1)) << "a view that did not fit blends from then on";
  EXPECT_TRUE(iterate(caches, 0));
  EXPECT_TRUE(caches.settings_for(0) && blend_cache_bytes(*caches.settings_for(0)) > 0) << "kept, recorded";
  ViewBlendCaches none(2, 0);
  EXPECT_FALSE(iterate(none, 0));
  EXPECT_EQ(none.kept_views(), 0);
}

}  // namespace
}  // namespace cls
