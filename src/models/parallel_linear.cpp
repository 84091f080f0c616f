#include "models/parallel_linear.h"

#include <ATen/Parallel.h>
#include <torch/torch.h>

#include <algorithm>

namespace cls {

bool split_over_threads(const torch::Tensor& x) {
  return x.device().is_cpu() && at::get_num_threads() > 1 && !(torch::GradMode::is_enabled() && x.requires_grad());
}

ScopedBlasThreads blas_threads_for_split(const torch::Tensor& x) {
  return ScopedBlasThreads(split_over_threads(x) ? 1 : blas_threads());
}

torch::Tensor parallel_rows_linear(const torch::Tensor& x, const torch::Tensor& weight, const torch::Tensor& bias) {
  const int64_t threads = at::get_num_threads(), in = x.size(-1), rows = x.numel() / std::max<int64_t>(1, in);
  const bool records = torch::GradMode::is_enabled() && (weight.requires_grad() || (bias.defined() && bias.requires_grad()));
  if (!split_over_threads(x) || records || rows < 64 * threads) return at::linear(x, weight, bias);
  const auto x2 = x.reshape({rows, in});
  const auto wt = weight.t();
  auto out = torch::empty({rows, weight.size(0)}, x.options());
  at::parallel_for(0, rows, (rows + threads - 1) / threads, [&](int64_t r0, int64_t r1) {
    torch::NoGradGuard no_grad;  // the worker threads' own grad mode
    auto block = out.slice(0, r0, r1);
    if (bias.defined()) at::addmm_out(block, bias, x2.slice(0, r0, r1), wt);
    else at::mm_out(block, x2.slice(0, r0, r1), wt);
  });
  auto sizes = x.sizes().vec();
  sizes.back() = weight.size(0);
  return out.view(sizes);
}

}  // namespace cls
