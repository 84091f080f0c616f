#pragma once
// Zip-format PyTorch archives read as weight containers: torch.save state dicts (PyTorch >= 1.6)
// and TorchScript archives such as OpenAI's CLIP .pt files. Only data.pkl and the data/N tensor
// records are read; TorchScript code is never compiled or run: every scripted class is rebuilt as a
// plain attribute bag and its tensor attributes become "module.path.name" entries.
#include <string>

#include "models/weights/weight_file.h"

namespace cls {

// Nested dicts and module objects are flattened with '.'; non-tensor values are skipped.
WeightFile read_torch_archive(const std::string& path);

}  // namespace cls
