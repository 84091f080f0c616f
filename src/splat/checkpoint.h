#pragma once
// Training checkpoints: named float/int tensors plus a JSON document (iteration, options, RNG state,
// Adam steps ...) in one safetensors file (the JSON under __metadata__["checkpoint"]), written
// atomically so a kill at any moment leaves either the previous or the new checkpoint.
#include <ATen/core/Tensor.h>
#include <nlohmann/json.hpp>

#include <map>
#include <string>

namespace cls {

struct Checkpoint {
  std::map<std::string, at::Tensor> tensors;  // CPU, contiguous
  nlohmann::json info;
};

void write_checkpoint(const std::string& path, const Checkpoint& checkpoint);
// cls::Error naming the file if it is missing, truncated or not a checkpoint.
Checkpoint read_checkpoint(const std::string& path);

}  // namespace cls
