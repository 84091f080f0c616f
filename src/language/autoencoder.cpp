// The shared autoencoder (paper 3.2). Layer layout follows LangSplat's autoencoder/model.py so the
// tensor names match its state_dict: encoder = Linear, then (BatchNorm1d, ReLU, Linear) per further
// size; decoder = Linear, then (ReLU, Linear) per further size; see docs/autoencoder.md.
#include "language/autoencoder.h"

#include <ATen/CPUGeneratorImpl.h>
#include <torch/torch.h>

#include <chrono>
#include <cmath>
#include <nlohmann/json.hpp>
#include <set>

#include "core/error.h"
#include "core/log.h"
#include "models/parallel_linear.h"
#include "models/weights/safetensors.h"

namespace cls {
namespace {

constexpr const char* kMetadataKey = "citylangsplat_autoencoder";
constexpr const char* kFormatName = "citylangsplat-autoencoder";
constexpr double kNormEps = 1e-12;  // as torch.nn.functional.normalize

// x / max(||x||, eps) per row.
at::Tensor l2_normalize(const at::Tensor& x) {
  return x / x.norm(2, {1}, /*keepdim=*/true).clamp_min(kNormEps);
}

struct AutoencoderNetImpl : torch::nn::Module {
  torch::nn::Sequential encoder{nullptr}, decoder{nullptr};

  explicit AutoencoderNetImpl(const AutoencoderConfig& c) {
    torch::nn::Sequential enc;
    enc->push_back(torch::nn::Linear(c.input_dim, c.encoder_dims[0]));
    for (size_t i = 1; i < c.encoder_dims.size(); ++i) {
      enc->push_back(torch::nn::BatchNorm1d(c.encoder_dims[i - 1]));
      enc->push_back(torch::nn::ReLU());
      enc->push_back(torch::nn::Linear(c.encoder_dims[i - 1], c.encoder_dims[i]));
    }
    torch::nn::Sequential dec;
    dec->push_back(torch::nn::Linear(c.latent_dim(), c.decoder_dims[0]));
    for (size_t i = 1; i < c.decoder_dims.size(); ++i) {
      dec->push_back(torch::nn::ReLU());
      dec->push_back(torch::nn::Linear(c.decoder_dims[i - 1], c.decoder_dims[i]));
    }
    encoder = register_module("encoder", enc);
    decoder = register_module("decoder", dec);
  }
};
TORCH_MODULE(AutoencoderNet);

nlohmann::json config_json(const AutoencoderConfig& c) {
  return {{"format", kFormatName},
          {"version", 1},
          {"input_dim", c.input_dim},
          {"encoder_dims", c.encoder_dims},
          {"decoder_dims", c.decoder_dims},
          {"normalize_latent", c.normalize_latent},
          {"normalize_output", c.normalize_output}};
}

AutoencoderConfig config_from_json(const std::string& path, const std::string& text) {
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& e) {
    fail(path, std::string("metadata '") + kMetadataKey + "' is not valid JSON: " + e.what());
  }
  AutoencoderConfig c;
  try {
    if (j.value("format", std::string()) != kFormatName)
      fail(path, std::string("metadata '") + kMetadataKey + "' is not a " + kFormatName + " config");
    if (j.at("version").get<int>() != 1)
      fail(path, "unsupported autoencoder format version " + j.at("version").dump());
    c.input_dim = j.at("input_dim").get<int>();
    c.encoder_dims = j.at("encoder_dims").get<std::vector<int>>();
    c.decoder_dims = j.at("decoder_dims").get<std::vector<int>>();
    c.normalize_latent = j.at("normalize_latent").get<bool>();
    c.normalize_output = j.at("normalize_output").get<bool>();
  } catch (const nlohmann::json::exception& e) {
    fail(path, std::string("metadata '") + kMetadataKey + "': " + e.what());
  }
  try {
    c.validate();
  } catch (const Error& e) {
    fail(path, e.what());
  }
  return c;
}

// nn.Linear's default initialisation (kaiming_uniform with a = sqrt(5): U(-1/sqrt(fan_in),
// 1/sqrt(fan_in)) for weight and bias), drawn from our own generator so a seed fixes it.
void init_linear_layers(AutoencoderNet& net, at::Generator& gen) {
  torch::NoGradGuard no_grad;
  for (const auto& m : net->modules(/*include_self=*/false)) {
    if (auto* linear = m->as<torch::nn::Linear>()) {
      const double bound = 1.0 / std::sqrt(static_cast<double>(linear->options.in_features()));
      linear->weight.uniform_(-bound, bound, gen);
      linear->bias.uniform_(-bound, bound, gen);
    }
  }
}

std::string sizes_string(at::IntArrayRef s) {
  return shape_string(std::vector<int64_t>(s.begin(), s.end()));
}

}  // namespace

