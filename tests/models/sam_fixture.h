#pragma once
// Shared set-up of the SAM model tests: the tiny reference model of tests/fixtures/sam/ and its
// fixture arrays.
#include <torch/torch.h>

#include <string>

#include "core/npy.h"
#include "models/sam/sam_model.h"
#include "models/weights/npy_tensor.h"
#include "models/weights/safetensors.h"

namespace cls::sam::testing {

inline std::string sam_fixture(const std::string& name) { return std::string(CLS_TEST_FIXTURES) + "/sam/" + name; }

inline torch::Tensor load_npy_tensor(const std::string& name) { return to_tensor(read_npy(sam_fixture(name))); }

// The tiny model of config.json with weights.safetensors loaded.
inline Sam load_tiny_sam() {
  Sam model(sam_config_from_json_file(sam_fixture("config.json")));
  load_sam_weights(*model, read_safetensors(sam_fixture("weights.safetensors")));
  model->eval();
  return model;
}

// max |a - b| and the largest excess over atol + rtol |b| (<= 0 means within tolerance).
struct Diff {
  double max_abs = 0, worst_excess = 0;
};
inline Diff compare(const torch::Tensor& a, const torch::Tensor& b, double atol, double rtol) {
  const auto d = (a.to(torch::kDouble) - b.to(torch::kDouble)).abs();
  Diff r;
  if (d.numel() == 0) return r;
  r.max_abs = d.max().item<double>();
  r.worst_excess = (d - (atol + rtol * b.to(torch::kDouble).abs())).max().item<double>();
  return r;
}

}  // namespace cls::sam::testing
