#pragma once
// Shared set-up of the SAM model tests: the tiny reference model of tests/fixtures/sam/ and its
// fixture arrays.
#include <torch/torch.h>

#include <nlohmann/json.hpp>
#include <string>

#include "core/atomic_file.h"
#include "core/npy.h"
#include "models/sam/sam_model.h"
#include "models/weights/npy_tensor.h"
#include "models/weights/safetensors.h"
#include "test_device.h"

namespace cls::sam::testing {

inline std::string sam_fixture(const std::string& name) { return std::string(CLS_TEST_FIXTURES) + "/sam/" + name; }

inline torch::Tensor load_npy_tensor(const std::string& name) { return to_tensor(read_npy(sam_fixture(name))); }

// config.json as plain JSON (not through the code under test): the sizes the tests expect.
inline const nlohmann::json& sam_config_json() {
  static const nlohmann::json j = nlohmann::json::parse(read_text_file(sam_fixture("config.json")));
  return j;
}
// The side of the model's square input (ResizeLongestSide's target length).
inline int img_size() { return sam_config_json().at("image_encoder").at("img_size").get<int>(); }
// Masks per prompt with multimask_output (the s / m / l outputs the AMG uses).
inline int64_t num_multimask_outputs() { return sam_config_json().at("num_multimask_outputs").get<int64_t>(); }

// The tiny model of config.json with weights.safetensors loaded, on cls::testing::test_device().
inline Sam load_tiny_sam() {
  Sam model(sam_config_from_json_file(sam_fixture("config.json")));
  load_sam_weights(*model, read_safetensors(sam_fixture("weights.safetensors")));
  model->eval();
  model->to(cls::testing::test_device());
  return model;
}

// max |a - b| and the largest excess over atol + rtol |b| (<= 0 means within tolerance).
struct Diff {
  double max_abs = 0, worst_excess = 0;
};
inline Diff compare(const torch::Tensor& a, const torch::Tensor& b, double atol, double rtol) {
  const auto d = (a.to(torch::kCPU, torch::kDouble) - b.to(torch::kCPU, torch::kDouble)).abs();
  Diff r;
  if (d.numel() == 0) return r;
  r.max_abs = d.max().item<double>();
  r.worst_excess = (d - (atol + rtol * b.to(torch::kDouble).abs())).max().item<double>();
  return r;
}

}  // namespace cls::sam::testing
