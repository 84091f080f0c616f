#include "language/autoencoder_stage.h"

#include <ATen/ATen.h>
#include <ATen/CPUGeneratorImpl.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/log.h"
#include "core/npy.h"
#include "core/progress.h"
#include "models/weights/npy_tensor.h"
#include "models/weights/weight_file.h"

namespace cls {
namespace fs = std::filesystem;

namespace {

bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

}  // namespace

std::vector<fs::path> find_sam_feature_files(const fs::path& dir) {
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) fail(dir.string(), "not a directory (expected the features stage's output)");
  std::vector<fs::path> files;
  for (auto it = fs::recursive_directory_iterator(dir, ec); !ec && it != fs::recursive_directory_iterator();
       it.increment(ec)) {
    if (!it->is_regular_file()) continue;
    const std::string name = it->path().filename().string();
    if (ends_with(name, "_f.npy") && !ends_with(name, "_gml_f.npy")) files.push_back(it->path());
  }
  if (ec) fail(dir.string(), "cannot list the directory: " + ec.message());
  std::sort(files.begin(), files.end());
  return files;
}

std::vector<fs::path> find_sam_feature_files(const std::vector<fs::path>& dirs) {
  std::map<fs::path, fs::path> by_name;  // path within its directory -> file
  for (const fs::path& dir : dirs) {
    const std::vector<fs::path> found = find_sam_feature_files(dir);
    if (found.empty())
      fail(dir.string(),
           "no SAM feature files (*_f.npy; *_gml_f.npy are not used for training): run the features stage first");
    for (const fs::path& file : found) by_name.emplace(file.lexically_relative(dir), file);
  }
  std::vector<fs::path> files;
  for (const auto& [name, file] : by_name) files.push_back(file);
  return files;
}

at::Tensor read_sam_features(const std::vector<fs::path>& files, int input_dim, int64_t max_samples, uint64_t seed,
                             int64_t* rows_read) {
  std::vector<at::Tensor> parts;
  at::Tensor reservoir;  // max_samples > 0: Algorithm R over the rows of every file in order
  at::Generator gen = at::detail::createCPUGenerator(seed);
  int64_t seen = 0;
  for (const fs::path& file : files) {
    const NpyArray a = read_npy(file);  // names the file on a malformed header or short data
    if (a.shape.size() != 2 || a.shape[1] != input_dim)
      fail(file.string(), cat("expected an N x ", input_dim, " array of CLIP features, got shape ",
                              shape_string(a.shape)));
    const NpyType t = a.type();
    if (t != NpyType::F16 && t != NpyType::F32 && t != NpyType::F64)
      fail(file.string(), "expected floating-point CLIP features, got dtype " + a.dtype);
    at::Tensor f = to_tensor(a).to(at::kFloat);
    if (!at::isfinite(f).all().item<bool>()) {
      const int64_t row = at::nonzero(~at::isfinite(f).all(1))[0][0].item<int64_t>();
      fail(file.string(), cat("row ", row, " of the CLIP features contains NaN or infinite values"));
    }
    const int64_t n = f.size(0);
    if (max_samples <= 0) {
      if (n > 0) parts.push_back(f);
    } else {
      if (!reservoir.defined()) reservoir = at::empty({max_samples, input_dim}, at::kFloat);
      const int64_t direct = std::clamp<int64_t>(max_samples - seen, 0, n);  // while the reservoir fills
      if (direct > 0) reservoir.slice(0, seen, seen + direct).copy_(f.slice(0, 0, direct));
      if (n > direct) {
        // Row r (global index seen + r) replaces slot j, uniform in [0, seen + r], when j < max_samples.
        const at::Tensor global = at::arange(seen + direct, seen + n, at::kDouble);
        const at::Tensor j = (at::rand({n - direct}, gen, at::kDouble) * (global + 1)).floor().to(at::kLong);
        const at::Tensor hit = j.lt(max_samples).nonzero().select(1, 0).contiguous();
        const at::Tensor slots = j.index_select(0, hit);
        const auto slot = slots.accessor<int64_t, 1>();
        const auto row = hit.accessor<int64_t, 1>();
        for (int64_t k = 0; k < hit.size(0); ++k) reservoir[slot[k]].copy_(f[direct + row[k]]);  // later rows win
      }
    }
    seen += n;
  }
  if (rows_read) *rows_read = seen;
  if (max_samples > 0) return seen >= max_samples ? reservoir : reservoir.slice(0, 0, seen).contiguous();
  if (parts.empty()) return at::empty({0, input_dim}, at::kFloat);
  return at::cat(parts, 0);
}

namespace {

// Layer sizes: a comma-separated list of positive integers.
Codec<std::vector<int>> dims_codec() {
  Codec<std::vector<int>> c;
  c.text = [](const std::vector<int>& v) {
    std::string s;
    for (size_t i = 0; i < v.size(); ++i) s += (i ? "," : "") + std::to_string(v[i]);
    return s;
  };
  const auto checked = [](const std::vector<int>& dims, const std::string& text) {
    if (dims.empty()) throw std::invalid_argument("must list at least one size");
    for (const int d : dims)
      if (d <= 0) throw std::invalid_argument("must be a comma-separated list of positive sizes, got '" + text + "'");
    return dims;
  };
  c.parse = [checked](const std::string& text) {
    std::vector<int> dims;
    std::stringstream in(text);
    for (std::string item; std::getline(in, item, ',');) dims.push_back(item.empty() ? 0 : default_codec<int>().parse(item));
    return checked(dims, text);
  };
  c.to_json = [](const std::vector<int>& v) { return nlohmann::json(v); };
  c.from_json = [checked](const nlohmann::json& j) { return checked(j.get<std::vector<int>>(), j.dump()); };
  return c;
}

// --features: the one directory of a command line (tiles give several in code).
Codec<std::vector<std::filesystem::path>> one_dir_codec() {
  Codec<std::vector<std::filesystem::path>> c;
  c.text = [](const std::vector<std::filesystem::path>& v) { return v.empty() ? std::string() : v.front().string(); };
  c.parse = [](const std::string& s) { return std::vector<std::filesystem::path>{s}; };
  c.to_json = [](const std::vector<std::filesystem::path>& v) {
    nlohmann::json j = nlohmann::json::array();
    for (const auto& p : v) j.push_back(p.string());
    return j;
  };
  c.from_json = [](const nlohmann::json& j) {
    std::vector<std::filesystem::path> v;
    for (const auto& p : j) v.emplace_back(p.get<std::string>());
    return v;
  };
  return c;
}

}  // namespace

