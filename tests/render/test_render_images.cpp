// The pieces of `render` that make pictures: PSNR, feature PCA, depth colouring, the MP4 writer.
#include <gtest/gtest.h>
#include <torch/torch.h>

#include <cmath>
#include <filesystem>
#include <opencv2/videoio.hpp>

#include "core/error.h"
#include "models/temp_dir.h"
#include "render/feature_pca.h"
#include "render/render_job.h"
#include "render/video_file.h"
#include "render/view_images.h"
#include "splat/image_tensor.h"
#include "splat/ssim.h"

namespace cls {
namespace {
namespace fs = std::filesystem;

TEST(RenderImages, PsnrMatchesADoublePrecisionHandComputation) {
  torch::manual_seed(1);
  const at::Tensor a = torch::rand({13, 17, 3}), b = (a + 0.05 * torch::randn({13, 17, 3})).clamp(0, 1);
  const auto pa = a.accessor<float, 3>(), pb = b.accessor<float, 3>();
  double se = 0;
  for (int y = 0; y < 13; ++y)
    for (int x = 0; x < 17; ++x)
      for (int c = 0; c < 3; ++c) se += std::pow(double(pa[y][x][c]) - double(pb[y][x][c]), 2);
  const double expected = 10 * std::log10(1.0 / (se / (13 * 17 * 3)));
  EXPECT_NEAR(psnr(a, b), expected, 1e-4);
  EXPECT_NEAR(psnr(a, a), 200, 1e-9);  // the MSE floor
  EXPECT_THROW(psnr(a, b.slice(0, 1)), Error);
}

TEST(RenderImages, ImageTensorRoundTrip) {
  cv::Mat bgr(5, 7, CV_8UC3);
  cv::randu(bgr, 0, 256);
  const at::Tensor t = image_to_tensor(bgr);
  EXPECT_FLOAT_EQ(t[2][3][0].item<float>(), bgr.at<cv::Vec3b>(2, 3)[2] / 255.0f);  // R first
  EXPECT_EQ(cv::norm(tensor_to_image(t), bgr, cv::NORM_INF), 0);
}

TEST(RenderImages, PcaFindsTheKnownPrincipalDirection) {
  // f(y, x) = m + a(x) d1 + 0.1 b(y) d2 with orthonormal d1, d2 in C = 6: the first component is d1
  // (sign: its largest entry positive), the second d2; red rises with a(x), green with b(y).
  const int H = 20, W = 30, C = 6;
  const at::Tensor d1 = torch::tensor({0.1, -0.2, 0.9, 0.3, 0.0, 0.2}, torch::kFloat64);
  at::Tensor d2 = torch::tensor({0.5, 0.5, 0.0, -0.5, 0.5, 0.0}, torch::kFloat64);
  const at::Tensor u1 = d1 / d1.norm();
  d2 = d2 - d2.dot(u1) * u1;
  const at::Tensor u2 = d2 / d2.norm();
  const at::Tensor a = torch::linspace(-1, 1, W, torch::kFloat64), b = torch::linspace(-1, 1, H, torch::kFloat64);
  const at::Tensor f = (torch::full({C}, 0.3, torch::kFloat64) + a.view({1, W, 1}) * u1 + 0.1 * b.view({H, 1, 1}) * u2)
                           .to(torch::kFloat32);
  at::Tensor mask = torch::ones({H, W}, torch::kBool);
  at::Tensor noisy = f.clone();
  noisy.index_put_({0}, 100.0f);  // garbage in the masked-out first row
  mask.index_put_({0}, false);
  const FeaturePca pca = fit_feature_pca(noisy, mask);
  const int biggest = int(u1.abs().argmax().item<int64_t>());
  const at::Tensor expected1 = u1 * u1[biggest].sign();
  EXPECT_NEAR(pca.components.select(1, 0).dot(expected1).item<double>(), 1.0, 1e-6);
  EXPECT_NEAR(std::abs(pca.components.select(1, 1).dot(u2).item<double>()), 1.0, 1e-6);

  const at::Tensor rgb = apply_feature_pca(pca, f);
  ASSERT_EQ(rgb.sizes(), (std::vector<int64_t>{H, W, 3}));
  EXPECT_GE(rgb.min().item<float>(), 0.0f);
  EXPECT_LE(rgb.max().item<float>(), 1.0f);
  const float sign = expected1.dot(u1).item<double>() > 0 ? 1.0f : -1.0f;  // red follows a(x) with this sign
  const at::Tensor red = rgb.select(2, 0)[H / 2];
  for (int x = 1; x < W; ++x) EXPECT_GE(sign * (red[x] - red[x - 1]).item<float>(), 0.0f) << x;
  EXPECT_GT((red[W - 1] - red[0]).abs().item<float>(), 0.9f);  // the 1st-99th percentile range fills [0, 1]
  EXPECT_THROW(fit_feature_pca(f, torch::zeros({H, W}, torch::kBool)), Error);
  EXPECT_THROW(apply_feature_pca(pca, f.slice(2, 0, 4)), Error);
}

TEST(RenderImages, ExpectedDepthAndItsColours) {
  const at::Tensor alpha = torch::tensor({{1.0f, 0.5f}, {0.0f, 0.25f}});
  const at::Tensor depth = torch::tensor({{2.0f, 1.5f}, {0.0f, 1.0f}});  // sum alpha_i T_i z_i
  const at::Tensor d = expected_depth(depth, alpha);
  EXPECT_FLOAT_EQ(d[0][0].item<float>(), 2);
  EXPECT_FLOAT_EQ(d[0][1].item<float>(), 3);
  EXPECT_FLOAT_EQ(d[1][0].item<float>(), 0);
  EXPECT_FLOAT_EQ(d[1][1].item<float>(), 4);
  const at::Tensor covered = alpha >= kCoveredAlpha;
  const MapRange r = depth_range(d, covered);
  EXPECT_NEAR(r.lo, 2 + 0.02, 1e-9);  // linear percentiles of {2, 3}
  EXPECT_NEAR(r.hi, 2 + 0.98, 1e-9);
  const cv::Mat img = colour_depth(d, covered, r);
  EXPECT_EQ(img.at<cv::Vec3b>(1, 1), cv::Vec3b(0, 0, 0));  // not covered: black
  EXPECT_NE(img.at<cv::Vec3b>(0, 0), img.at<cv::Vec3b>(0, 1));
}

TEST(RenderImages, OverlayKeepsTheRenderWhereRelevanceIsLow) {
  cv::Mat render(2, 2, CV_8UC3, cv::Scalar(10, 20, 30));
  const cv::Mat out = relevance_overlay(render, torch::tensor({{0.0f, 0.5f}, {0.75f, 1.0f}}));
  EXPECT_EQ(out.at<cv::Vec3b>(0, 0), render.at<cv::Vec3b>(0, 0));
  EXPECT_EQ(out.at<cv::Vec3b>(0, 1), render.at<cv::Vec3b>(0, 1));
  EXPECT_NE(out.at<cv::Vec3b>(1, 1), render.at<cv::Vec3b>(1, 1));
}

TEST(RenderImages, Mp4ReadsBackWithItsFrameCountAndSize) {
  test::TempDir tmp;
  const fs::path path = tmp.path / "v" / "clip.mp4";
  const int frames = 9;
  const cv::Size size(64, 48);
  {
    VideoFile video(path, 12, size);
    for (int k = 0; k < frames; ++k) video.write(cv::Mat(size, CV_8UC3, cv::Scalar(20 * k, 100, 255 - 20 * k)));
    EXPECT_FALSE(fs::exists(path));  // only a temporary until finish()
    video.finish();
  }
  cv::VideoCapture cap(path.string(), cv::CAP_FFMPEG);
  ASSERT_TRUE(cap.isOpened());
  EXPECT_EQ(cap.get(cv::CAP_PROP_FRAME_COUNT), frames);
  int read = 0;
  for (cv::Mat f; cap.read(f); ++read) EXPECT_EQ(f.size(), size);
  EXPECT_EQ(read, frames);
  EXPECT_EQ(std::distance(fs::directory_iterator(path.parent_path()), fs::directory_iterator()), 1);
  EXPECT_THROW(VideoFile(tmp.path / "odd.mp4", 12, cv::Size(63, 48)), Error);
  {
    VideoFile abandoned(tmp.path / "abandoned.mp4", 12, size);
    EXPECT_THROW(abandoned.write(cv::Mat(cv::Size(32, 48), CV_8UC3)), Error);
  }
  EXPECT_FALSE(fs::exists(tmp.path / "abandoned.mp4"));
  EXPECT_EQ(std::distance(fs::directory_iterator(tmp.path), fs::directory_iterator()), 1);  // v/ only
}

TEST(RenderImages, WhatListKeepsCommasInsideRelevanceTexts) {
  EXPECT_EQ(split_what("rgb,relevance:red roof, tiles,depth,relevance:window"),
            (std::vector<std::string>{"rgb", "relevance:red roof, tiles", "depth", "relevance:window"}));
  EXPECT_EQ(split_what(""), std::vector<std::string>{});
}

}  // namespace
}  // namespace cls
