#pragma once
// Loading the CLIP reference fixtures (tests/fixtures/clip/models/<name>/) for the model tests.
#include <ATen/ATen.h>

#include <map>
#include <nlohmann/json.hpp>
#include <string>

#include "core/atomic_file.h"
#include "core/npy.h"
#include "models/weights/npy_tensor.h"

namespace cls::clip::testing {

inline std::string fixture_dir(const std::string& model) {
  return std::string(CLS_TEST_FIXTURES) + "/clip/models/" + model;
}

// The model's config.json as plain JSON (not through read_clip_config, the code under test).
inline nlohmann::json fixture_config(const std::string& model) {
  return nlohmann::json::parse(read_text_file(fixture_dir(model) + "/config.json"));
}

inline at::Tensor load_npy(const std::string& path) { return to_tensor(read_npy(path)); }

// The state dict of a fixture safetensors file; weights_rows.safetensors (see
// scripts/derive_clip_test_weights.py) gets its full token_embedding.weight rebuilt with zero rows.
std::map<std::string, at::Tensor> load_state(const std::string& path, int64_t vocab_size);

}  // namespace cls::clip::testing
