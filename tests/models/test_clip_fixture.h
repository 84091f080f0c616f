#pragma once
// Loading the CLIP reference fixtures (tests/fixtures/clip/models/<name>/) for the model tests.
#include <ATen/ATen.h>

#include <map>
#include <string>

#include "core/npy.h"

namespace cls::clip::testing {

inline std::string fixture_dir(const std::string& model) {
  return std::string(CLS_TEST_FIXTURES) + "/clip/models/" + model;
}

// A .npy file as a CPU tensor (float32/float64/int64).
inline at::Tensor load_npy(const std::string& path) {
  const NpyArray a = read_npy(path);
  at::ScalarType t = at::kFloat;
  if (a.dtype == "<f8") t = at::kDouble;
  else if (a.dtype == "<i8") t = at::kLong;
  else if (a.dtype != "<f4") throw std::runtime_error(path + ": unexpected dtype " + a.dtype);
  return at::from_blob(const_cast<uint8_t*>(a.data.data()), a.shape, at::TensorOptions().dtype(t)).clone();
}

// The state dict of a fixture safetensors file; weights_rows.safetensors (see
// scripts/derive_clip_test_weights.py) gets its full token_embedding.weight rebuilt with zero rows.
std::map<std::string, at::Tensor> load_state(const std::string& path, int64_t vocab_size);

}  // namespace cls::clip::testing