AutoencoderConfig langsplat_autoencoder_config(int input_dim) {
  AutoencoderConfig c;
  c.input_dim = input_dim;
  c.encoder_dims = {256, 128, 64, 32, 3};
  c.decoder_dims = {16, 32, 64, 128, 256, 256, input_dim};
  c.normalize_latent = true;
  c.normalize_output = true;
  return c;
}

AutoencoderTrainOptions langsplat_autoencoder_training() {
  AutoencoderTrainOptions o;
  o.lr = 7e-4;  // process.sh's --lr 0.0007, not train.py's default 1e-4 (autoencoder.h)
  o.batch_size = 64;
  o.lambda_cos = 0.512;
  return o;
}

void AutoencoderConfig::validate() const {
  auto positive = [](const std::vector<int>& v) {
    for (int d : v)
      if (d <= 0) return false;
    return true;
  };
  if (input_dim <= 0) throw Error("autoencoder: input_dim must be positive");
  if (encoder_dims.empty() || !positive(encoder_dims))
    throw Error("autoencoder: encoder_dims must be a non-empty list of positive sizes");
  if (decoder_dims.empty() || !positive(decoder_dims))
    throw Error("autoencoder: decoder_dims must be a non-empty list of positive sizes");
  if (decoder_dims.back() != input_dim)
    throw Error(cat("autoencoder: the last decoder size (", decoder_dims.back(), ") must equal input_dim (",
                    input_dim, ")"));
}

struct Autoencoder::Impl {
  AutoencoderConfig config;
  mutable AutoencoderNet net;  // forward() of torch modules is non-const
  Impl(const AutoencoderConfig& c) : config(c), net(c) {}

  at::Tensor run_encoder(const at::Tensor& x) const {
    at::Tensor z = net->encoder->forward(x);
    return config.normalize_latent ? l2_normalize(z) : z;
  }
  // Layer by layer, the linear layers through parallel_rows_linear (torch::linear while autograd
  // records, in training): a relevance map decodes millions of pixels on one thread pool.
  at::Tensor run_decoder(const at::Tensor& z) const {
    const torch::nn::LinearImpl& last = output_layer();
    const at::Tensor r = parallel_rows_linear(run_hidden(z), last.weight, last.bias);
    return config.normalize_output ? l2_normalize(r) : r;
  }
  // Every decoder layer but the last, which is a Linear (AutoencoderNetImpl).
  at::Tensor run_hidden(const at::Tensor& z) const {
    at::Tensor r = z;
    const size_t before_last = net->decoder->size() - 1;
    size_t i = 0;
    for (auto& layer : *net->decoder) {
      if (i++ == before_last) break;
      if (const auto* linear = layer.ptr()->as<torch::nn::Linear>()) r = parallel_rows_linear(r, linear->weight, linear->bias);
      else r = layer.forward(r);
    }
    return r;
  }
  const torch::nn::LinearImpl& output_layer() const {
    return *net->decoder->ptr(net->decoder->size() - 1)->as<torch::nn::Linear>();
  }
  c10::Device device() const { return net->parameters().front().device(); }

  // The input as a float tensor on the model's device, after a shape check.
  at::Tensor prepare(const at::Tensor& x, int64_t dim, const char* what) const {
    if (!x.defined() || x.dim() != 2 || x.size(1) != dim)
      throw Error(cat("autoencoder: ", what, " expects a B x ", dim, " tensor, got ",
                      x.defined() ? sizes_string(x.sizes()) : std::string("an undefined tensor")));
    return x.to(device(), at::kFloat);
  }
};

Autoencoder::Autoencoder(const AutoencoderConfig& config, uint64_t seed) {
  config.validate();
  impl_ = std::make_unique<Impl>(config);
  at::Generator gen = at::detail::createCPUGenerator(seed);
  init_linear_layers(impl_->net, gen);
  impl_->net->eval();
}

Autoencoder::~Autoencoder() = default;
Autoencoder::Autoencoder(Autoencoder&&) noexcept = default;
Autoencoder& Autoencoder::operator=(Autoencoder&&) noexcept = default;

