#pragma once
// The shared autoencoder (paper 3.2): MLP encoder D -> ... -> latent (default 512 -> 256 -> 128) and
// decoder latent -> ... -> D (128 -> 256 -> 512), trained on SAM features only with
// L_rec = ||f - f^||^2 + lambda_cos (1 - cos(f, f^)) per sample, then applied to both sources.
#include <ATen/core/Tensor.h>

#include <memory>
#include <string>
#include <vector>

namespace cls {

struct AutoencoderConfig {
  int input_dim = 512;
  std::vector<int> encoder_dims{256, 128};  // the last one is the latent size
  std::vector<int> decoder_dims{256, 512};  // the last one must equal input_dim
  int latent_dim() const { return encoder_dims.back(); }
};

struct AutoencoderTrainOptions {
  int epochs = 100;
  int batch_size = 256;
  double lr = 1e-3;
  double lambda_cos = 1.0;
  double holdout_fraction = 0.1;  // held-out features for the reported cosine
  uint64_t seed = 1;
};

struct AutoencoderReport {
  double train_loss = 0;
  double holdout_cosine = 0;  // mean cos(f, D(E(f))) on held-out features
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
  // Trains on `sam_features` (B x D float32).
  AutoencoderReport train(const at::Tensor& sam_features, const AutoencoderTrainOptions& options);

  // safetensors with the config in its metadata; load() gives a cls::Error naming the file on
  // missing/mis-shaped tensors or a bad config.
  void save(const std::string& path) const;
  static Autoencoder load(const std::string& path);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Per-sample loss, exposed for tests: ||f - r||^2 + lambda_cos (1 - cos(f, r)), B values.
at::Tensor reconstruction_loss(const at::Tensor& f, const at::Tensor& r, double lambda_cos);

}  // namespace cls