const OptionList<AutoencoderStageOptions>& autoencoder_options() {
  using O = AutoencoderStageOptions;
  using R = OptionRole;
  static const OptionList<O> list = [] {
    OptionList<O> o;
    o.add("features", &O::features_dirs, "features directory (the features stage's output)", R::Location, one_dir_codec())
        .required()
        .add("out", &O::out, "the model file to write, e.g. OUT/autoencoder.safetensors", R::Location)
        .required()
        .add("epochs", [](O& x) -> int& { return x.train.epochs; }, "training epochs")
        .add("batch-size", [](O& x) -> int& { return x.train.batch_size; }, "mini-batch size (>= 2)")
        .add("lr", [](O& x) -> double& { return x.train.lr; }, "Adam learning rate")
        .add("lambda-cos", [](O& x) -> double& { return x.train.lambda_cos; }, "weight of the cosine term")
        .add("holdout", [](O& x) -> double& { return x.train.holdout_fraction; },
             "fraction of features held out for the reported cosine")
        .add("encoder-dims", [](O& x) -> std::vector<int>& { return x.config.encoder_dims; },
             "encoder layer sizes after the input; the last is the latent", R::Setting, dims_codec())
        .add("decoder-dims", [](O& x) -> std::vector<int>& { return x.config.decoder_dims; },
             "decoder layer sizes; the last must be the feature size", R::Setting, dims_codec())
        .add("seed", [](O& x) -> uint64_t& { return x.train.seed; }, "seed of initialisation, split and shuffling");
    return o;
  }();
  return list;
}

AutoencoderReport run_autoencoder_stage(const AutoencoderStageOptions& o) {
  if (o.features_dirs.empty()) throw UsageError("autoencoder: no features directory given");
  const std::string where = o.features_dirs.front().string();
  const std::vector<fs::path> files = find_sam_feature_files(o.features_dirs);
  int64_t rows_read = 0;
  const at::Tensor features = read_sam_features(files, o.config.input_dim, o.max_samples, o.train.seed, &rows_read);
  if (rows_read == 0) fail(where, "the SAM feature files hold no rows");
  log_info(cat("autoencoder: ", features.size(0), " of ", rows_read, " SAM features from ", files.size(), " files, ",
               o.config.input_dim, " -> ", o.config.latent_dim()));

  Autoencoder ae(o.config, o.train.seed);
  AutoencoderTrainOptions train = o.train;
  AutoencoderReport report;
  {
    // Counted in mini-batches: an epoch over the features of 200 photos takes minutes on a CPU.
    std::optional<Progress> progress;
    const int every = std::max(1, train.epochs / 10);
    train.on_batch = [&](size_t batches) {
      if (!progress) progress.emplace("autoencoder", static_cast<uint64_t>(train.epochs) * batches, "batches");
      progress->advance();
    };
    train.on_epoch = [&](int epoch, double loss) {
      if (o.train.on_epoch) o.train.on_epoch(epoch, loss);
      const std::string line = cat("autoencoder: epoch ", epoch, "/", train.epochs, " loss ", loss);
      if (epoch % every == 0 || epoch == train.epochs)
        log_info(line);
      else
        log_verbose(line);
      if (progress) progress->set_detail(cat("epoch ", epoch, "/", train.epochs, " loss ", loss));
    };
    report = ae.train(features, train);
    if (progress) progress->finish();
  }

  if (o.out.has_parent_path()) fs::create_directories(o.out.parent_path());
  ae.save(o.out.string());
  const auto finite_or_null = [](double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(); };
  const nlohmann::json j = {
      {"samples", features.size(0)},
      {"rows_read", rows_read},
      {"train_samples", report.train_samples},
      {"holdout_samples", report.holdout_samples},
      {"files", files.size()},
      {"train_loss", finite_or_null(report.train_loss)},
      {"holdout_cosine", finite_or_null(report.holdout_cosine)},
      {"seconds", report.seconds},
      {"epochs", train.epochs},
      {"batch_size", train.batch_size},
      {"lr", train.lr},
      {"lambda_cos", train.lambda_cos},
      {"holdout_fraction", train.holdout_fraction},
      {"seed", train.seed},
      {"config",
       {{"input_dim", o.config.input_dim},
        {"encoder_dims", o.config.encoder_dims},
        {"decoder_dims", o.config.decoder_dims},
        {"normalize_latent", o.config.normalize_latent},
        {"normalize_output", o.config.normalize_output}}}};
  write_text_atomic(o.out.string() + ".json", j.dump(2) + "\n");
  log_info(cat("autoencoder: held-out cosine ", report.holdout_cosine, " (", report.holdout_samples,
               " features), wrote ", o.out.string()));
  return report;
}

}  // namespace cls