const AutoencoderConfig& Autoencoder::config() const { return impl_->config; }

void Autoencoder::to(const c10::Device& device) { impl_->net->to(device); }
c10::Device Autoencoder::device() const { return impl_->device(); }

at::Tensor Autoencoder::encode(const at::Tensor& features) const {
  at::Tensor x = impl_->prepare(features, impl_->config.input_dim, "encode");
  torch::NoGradGuard no_grad;
  if (x.size(0) == 0) return at::empty({0, impl_->config.latent_dim()}, x.options());
  return impl_->run_encoder(x);
}

at::Tensor Autoencoder::decode(const at::Tensor& latents) const {
  at::Tensor z = impl_->prepare(latents, impl_->config.latent_dim(), "decode");
  torch::NoGradGuard no_grad;
  if (z.size(0) == 0) return at::empty({0, impl_->config.input_dim}, z.options());
  const auto blas = blas_threads_for_split(z);  // models/parallel_linear.h
  return impl_->run_decoder(z);
}

at::Tensor Autoencoder::decode_hidden(const at::Tensor& latents) const {
  at::Tensor z = impl_->prepare(latents, impl_->config.latent_dim(), "decode");
  torch::NoGradGuard no_grad;
  const auto blas = blas_threads_for_split(z);
  return impl_->run_hidden(z);
}

const at::Tensor& Autoencoder::output_weight() const { return impl_->output_layer().weight; }
const at::Tensor& Autoencoder::output_bias() const { return impl_->output_layer().bias; }

at::Tensor reconstruction_loss(const at::Tensor& f, const at::Tensor& r, double lambda_cos) {
  if (f.dim() != 2 || !f.sizes().equals(r.sizes()))
    throw Error("reconstruction_loss: f and r must be B x D tensors of one shape, got " +
                sizes_string(f.sizes()) + " and " + sizes_string(r.sizes()));
  const at::Tensor squared = (f - r).pow(2).sum(1);
  // cos = <f, r> / (max(|f|, eps) max(|r|, eps)), eps = 1e-8 as torch.nn.functional.cosine_similarity.
  const at::Tensor cos =
      (f * r).sum(1) / (f.norm(2, {1}).clamp_min(1e-8) * r.norm(2, {1}).clamp_min(1e-8));
  return squared + lambda_cos * (1 - cos);
}

AutoencoderReport Autoencoder::train(const at::Tensor& sam_features, const AutoencoderTrainOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  Impl& m = *impl_;
  if (o.epochs < 0) throw Error("autoencoder: epochs must be >= 0");
  if (o.batch_size < 2) throw Error("autoencoder: batch size must be >= 2 (BatchNorm needs 2 samples)");
  if (!(o.lr > 0)) throw Error("autoencoder: the learning rate must be positive");
  if (!(o.lambda_cos >= 0)) throw Error("autoencoder: lambda_cos must be >= 0");
  if (!(o.holdout_fraction >= 0 && o.holdout_fraction < 1))
    throw Error("autoencoder: the held-out fraction must lie in [0, 1)");
  const at::Tensor all = m.prepare(sam_features, m.config.input_dim, "train");
  if (!at::isfinite(all).all().item<bool>())
    throw Error("autoencoder: the training features contain NaN or infinite values");

  // Held-out split and mini-batch order come from one seeded generator: a seed fixes the run.
  at::Generator gen = at::detail::createCPUGenerator(o.seed);
  const int64_t n = all.size(0);
  const int64_t n_holdout = static_cast<int64_t>(std::floor(o.holdout_fraction * static_cast<double>(n)));
  const int64_t n_train = n - n_holdout;
  if (n_train < 2) throw Error(cat("autoencoder: need at least 2 training features, got ", n_train));
  const auto long_cpu = at::TensorOptions().dtype(at::kLong);
  const at::Tensor order = at::randperm(n, gen, long_cpu).to(all.device());
  const at::Tensor train_set = all.index_select(0, order.slice(0, 0, n_train));
  const at::Tensor holdout_set = all.index_select(0, order.slice(0, n_train, n));

  // Batch boundaries; a trailing batch of one sample joins the previous one (BatchNorm in training
  // mode needs at least two samples per batch).
  std::vector<int64_t> starts;
  for (int64_t s = 0; s < n_train; s += o.batch_size) starts.push_back(s);
  if (starts.size() > 1 && n_train - starts.back() == 1) starts.pop_back();
  starts.push_back(n_train);

  torch::optim::Adam adam(m.net->parameters(), torch::optim::AdamOptions(o.lr));
  AutoencoderReport report;
  report.train_samples = n_train;
  report.holdout_samples = n_holdout;
  report.train_loss = std::nan("");
  m.net->train();
  for (int epoch = 1; epoch <= o.epochs; ++epoch) {
    const at::Tensor perm = at::randperm(n_train, gen, long_cpu).to(all.device());
    double loss_sum = 0;
    for (size_t b = 0; b + 1 < starts.size(); ++b) {
      const at::Tensor f = train_set.index_select(0, perm.slice(0, starts[b], starts[b + 1]));
      const at::Tensor r = m.run_decoder(m.run_encoder(f));
      const at::Tensor per_sample = reconstruction_loss(f, r, o.lambda_cos);
      const at::Tensor loss = per_sample.mean();
      adam.zero_grad();
      loss.backward();
      adam.step();
      loss_sum += per_sample.sum().item<double>();
      if (o.on_batch) o.on_batch(starts.size() - 1);
    }
    report.train_loss = loss_sum / static_cast<double>(n_train);
    if (!std::isfinite(report.train_loss))
      throw Error(cat("autoencoder: the training loss diverged (", report.train_loss, ") in epoch ", epoch,
                      "; try a smaller learning rate"));
    if (o.on_epoch) o.on_epoch(epoch, report.train_loss);
  }
  m.net->eval();

  report.holdout_cosine = std::nan("");
  if (n_holdout > 0) {
    const at::Tensor r = decode(encode(holdout_set));
    const at::Tensor cos = (holdout_set * r).sum(1) /
                           (holdout_set.norm(2, {1}).clamp_min(1e-8) * r.norm(2, {1}).clamp_min(1e-8));
    report.holdout_cosine = cos.mean().item<double>();
  }
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return report;
}

