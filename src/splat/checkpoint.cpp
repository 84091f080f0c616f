#include "splat/checkpoint.h"

#include <torch/torch.h>

#include <filesystem>

#include "core/error.h"
#include "models/weights/safetensors.h"

namespace cls {
namespace {
constexpr const char* kInfoKey = "checkpoint";
}

void write_checkpoint(const std::string& path, const Checkpoint& checkpoint) {
  std::vector<SafetensorsEntry> entries;
  entries.reserve(checkpoint.tensors.size());
  for (const auto& [name, tensor] : checkpoint.tensors) {
    if (!tensor.defined()) throw Error(path + ": checkpoint tensor '" + name + "' is undefined");
    SafetensorsEntry e;
    e.name = name;
    e.data = tensor.detach().to(torch::kCPU).contiguous();
    e.dtype = e.data.scalar_type();
    e.shape = e.data.sizes().vec();
    entries.push_back(std::move(e));
  }
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  if (!parent.empty()) std::filesystem::create_directories(parent);
  write_safetensors(path, entries, {{kInfoKey, checkpoint.info.dump()}});
}

Checkpoint read_checkpoint(const std::string& path) {
  if (!std::filesystem::exists(path)) fail(path, "checkpoint not found");
  WeightFile file = read_safetensors(path);  // validates header, offsets and sizes
  auto it = file.metadata.find(kInfoKey);
  if (it == file.metadata.end()) fail(path, "not a training checkpoint (no '" + std::string(kInfoKey) + "' metadata)");
  Checkpoint c;
  try {
    c.info = nlohmann::json::parse(it->second);
  } catch (const nlohmann::json::exception& e) {
    fail(path, std::string("checkpoint metadata is not valid JSON: ") + e.what());
  }
  // Own the data: the file is memory-mapped and will be replaced by the next checkpoint.
  for (const std::string& name : file.names()) c.tensors[name] = file.get(name).clone();
  return c;
}

}  // namespace cls
