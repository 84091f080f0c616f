#include "language/language_model.h"

#include <ATen/ATen.h>

#include <filesystem>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/log.h"
#include "core/run_layout.h"
#include "language/provenance.h"
#include "models/weights/safetensors.h"
#include "splat/ply_gaussians.h"

namespace cls {
namespace fs = std::filesystem;

namespace {

const char* const kLevelNames[3] = {"level1", "level2", "level3"};


}  // namespace

const Autoencoder& LanguageModel::dense_autoencoder(const std::string& command) const {
  if (!autoencoder)
    throw UsageError(command + ": needs the dense field's autoencoder, but the model's language field is sparse "
                     "(model.json \"field\")");
  return *autoencoder;
}

int64_t LanguageModel::feature_dim() const {
  return is_sparse() ? sparse[0].codebook.size(1) : dense_autoencoder("language model").config().input_dim;
}

namespace {

std::string sparse_name(int level, const char* part) { return std::string(kLevelNames[level]) + "." + part; }

void save_sparse(const LanguageModelFiles& files, const LanguageModel& model) {
  const std::string path = files.sparse().string();
  const int64_t n = model.gaussians.size();
  std::vector<SafetensorsEntry> entries;
  for (int l = 0; l < 3; ++l) {
    const SparseLevel& s = model.sparse[l];
    s.validate(path + " (" + kLevelNames[l] + ")", n, model.sparse[0].codebook.size(1));
    for (const auto& [part, t] : {std::pair{"indices", s.indices}, std::pair{"weights", s.weights},
                                  std::pair{"codebook", s.codebook}}) {
      const at::Tensor data = t.detach().cpu().contiguous();
      entries.push_back({sparse_name(l, part), data.scalar_type(), data.sizes().vec(), data});
    }
  }
  write_safetensors(path, entries, {{"format", "citylangsplat-sparse-field"}});
}

void load_sparse(const LanguageModelFiles& files, LanguageModel& model) {
  const std::string path = files.sparse().string();
  if (!fs::exists(path)) fail(path, "missing (model.json says the field is sparse)");
  const WeightFile file = read_safetensors(path);
  for (int l = 0; l < 3; ++l) {
    SparseLevel& s = model.sparse[l];
    for (const auto& [part, t, dtype] : {std::tuple{"indices", &s.indices, at::kInt}, std::tuple{"weights", &s.weights, at::kFloat},
                                         std::tuple{"codebook", &s.codebook, at::kFloat}}) {
      if (!file.contains(sparse_name(l, part))) fail(path, "no tensor '" + sparse_name(l, part) + "'");
      if (file.info(sparse_name(l, part)).dtype != dtype)
        fail(path, "tensor '" + sparse_name(l, part) + "' must be " + safetensors_dtype_name(dtype));
      *t = file.get(sparse_name(l, part), dtype).clone();
    }
    s.validate(path + " (" + kLevelNames[l] + ")", model.gaussians.size(), model.sparse[0].codebook.size(1));
  }
}

void load_dense(const LanguageModelFiles& files, LanguageModel& model) {
  const std::string ae_path = files.autoencoder().string();
  if (!fs::exists(ae_path)) fail(ae_path, "missing");
  model.autoencoder = Autoencoder::load(ae_path);

  const std::string latents_path = files.latents().string();
  if (!fs::exists(latents_path)) fail(latents_path, "missing");
  const WeightFile file = read_safetensors(latents_path);
  const int64_t n = model.gaussians.size();
  const int latent = model.autoencoder->config().latent_dim();
  for (int l = 0; l < 3; ++l) {
    if (!file.contains(kLevelNames[l])) fail(latents_path, std::string("no tensor '") + kLevelNames[l] + "'");
    const TensorInfo& ti = file.info(kLevelNames[l]);
    if (ti.shape != std::vector<int64_t>{n, int64_t(latent)})
      fail(latents_path, std::string("tensor '") + kLevelNames[l] + "' has shape " + shape_string(ti.shape) +
                             ", expected [" + std::to_string(n) + ", " + std::to_string(latent) +
                             "] (Gaussians of point_cloud.ply x the autoencoder's latent)");
    // A copy: the file's mapping is not kept alive by the model.
    model.latents[l] = file.get(kLevelNames[l], at::kFloat).clone();
  }
}

}  // namespace

void save_language_model(const std::string& dir, const LanguageModel& model) {
  const int64_t n = model.gaussians.size();
  const LanguageModelFiles files{dir};
  const bool sparse = model.is_sparse();
  const int latent = sparse ? 0 : model.dense_autoencoder("save").config().latent_dim();
  const std::string latents_path = files.latents().string();
  std::vector<SafetensorsEntry> entries;
  for (int l = 0; l < 3 && !sparse; ++l) {
    const at::Tensor& t = model.latents[l];
    if (!t.defined() || t.dim() != 2 || t.size(0) != n || t.size(1) != latent)
      fail(latents_path, std::string("latents of ") + kLevelNames[l] + " must be " + std::to_string(n) + " x " +
                             std::to_string(latent) + " (Gaussians x autoencoder latent)");
    const at::Tensor data = t.detach().to(at::kCPU, at::kFloat).contiguous();
    entries.push_back({kLevelNames[l], at::kFloat, {n, int64_t(latent)}, data});
  }
  fs::create_directories(dir);
  // Geometry first and model.json last: a model.json marks a complete directory.
  GaussianModel geometry = model.gaussians;
  geometry.features = at::Tensor();  // the latents live in latents.safetensors
  write_gaussians_ply(files.geometry().string(), geometry);
  if (sparse) {
    save_sparse(files, model);
  } else {
    write_safetensors(latents_path, entries, {{"format", "citylangsplat-latents"}});
    model.autoencoder->save(files.autoencoder().string());
  }
  if (!model.objects.objects.empty()) write_city_objects(files.city_objects().string(), model.objects);
  nlohmann::json info = model.info.is_object() ? model.info : nlohmann::json::object();
  info["levels"] = {1, 2, 3};
  info["gaussians"] = n;
  info["field"] = model.field();
  if (sparse) {
    info["codebook_size"] = model.sparse[0].codebook.size(0);
    info["top_k"] = model.sparse[0].weights.size(1);
  } else {
    info["latent_dim"] = latent;
  }
  write_text_atomic(files.model_json(), info.dump(2) + "\n");
}

LanguageModel load_language_model(const std::string& dir) {
  const LanguageModelFiles files{dir};
  const std::string json_path = files.model_json().string();
  if (!fs::exists(json_path)) fail(json_path, "missing (not a language model directory, or an unfinished one)");
  nlohmann::json info;
  try {
    info = nlohmann::json::parse(read_text_file(json_path));
  } catch (const nlohmann::json::exception& e) {
    fail(json_path, std::string("not valid JSON: ") + e.what());
  }
  if (!info.is_object()) fail(json_path, "not a JSON object");

  const std::string ply_path = files.geometry().string();
  if (!fs::exists(ply_path)) fail(ply_path, "missing");
  GaussianModel gaussians = read_gaussians_ply(ply_path);
  gaussians.features = at::Tensor();
  const std::string field = info.value("field", "dense");
  if (field != "dense" && field != "sparse") fail(json_path, "\"field\" must be \"dense\" or \"sparse\", got \"" + field + "\"");
  LanguageModel model{std::move(gaussians), {}, std::nullopt, std::move(info), {}, {}};
  if (field == "sparse")
    load_sparse(files, model);
  else
    load_dense(files, model);
  const int64_t n = model.gaussians.size();
  if (model.info.contains("gaussians") && model.info["gaussians"] != n)
    fail(json_path, "records " + model.info["gaussians"].dump() + " Gaussians but point_cloud.ply has " +
                        std::to_string(n));
  const std::string objects_path = files.city_objects().string();
  if (fs::exists(objects_path)) {
    model.objects = read_city_objects(objects_path);
    const GaussianExtra* object = model.gaussians.extra(kObjectProperty);
    if (!object || object->values.scalar_type() != at::kInt)
      fail(ply_path, std::string("has no int property '") + kObjectProperty + "' although " + objects_path + " exists");
    const int64_t objects = static_cast<int64_t>(model.objects.objects.size());
    if (n > 0 && (object->values.min().item<int32_t>() < -1 || object->values.max().item<int32_t>() >= objects))
      fail(ply_path, cat("property '", kObjectProperty, "' indexes beyond the ", objects, " objects of ", objects_path));
  }
  return model;
}

fs::path language_model_dir(const fs::path& out, const std::string& method, const std::string& command) {
  if (fs::exists(LanguageModelFiles{out}.model_json())) return out;
  const fs::path in_run = RunLayout(out).language(method);
  if (fs::exists(LanguageModelFiles{in_run}.model_json())) return in_run;
  throw UsageError(command + ": " + out.string() + " is neither a language model (model.json) nor a `run` output with " +
                   LanguageModelFiles{RunLayout().language(method)}.model_json().string());
}

}  // namespace cls