void Autoencoder::save(const std::string& path) const {
  std::vector<SafetensorsEntry> entries;
  auto add = [&](const std::string& name, const at::Tensor& t) {
    SafetensorsEntry e;
    e.name = name;
    e.data = t.detach().to(at::kCPU).contiguous();
    e.dtype = e.data.scalar_type();
    e.shape.assign(e.data.sizes().begin(), e.data.sizes().end());
    entries.push_back(std::move(e));
  };
  for (const auto& p : impl_->net->named_parameters(/*recurse=*/true)) add(p.key(), p.value());
  for (const auto& b : impl_->net->named_buffers(/*recurse=*/true)) add(b.key(), b.value());
  write_safetensors(path, entries, {{kMetadataKey, config_json(impl_->config).dump()}});
}

Autoencoder Autoencoder::load(const std::string& path) {
  const WeightFile file = read_safetensors(path);
  const auto meta = file.metadata.find(kMetadataKey);
  if (meta == file.metadata.end())
    fail(path, std::string("no '") + kMetadataKey + "' metadata: not an autoencoder written by citylangsplat");
  Autoencoder ae(config_from_json(path, meta->second), 0);

  std::set<std::string> expected;
  auto fill = [&](const std::string& name, at::Tensor& target) {
    expected.insert(name);
    if (!file.contains(name)) {
      // BatchNorm's step counter is not used in eval mode; files converted from elsewhere may lack it.
      if (name.size() > 20 && name.compare(name.size() - 20, 20, ".num_batches_tracked") == 0) return;
      fail(path, "missing tensor '" + name + "'");
    }
    const TensorInfo& info = file.info(name);
    if (!target.sizes().equals(info.shape))
      fail(path, "tensor '" + name + "' has shape " + shape_string(info.shape) + ", expected " +
                     sizes_string(target.sizes()));
    at::Tensor value;
    try {
      value = file.get(name, target.scalar_type());
    } catch (const Error& e) {
      fail(path, "tensor '" + name + "': " + e.what());
    }
    if (target.is_floating_point() && !at::isfinite(value).all().item<bool>())
      fail(path, "tensor '" + name + "' contains NaN or infinite values");
    torch::NoGradGuard no_grad;
    target.copy_(value);
  };
  for (auto& p : ae.impl_->net->named_parameters(true)) fill(p.key(), p.value());
  for (auto& b : ae.impl_->net->named_buffers(true)) fill(b.key(), b.value());
  for (const std::string& name : file.names())
    if (!expected.count(name)) fail(path, "unexpected tensor '" + name + "' for this autoencoder layout");
  return ae;
}

}  // namespace cls
