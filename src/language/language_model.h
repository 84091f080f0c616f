#pragma once
// A trained language field on disk (one directory, what `query` and `evaluate` open):
//   model.json                {"method": "citylangsplat" | "langsplat", "field": "dense" | "sparse",
//                              "levels": [1, 2, 3],
//                              "iterations", "lambda_sam", "lambda_citygml", "features": <dir>,
//                              "provider": <spec>, "geometry_source": <ply>, "normalize_latents", ...}
//   point_cloud.ply           the frozen geometry (3DGS layout)
//   latents.safetensors       dense: "level1", "level2", "level3": N x latent float32
//   autoencoder.safetensors   dense: the shared autoencoder
//   sparse.safetensors        sparse (sparse_field.h): "level<l>.indices" N x K int32, "level<l>.weights"
//                             N x K float32, "level<l>.codebook" L x D float32
//   city_objects.json         the city objects the PLY's city_object property indexes (provenance.h),
//                             when the label maps had object maps
#include <ATen/core/Tensor.h>
#include <nlohmann/json.hpp>

#include <array>
#include <filesystem>
#include <optional>
#include <string>

#include "citymodel/city_objects.h"
#include "language/autoencoder.h"
#include "language/sparse_field.h"
#include "splat/gaussians.h"

namespace cls {

struct LanguageModel {
  GaussianModel gaussians;
  std::array<at::Tensor, 3> latents;  // dense field: level 1..3 at index 0..2, N x latent
  std::optional<Autoencoder> autoencoder;  // dense field: the decoder of the latents
  nlohmann::json info;                // model.json
  CityObjects objects;                // empty without provenance
  std::array<SparseLevel, 3> sparse;  // sparse field: level 1..3 at index 0..2

  bool is_sparse() const { return sparse[0].defined(); }
  const char* field() const { return is_sparse() ? "sparse" : "dense"; }
  bool has_level(int level) const {  // 1..3
    return is_sparse() ? sparse[size_t(level - 1)].defined() : latents[size_t(level - 1)].defined();
  }
  // The dense field's autoencoder, for what works on latents only; cls::UsageError naming `command` for a
  // sparse field.
  const Autoencoder& dense_autoencoder(const std::string& command) const;
  // The size of the features the field answers in (the autoencoder's input, the codebook's width).
  int64_t feature_dim() const;
};

void save_language_model(const std::string& dir, const LanguageModel& model);  // each file atomic
// cls::Error naming the file on a missing/inconsistent part.
LanguageModel load_language_model(const std::string& dir);

// The language model directory of OUT: OUT itself when it holds model.json, else the `run` output's
// OUT/language/<method>. cls::UsageError, prefixed with `command`, saying what was looked for otherwise.
std::filesystem::path language_model_dir(const std::filesystem::path& out, const std::string& method,
                                         const std::string& command);

}  // namespace cls
