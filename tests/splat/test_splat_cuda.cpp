// The CUDA forward rasterizer against the CPU path (same scene, same order of blending). Runs only
// where the CUDA backend is linked (CLS_WITH_CUDA) and a device is present; skipped, saying so,
// elsewhere.
#include <gtest/gtest.h>

#ifdef CLS_WITH_CUDA
#include <torch/cuda.h>
#include <torch/torch.h>

#include "splat/rasterize.h"
#include "splat/rasterize_cuda.h"
#include "splat/ssim.h"
#include "splat_scene.h"

namespace cls {
namespace {

void compare_cuda_cpu(const test::RandomScene& s) {
  const auto a = test::scene_arrays<float>(s);
  const SplatCamera<float> cam = test::cast_camera<float>(s.cam);
  const size_t n_pix = static_cast<size_t>(cam.width) * cam.height;
  std::vector<float> image(n_pix * s.channels), alpha(n_pix), depth(n_pix);
  SplatForwardState<float> st;
  rasterize_forward_cpu(cam, a.inputs(s), image.data(), alpha.data(), depth.data(), st);

  auto dev = [](const std::vector<float>& v) {
    return torch::tensor(v.empty() ? std::vector<float>{0.f} : v, torch::kFloat32).to(torch::kCUDA);
  };
  const auto means = dev(a.means), scales = dev(a.scales), quats = dev(a.quats), opac = dev(a.opacities),
             sh = dev(a.sh), feat = dev(a.features), bg = dev(a.background);
  auto g_image = torch::empty({cam.height, cam.width, s.channels}, torch::dtype(torch::kFloat32).device(torch::kCUDA));
  auto g_alpha = torch::empty({cam.height, cam.width}, g_image.options());
  auto g_depth = torch::empty({cam.height, cam.width}, g_image.options());
  CudaSplatArgs args;
  args.cam = cam;
  args.n = s.n;
  args.means = means.data_ptr<float>(), args.scales = scales.data_ptr<float>();
  args.quats = quats.data_ptr<float>(), args.opacities = opac.data_ptr<float>();
  if (!a.sh.empty()) args.sh = sh.data_ptr<float>(), args.sh_degree = s.sh_degree;
  else args.features = feat.data_ptr<float>();
  args.channels = s.channels;
  args.background = bg.data_ptr<float>();
  args.image = g_image.data_ptr<float>(), args.alpha = g_alpha.data_ptr<float>(), args.depth = g_depth.data_ptr<float>();
  CudaForwardStatePtr state;
  ASSERT_EQ(rasterize_forward_cuda(args, state), 0);
  torch::cuda::synchronize();
  const auto cpu_image = torch::from_blob(image.data(), {cam.height, cam.width, s.channels});
  const auto cpu_alpha = torch::from_blob(alpha.data(), {cam.height, cam.width});
  const auto cpu_depth = torch::from_blob(depth.data(), {cam.height, cam.width});
  EXPECT_LT((g_image.cpu() - cpu_image).abs().max().item<float>(), 1e-5f) << s.channels << " channels";
  EXPECT_LT((g_alpha.cpu() - cpu_alpha).abs().max().item<float>(), 1e-5f);
  EXPECT_LT((g_depth.cpu() - cpu_depth).abs().max().item<float>(), 1e-4f);
}

// The scene's camera and pose as the autograd functions take them.
RasterizeSettings settings_of(const test::RandomScene& s) {
  RasterizeSettings settings;
  settings.camera = PinholeCamera{s.cam.fx, s.cam.fy, s.cam.cx, s.cam.cy, s.cam.width, s.cam.height};
  settings.pose.R = s.cam.R;
  settings.pose.t = s.cam.t;
  return settings;
}

// One of the scene's arrays as a float32 CPU tensor of `shape`.
torch::Tensor float_tensor(const std::vector<double>& v, std::vector<int64_t> shape) {
  return torch::tensor(v, torch::kFloat64).reshape(shape).to(torch::kFloat32);
}

// Gradients through the autograd function on CUDA against the CPU function (float32 both). With
// `geometry` false only the colours/features require a gradient (a language field on frozen
// Gaussians), which takes the CUDA backward's path without the alpha gradient.
void compare_gradients(bool use_sh, int channels, unsigned seed, bool geometry = true) {
  const auto s = test::random_scene(200, 53, 37, channels, use_sh, seed, 0.9);
  const RasterizeSettings settings = settings_of(s);
  const int64_t n = s.n;
  std::vector<torch::Tensor> params = {float_tensor(s.means, {n, 3}), float_tensor(s.scales, {n, 3}),
                                       float_tensor(s.quats, {n, 4}), float_tensor(s.opacities, {n}),
                                       use_sh ? float_tensor(s.sh, {n, 16, 3}) : float_tensor(s.features, {n, channels})};
  torch::manual_seed(seed);
  const auto w = torch::randn({s.cam.height, s.cam.width, s.channels});
  const auto wa = torch::randn({s.cam.height, s.cam.width});
  const auto wd = torch::randn({s.cam.height, s.cam.width});
  std::vector<std::vector<torch::Tensor>> grads;
  std::vector<torch::Tensor> m2d;
  for (const torch::Device dev : {torch::Device(torch::kCPU), torch::Device(torch::kCUDA)}) {
    std::vector<torch::Tensor> p;
    // detach: on the CPU, to() returns the tensor itself, which must not become a leaf of this pass.
    for (size_t k = 0; k < params.size(); ++k)
      p.push_back(params[k].to(dev).detach().requires_grad_(geometry || k + 1 == params.size()));
    auto means2d = torch::zeros({n, 2}, torch::dtype(torch::kFloat32).device(dev)).requires_grad_(geometry);
    RasterizeSettings sd = settings;
    sd.background = float_tensor(s.background, {int64_t(s.background.size())}).to(dev);
    const auto o = use_sh ? rasterize_sh(p[0], p[1], p[2], p[3], p[4], 3, means2d, sd)
                          : rasterize_features(p[0], p[1], p[2], p[3], p[4], means2d, sd);
    ((o.image * w.to(dev)).sum() + (o.alpha * wa.to(dev)).sum() + (o.depth * wd.to(dev)).sum()).backward();
    std::vector<torch::Tensor> g;
    for (auto& x : p)
      if (x.grad().defined()) g.push_back(x.grad().cpu());
    grads.push_back(g);
    if (geometry) m2d.push_back(means2d.grad().cpu());
  }
  ASSERT_EQ(grads[0].size(), geometry ? params.size() : 1u);
  ASSERT_EQ(grads[1].size(), grads[0].size());
  for (size_t k = 0; k < grads[0].size(); ++k) {
    const double scale = grads[0][k].abs().max().item<double>();
    ASSERT_GT(scale, 0.0) << "param " << k << ": the scene gives it no gradient to compare";
    EXPECT_LT((grads[1][k] - grads[0][k]).abs().max().item<double>(), 1e-3 * scale)
        << "param " << k << ", " << channels << " channels, geometry " << geometry;
  }
  if (geometry) EXPECT_LT((m2d[1] - m2d[0]).abs().max().item<double>(), 1e-3 * m2d[0].abs().max().item<double>());
}

TEST(SplatCuda, GradientsMatchCpu) {
  if (!torch::cuda::is_available()) GTEST_SKIP() << "no CUDA device: the CUDA backward is not compared with the CPU path";
  compare_gradients(true, 3, 51);
  // every register width of the backward (4 ... 128 channels), and channels beyond the registers
  for (int C : {1, 5, 16, 32, 48, 128, 200}) compare_gradients(false, C, 52 + C);
}

TEST(SplatCuda, FeatureGradientsWithoutGeometryMatchCpu) {
  if (!torch::cuda::is_available()) GTEST_SKIP() << "no CUDA device: the CUDA backward is not compared with the CPU path";
  compare_gradients(true, 3, 61, false);
  for (int C : {3, 5, 12, 32, 100, 128, 200}) compare_gradients(false, C, 62 + C, false);
}

// The CUDA SSIM kernels against ssim_ops on the same device (LibTorch's convolutions), value and
// gradient: an image of several thread blocks, and one narrower than the window with four channels.
TEST(SplatCuda, SsimKernelsMatchTheOps) {
  if (!torch::cuda::is_available()) GTEST_SKIP() << "no CUDA device: the CUDA SSIM kernels are not compared with the ops";
  torch::manual_seed(5);
  for (const std::vector<int64_t> shape : {std::vector<int64_t>{101, 67, 3}, std::vector<int64_t>{7, 5, 4}}) {
    const auto opts = torch::dtype(torch::kFloat32).device(torch::kCUDA);
    const at::Tensor a0 = torch::rand(shape, opts);
    const at::Tensor b = (a0 + 0.3 * torch::randn_like(a0)).clamp(0, 1);
    const at::Tensor a = a0.clone().requires_grad_(true), a_ops = a0.clone().requires_grad_(true);
    const at::Tensor s = ssim(a, b), s_ops = ssim_ops(a_ops, b);
    ASSERT_NE(s.grad_fn()->name().find("SsimKernels"), std::string::npos) << s.grad_fn()->name();  // the kernels ran
    EXPECT_NEAR(s.item<double>(), s_ops.item<double>(), 2e-6) << at::IntArrayRef(shape);
    (3.0 * s).backward();
    (3.0 * s_ops).backward();
    const double scale = a_ops.grad().abs().max().item<double>();
    ASSERT_GT(scale, 0);
    EXPECT_LT((a.grad() - a_ops.grad()).abs().max().item<double>() / scale, 1e-5) << at::IntArrayRef(shape);
    EXPECT_NEAR(ssim(a0, b).item<double>(), s.item<double>(), 1e-7);  // without a gradient
  }
}

// The sparse features (K weights at K of C channels) on CUDA against the CPU's sparse tile kernels: the image
// and the weights' gradient, through the sparse CUDA kernels (frozen geometry, K <= kCudaSparseMaxNnz; C over
// one chunk of 64 and over two) and through the dense kernel on the scattered weights (geometry gradients, or
// more weights than the sparse kernels take), then the means' gradient as well; each backward instantiation
// (K 1, 2, 3-4, 5-8, 9-16) and one case on a background. Random indices repeat within a Gaussian at times:
// both sum them.
TEST(SplatCuda, SparseFeaturesMatchCpu) {
  if (!torch::cuda::is_available()) GTEST_SKIP() << "no CUDA device: the sparse features are not compared with the CPU path";
  const auto s = test::random_scene(200, 53, 37, 1, false, 71, 0.9);
  const RasterizeSettings settings = settings_of(s);
  const int64_t n = s.n;
  struct Case {
    int K, C;
    bool geometry = false, background = false;
  };
  for (const Case c : {Case{4, 64}, Case{4, 100}, Case{1, 8}, Case{2, 8, false, true}, Case{7, 64},
                       Case{kCudaSparseMaxNnz, 100}, Case{3, 64, true}, Case{kCudaSparseMaxNnz + 4, 64}}) {
    SCOPED_TRACE(testing::Message() << "K " << c.K << ", C " << c.C << (c.geometry ? ", with geometry" : "")
                                    << (c.background ? ", on a background" : ""));
    RasterizeSettings on = settings;
    if (c.background) on.background = torch::linspace(0.1, 0.9, c.C);
    torch::manual_seed(72 + c.K + c.C);
    const torch::Tensor weights = torch::rand({n, c.K}), indices = torch::randint(0, c.C, {n, c.K}, torch::kInt32);
    const torch::Tensor w = torch::randn({s.cam.height, s.cam.width, c.C});
    std::vector<torch::Tensor> images, grads, mean_grads;
    for (const torch::Device dev : {torch::Device(torch::kCPU), torch::Device(torch::kCUDA)}) {
      const torch::Tensor v = weights.to(dev).detach().requires_grad_(true);
      const torch::Tensor means = float_tensor(s.means, {n, 3}).to(dev).detach().requires_grad_(c.geometry);
      const auto o = rasterize_sparse_features(means, float_tensor(s.scales, {n, 3}).to(dev),
                                               float_tensor(s.quats, {n, 4}).to(dev), float_tensor(s.opacities, {n}).to(dev),
                                               v, indices.to(dev), c.C, {}, on);
      (o.image * w.to(dev)).sum().backward();
      images.push_back(o.image.cpu());
      grads.push_back(v.grad().cpu());
      if (c.geometry) mean_grads.push_back(means.grad().cpu());
    }
    EXPECT_LT((images[1] - images[0]).abs().max().item<float>(), 1e-5f);
    const double scale = grads[0].abs().max().item<double>();
    ASSERT_GT(scale, 0.0);
    EXPECT_LT((grads[1] - grads[0]).abs().max().item<double>(), 1e-4 * scale);
    if (c.geometry) {
      const double mscale = mean_grads[0].abs().max().item<double>();
      ASSERT_GT(mscale, 0.0);
      EXPECT_LT((mean_grads[1] - mean_grads[0]).abs().max().item<double>(), 1e-3 * mscale);
    }
  }
}

TEST(SplatCuda, ForwardMatchesCpu) {
  if (!torch::cuda::is_available()) GTEST_SKIP() << "no CUDA device: the CUDA rasterizer is not compared with the CPU path";
  compare_cuda_cpu(test::random_scene(400, 70, 45, 3, true, 31, 0.98));
  for (int C : {1, 3, 16, 32, 128}) compare_cuda_cpu(test::random_scene(300, 53, 37, C, false, 40 + C, 0.98));
}

}  // namespace
}  // namespace cls

#else

TEST(SplatCuda, ForwardMatchesCpu) {
  GTEST_SKIP() << "built without the CUDA backend (CLS_WITH_CUDA): the CUDA rasterizer is not compared with the CPU path";
}
TEST(SplatCuda, GradientsMatchCpu) {
  GTEST_SKIP() << "built without the CUDA backend (CLS_WITH_CUDA): the CUDA backward is not compared with the CPU path";
}
TEST(SplatCuda, FeatureGradientsWithoutGeometryMatchCpu) {
  GTEST_SKIP() << "built without the CUDA backend (CLS_WITH_CUDA): the CUDA backward is not compared with the CPU path";
}
TEST(SplatCuda, SsimKernelsMatchTheOps) {
  GTEST_SKIP() << "built without the CUDA backend (CLS_WITH_CUDA): the CUDA SSIM kernels are not compared with the ops";
}
TEST(SplatCuda, SparseFeaturesMatchCpu) {
  GTEST_SKIP() << "built without the CUDA backend (CLS_WITH_CUDA): the sparse CUDA kernels are not compared with the CPU path";
}

#endif
