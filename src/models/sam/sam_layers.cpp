#include "models/sam/sam_layers.h"

#include <ATen/Parallel.h>

namespace cls::sam {

LayerNorm2dImpl::LayerNorm2dImpl(int64_t channels, double eps_) : eps(eps_) {
  weight = register_parameter("weight", torch::ones({channels}));
  bias = register_parameter("bias", torch::zeros({channels}));
}

torch::Tensor LayerNorm2dImpl::forward(const torch::Tensor& x) {
  const auto u = x.mean(1, /*keepdim=*/true);
  const auto s = (x - u).pow(2).mean(1, /*keepdim=*/true);
  const auto y = (x - u) / torch::sqrt(s + eps);
  return weight.view({-1, 1, 1}) * y + bias.view({-1, 1, 1});
}

bool split_over_threads(const torch::Tensor& x) {
  return x.device().is_cpu() && !torch::GradMode::is_enabled() && at::get_num_threads() > 1;
}

torch::Tensor parallel_rows_linear(const torch::Tensor& x, torch::nn::LinearImpl& lin) {
  const int64_t threads = at::get_num_threads(), in = x.size(-1), rows = x.numel() / std::max<int64_t>(1, in);
  if (!split_over_threads(x) || rows < 64 * threads) return lin.forward(x);
  const auto x2 = x.reshape({rows, in});
  const auto wt = lin.weight.t();
  auto out = torch::empty({rows, lin.weight.size(0)}, x.options());
  at::parallel_for(0, rows, (rows + threads - 1) / threads, [&](int64_t r0, int64_t r1) {
    torch::NoGradGuard no_grad;  // the worker threads' own grad mode
    auto block = out.slice(0, r0, r1);
    if (lin.bias.defined()) at::addmm_out(block, lin.bias, x2.slice(0, r0, r1), wt);
    else at::mm_out(block, x2.slice(0, r0, r1), wt);
  });
  auto sizes = x.sizes().vec();
  sizes.back() = lin.weight.size(0);
  return out.view(sizes);
}

torch::Tensor activate(const torch::Tensor& x, Activation act) {
  return act == Activation::GELU ? torch::gelu(x) : torch::relu(x);
}

MLPBlockImpl::MLPBlockImpl(int64_t embedding_dim, int64_t mlp_dim, Activation act_) : act(act_) {
  lin1 = register_module("lin1", torch::nn::Linear(embedding_dim, mlp_dim));
  lin2 = register_module("lin2", torch::nn::Linear(mlp_dim, embedding_dim));
}

torch::Tensor MLPBlockImpl::forward(const torch::Tensor& x) {
  return parallel_rows_linear(activate(parallel_rows_linear(x, *lin1), act), *lin2);
}

MLPImpl::MLPImpl(int64_t input_dim, int64_t hidden_dim, int64_t output_dim, int num_layers) {
  for (int i = 0; i < num_layers; ++i) {
    const int64_t in = i == 0 ? input_dim : hidden_dim;
    const int64_t out = i == num_layers - 1 ? output_dim : hidden_dim;
    layers->push_back(torch::nn::Linear(in, out));
  }
  register_module("layers", layers);
}

torch::Tensor MLPImpl::forward(torch::Tensor x) {
  const size_t n = layers->size();
  for (size_t i = 0; i < n; ++i) {
    x = layers[i]->as<torch::nn::Linear>()->forward(x);
    if (i + 1 < n) x = torch::relu(x);
  }
  return x;
}

}  // namespace cls::sam
