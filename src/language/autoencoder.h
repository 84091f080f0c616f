#pragma once
// The shared autoencoder (paper 3.2): MLP encoder D -> ... -> latent (default 512 -> 256 -> 128) and
// decoder latent -> ... -> D (128 -> 256 -> 512), trained on SAM features only with
// L_rec = ||f - f^||^2 + lambda_cos (1 - cos(f, f^)) per sample, then applied to both sources.
#include <ATen/core/Tensor.h>
#include <c10/core/Device.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace cls {

struct AutoencoderConfig {
  int input_dim = 512;
  std::vector<int> encoder_dims{256, 128};  // the last one is the latent size
  std::vector<int> decoder_dims{256, 512};  // the last one must equal input_dim
  // LangSplat's autoencoder L2-normalises the latent (so latents of both sources share one scale) and
  // the output; we keep the latent normalisation and leave the output unnormalised by default, so
  // the paper's Euclidean term can preserve the features' scale (docs/autoencoder.md).
  bool normalize_latent = true;
  bool normalize_output = false;
  int latent_dim() const { return encoder_dims.back(); }
  // Throws cls::Error when a size is not positive, a list is empty or decoder_dims.back() != input_dim.
  void validate() const;
};

struct AutoencoderTrainOptions {
  int epochs = 100;
  int batch_size = 256;
  double lr = 1e-3;
  double lambda_cos = 1.0;
  double holdout_fraction = 0.1;  // held-out features for the reported cosine
  uint64_t seed = 1;
  // Called after every epoch with the epoch (1-based) and its mean training loss (progress output).
  std::function<void(int epoch, double train_loss)> on_epoch;
  // Called after every mini-batch with the batches an epoch has (progress within an epoch, which takes
  // minutes over the features of hundreds of photos).
  std::function<void(size_t batches_per_epoch)> on_batch;
};

struct AutoencoderReport {
  double train_loss = 0;
  double holdout_cosine = 0;  // mean cos(f, D(E(f))) on held-out features; NaN when none are held out
  int64_t train_samples = 0, holdout_samples = 0;
  double seconds = 0;
};

class Autoencoder {
 public:
  Autoencoder(const AutoencoderConfig& config, uint64_t seed);
  ~Autoencoder();
  Autoencoder(Autoencoder&&) noexcept;
  Autoencoder& operator=(Autoencoder&&) noexcept;

  const AutoencoderConfig& config() const;
  at::Tensor encode(const at::Tensor& features) const;  // B x D -> B x latent (no grad, eval mode)
  at::Tensor decode(const at::Tensor& latents) const;   // B x latent -> B x D
  // The decoder split before its last linear layer: decode(z) = n(decode_hidden(z) W^T + b), n the output
  // normalisation when configured. Relevance maps use the split to take cosines of decoded features
  // without forming them (query/relevance.h). B x latent -> B x H (H: the last layer's input size).
  at::Tensor decode_hidden(const at::Tensor& latents) const;
  const at::Tensor& output_weight() const;  // W, D x H
  const at::Tensor& output_bias() const;    // b, D
  // Moves the weights (encode/decode then take inputs on any device and answer on this one).
  void to(const c10::Device& device);
  c10::Device device() const;
  // Trains on `sam_features` (B x D float32; any device, trained on device()). Deterministic for a
  // seed on one machine and thread count. Throws cls::Error for a wrong shape, non-finite values,
  // fewer than 2 training samples or invalid options.
  AutoencoderReport train(const at::Tensor& sam_features, const AutoencoderTrainOptions& options);

  // safetensors with the config in its metadata; load() gives a cls::Error naming the file on
  // missing/mis-shaped tensors or a bad config.
  void save(const std::string& path) const;
  static Autoencoder load(const std::string& path);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// LangSplat as published (the paper's "original implementation with its default configuration" baseline):
// 512 -> 256, 128, 64, 32, 3 -> 16, 32, 64, 128, 256, 256, 512, latent and output normalised, Adam lr 7e-4
// (its published command, process.sh: `train.py ... --lr 0.0007`; train.py's own default is 1e-4) in
// batches of 64. Its loss mean((f - f^)^2) + 0.001 (1 - cos) is ours
// with lambda_cos = 0.512 up to the factor 1/512 (its mean runs over the 512 channels too); its cosine runs
// over the batch axis (F.cosine_similarity(..., dim=0)), a quirk not reproduced: ours is per feature.
AutoencoderConfig langsplat_autoencoder_config(int input_dim = 512);  // the decoder ends in input_dim
AutoencoderTrainOptions langsplat_autoencoder_training();

// Per-sample loss, exposed for tests: ||f - r||^2 + lambda_cos (1 - cos(f, r)), B values.
at::Tensor reconstruction_loss(const at::Tensor& f, const at::Tensor& r, double lambda_cos);

}  // namespace cls
