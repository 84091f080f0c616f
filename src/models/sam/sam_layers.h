#pragma once
// Small building blocks shared by SAM's image encoder, prompt encoder and mask decoder
// (segment_anything/modeling/common.py and mask_decoder.py's MLP). Parameter names follow the
// official state_dict so that named_parameters() yields the checkpoint keys.
#include <torch/torch.h>

namespace cls::sam {

// The largest float32 block the CPU paths of SAM compute at once (encoder attention bands, AMG
// decoder and upsampling slices). Under glibc's 32 MB mmap ceiling, so freed blocks are reused from
// the heap instead of being mapped, faulted in and unmapped again on every step (the reference's
// whole-batch tensors of 64-805 MB spent half the AMG's CPU time in the kernel), and near the size
// of a last-level cache. Only the blocking changes: each row, prompt and mask is computed on its own.
constexpr int64_t kCpuBlockBytes = int64_t(16) << 20;

// LayerNorm over the channel dimension of an NCHW tensor (common.py LayerNorm2d): mean and biased
// variance over C, (x - u) / sqrt(var + eps), then per-channel affine.
struct LayerNorm2dImpl : torch::nn::Module {
  explicit LayerNorm2dImpl(int64_t channels, double eps = 1e-6);
  torch::Tensor forward(const torch::Tensor& x);
  torch::Tensor weight, bias;
  double eps;
};
TORCH_MODULE(LayerNorm2d);

enum class Activation { GELU, ReLU };

// lin1 -> act -> lin2 (common.py MLPBlock). GELU is the exact (erf) one.
struct MLPBlockImpl : torch::nn::Module {
  MLPBlockImpl(int64_t embedding_dim, int64_t mlp_dim, Activation act);
  torch::Tensor forward(const torch::Tensor& x);
  torch::nn::Linear lin1{nullptr}, lin2{nullptr};
  Activation act;
};
TORCH_MODULE(MLPBlock);

// num_layers Linear layers named layers.N with ReLU between them (mask_decoder.py MLP; no sigmoid).
struct MLPImpl : torch::nn::Module {
  MLPImpl(int64_t input_dim, int64_t hidden_dim, int64_t output_dim, int num_layers);
  torch::Tensor forward(torch::Tensor x);
  torch::nn::ModuleList layers;
};
TORCH_MODULE(MLP);

torch::Tensor activate(const torch::Tensor& x, Activation act);

}  // namespace cls::sam
