#include "render/view_images.h"

#include <torch/torch.h>

#include "core/error.h"

namespace cls {

at::Tensor expected_depth(const at::Tensor& depth, const at::Tensor& alpha) {
  const at::Tensor d = depth.to(torch::kCPU, torch::kFloat32), a = alpha.to(torch::kCPU, torch::kFloat32);
  return torch::where(a > 0, d / a.clamp_min(1e-12), torch::zeros_like(d));
}

MapRange depth_range(const at::Tensor& depth, const at::Tensor& covered) {
  const at::Tensor values = depth.index({covered}).to(torch::kFloat64);
  if (values.numel() == 0) return {0, 1};
  const at::Tensor q = torch::quantile(values, torch::tensor({0.02, 0.98}, torch::kFloat64));
  MapRange r{q[0].item<double>(), q[1].item<double>()};
  if (!(r.hi > r.lo)) r.lo = r.hi - 1;
  return r;
}

cv::Mat colour_depth(const at::Tensor& depth, const at::Tensor& covered, MapRange range) {
  cv::Mat img = colour_map(depth, range);
  const at::Tensor mask = covered.logical_not().to(torch::kCPU, torch::kUInt8).mul(255).contiguous();
  img.setTo(cv::Scalar(0, 0, 0), cv::Mat(img.rows, img.cols, CV_8UC1, mask.data_ptr<uint8_t>()));
  return img;
}

cv::Mat relevance_overlay(const cv::Mat& render_bgr, const at::Tensor& relevancy) {
  const at::Tensor r = relevancy.to(torch::kCPU, torch::kFloat32);
  if (r.dim() != 2 || r.size(0) != render_bgr.rows || r.size(1) != render_bgr.cols)
    throw Error("relevance overlay: the map and the render differ in size");
  const cv::Mat heat = colour_map(r, MapRange{0, 1});
  const at::Tensor w = ((r - 0.5) * (2 * kOverlayMaxWeight)).clamp(0, kOverlayMaxWeight).contiguous();
  cv::Mat out(render_bgr.size(), CV_8UC3);
  const float* wp = w.data_ptr<float>();
  for (int y = 0; y < out.rows; ++y)
    for (int x = 0; x < out.cols; ++x) {
      const float a = wp[size_t(y) * out.cols + x];
      const cv::Vec3b &base = render_bgr.at<cv::Vec3b>(y, x), &hot = heat.at<cv::Vec3b>(y, x);
      for (int c = 0; c < 3; ++c) out.at<cv::Vec3b>(y, x)[c] = cv::saturate_cast<uint8_t>((1 - a) * base[c] + a * hot[c]);
    }
  return out;
}

cv::Mat side_by_side(const std::vector<cv::Mat>& images) {
  constexpr int kGap = 4;
  std::vector<cv::Mat> parts;
  for (const cv::Mat& m : images) {
    if (m.rows != images.front().rows || m.type() != images.front().type())
      throw Error("side by side: images of different heights or types");
    if (!parts.empty()) parts.push_back(cv::Mat(m.rows, kGap, m.type(), cv::Scalar::all(255)));
    parts.push_back(m);
  }
  cv::Mat out;
  cv::hconcat(parts, out);
  return out;
}

}  // namespace cls
