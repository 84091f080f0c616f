// LangSplat mask_nms as batched tensor algebra (for GPUs): intersections I = X X^T of the flattened
// 0/1 masks, accumulated over pixel chunks; then the reference's decision in matrix form:
//   Q[a, b] = I[a, b] / area[a] (share of mask a covered by b), IoU = I / (A_a + A_b - I),
//   inner[a, b] = 1 - Q[b, a] Q[a, b] where Q[a, b] < 0.5 and Q[b, a] >= 0.85 (this single rule
//   yields both of the reference's assignments: a < b is its first branch, a > b its second),
//   iou_max = triu(IoU, 1).max(0), inner_u = triu(inner, 1).max(0), inner_l = tril(inner, 1).max(0).
// Verified on CPU against mask_nms_reference by the tests; the CUDA path is the same code on a CUDA
// device and is unverified here (no GPU in this build environment).
#include <torch/torch.h>

#include <algorithm>

#include "core/error.h"
#include "models/sam_amg/mask_nms.h"

namespace cls::amg {

std::vector<int> mask_nms_torch(const std::vector<BinaryMask>& masks, const std::vector<double>& scores,
                                const MaskNmsParams& params, const char* device_name) {
  if (masks.size() != scores.size()) throw Error("mask_nms: masks and scores differ in length");
  const int64_t n = static_cast<int64_t>(masks.size());
  if (n == 0) return {};
  const int64_t pixels = static_cast<int64_t>(masks[0].pixels.size());
  for (const auto& m : masks)
    if (m.height != masks[0].height || m.width != masks[0].width) throw Error("mask_nms: masks differ in size");
  const torch::Device device(device_name);
  const std::vector<int> idx = score_order(scores);
  std::vector<double> sorted_scores(n);
  for (int64_t k = 0; k < n; ++k) sorted_scores[k] = scores[idx[k]];

  // Chunks of about 64 MiB of float32 on the host; partial products are integers < 2^24, exact in
  // float32 (also under TF32, whose inputs are exact for 0/1), summed in float64.
  const int64_t chunk = std::max<int64_t>(4096, (int64_t(16) << 20) / n);
  torch::NoGradGuard no_grad;
  auto inter = torch::zeros({n, n}, torch::TensorOptions().dtype(torch::kFloat64).device(device));
  auto area = torch::zeros({n}, torch::TensorOptions().dtype(torch::kFloat64).device(device));
  for (int64_t p0 = 0; p0 < pixels; p0 += chunk) {
    const int64_t len = std::min(chunk, pixels - p0);
    auto host = torch::empty({n, len}, torch::kUInt8);
    uint8_t* dst = host.data_ptr<uint8_t>();
    for (int64_t k = 0; k < n; ++k)
      std::copy_n(masks[idx[k]].pixels.data() + p0, len, dst + k * len);
    auto x = host.to(device).to(torch::kFloat32);
    inter += torch::matmul(x, x.t()).to(torch::kFloat64);
    area += x.sum(1, /*keepdim=*/false, torch::kFloat64);
  }
  const auto fi = inter.to(torch::kFloat32);
  const auto fa = area.to(torch::kFloat32);
  const auto fu = (area.unsqueeze(1) + area.unsqueeze(0) - inter).to(torch::kFloat32);  // exact integers
  const auto iou = fi / fu;
  const auto q = fi / fa.unsqueeze(1);
  const auto qt = q.t();
  const auto inner = torch::where((q < 0.5f) & (qt >= 0.85f), 1.0f - qt * q, torch::zeros_like(q));
  const auto iou_max = std::get<0>(torch::triu(iou, 1).max(0)).cpu().contiguous();
  const auto inner_u = std::get<0>(torch::triu(inner, 1).max(0)).cpu().contiguous();
  const auto inner_l = std::get<0>(torch::tril(inner, 1).max(0)).cpu().contiguous();
  auto to_vec = [](const torch::Tensor& t) {
    return std::vector<float>(t.data_ptr<float>(), t.data_ptr<float>() + t.numel());
  };
  return select_kept(idx, sorted_scores, to_vec(iou_max), to_vec(inner_u), to_vec(inner_l), params);
}

}  // namespace cls::amg
