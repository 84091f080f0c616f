#pragma once
// Loading the CLIP reference fixtures (tests/fixtures/clip/models/<name>/) for the model tests.
#include <ATen/ATen.h>

#include <map>
#include <string>

#include "core/npy.h"
#include "models/weights/npy_tensor.h"

namespace cls::clip::testing {

inline std::string fixture_dir(const std::string& model) {
  return std::string(CLS_TEST_FIXTURES) + "/clip/models/" + model;
}

inline at::Tensor load_npy(const std::string& path) { return to_tensor(read_npy(path)); }

// The state dict of a fixture safetensors file; weights_rows.safetensors (see
// scripts/derive_clip_test_weights.py) gets its full token_embedding.weight rebuilt with zero rows.
std::map<std::string, at::Tensor> load_state(const std::string& path, int64_t vocab_size);

}  // namespace cls::clip::testing
