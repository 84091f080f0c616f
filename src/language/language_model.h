#pragma once
// A trained language field on disk (one directory, what `query` and `evaluate` open):
//   model.json                {"method": "citylangsplat" | "langsplat", "levels": [1, 2, 3],
//                              "iterations", "lambda_sam", "lambda_citygml", "features": <dir>,
//                              "provider": <spec>, "geometry_source": <ply>, "normalize_latents", ...}
//   point_cloud.ply           the frozen geometry (3DGS layout)
//   latents.safetensors       "level1", "level2", "level3": N x latent float32
//   autoencoder.safetensors   the shared autoencoder
//   city_objects.json         the city objects the PLY's city_object property indexes (provenance.h),
//                             when the label maps had object maps
#include <ATen/core/Tensor.h>
#include <nlohmann/json.hpp>

#include <array>
#include <filesystem>
#include <string>

#include "citymodel/city_objects.h"
#include "language/autoencoder.h"
#include "splat/gaussians.h"

namespace cls {

struct LanguageModel {
  GaussianModel gaussians;
  std::array<at::Tensor, 3> latents;  // level 1..3 at index 0..2, N x latent
  Autoencoder autoencoder;
  nlohmann::json info;                // model.json
  CityObjects objects;                // empty without provenance
};

void save_language_model(const std::string& dir, const LanguageModel& model);  // each file atomic
// cls::Error naming the file on a missing/inconsistent part.
LanguageModel load_language_model(const std::string& dir);

// The language model directory of OUT: OUT itself when it holds model.json, else the `run` output's
// OUT/language/<method>. cls::UsageError, prefixed with `command`, saying what was looked for otherwise.
std::filesystem::path language_model_dir(const std::filesystem::path& out, const std::string& method,
                                         const std::string& command);

}  // namespace cls
