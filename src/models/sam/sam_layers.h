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

// Whether to split this CPU work over LibTorch's threads by hand (parallel_rows_linear, the encoder's
// attention bands): on the CPU, without autograd (the worker threads do not record it), with threads.
bool split_over_threads(const torch::Tensor& x);

// lin(x) with x's rows split over LibTorch's threads, each block one GEMM on its own thread (when
// split_over_threads and there are rows enough; else lin(x)). For the image encoder, which holds
// OpenBLAS to the calling thread (ScopedBlasThreads): one thread pool then does all its work, where
// LibTorch's OpenMP pool and OpenBLAS's own otherwise take turns spinning and yielding on the same
// cores (docs/benchmarks.md, "The AMG on 2 cores").
torch::Tensor parallel_rows_linear(const torch::Tensor& x, torch::nn::LinearImpl& lin);

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
