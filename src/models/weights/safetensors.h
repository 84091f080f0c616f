#pragma once
// safetensors (huggingface/safetensors format): u64 little-endian header size N, N bytes of JSON
// {"name": {"dtype": "F32", "shape": [...], "data_offsets": [begin, end]}, "__metadata__": {...}},
// then the byte buffer the offsets index. The file is memory-mapped; tensors whose data is aligned
// for their element type are zero-copy views of the mapping.
#include <ATen/core/Tensor.h>

#include <map>
#include <string>
#include <vector>

#include "models/weights/weight_file.h"

namespace cls {

// Validates the whole header before returning (offsets inside the buffer, no overlaps or holes,
// byte sizes matching dtype x shape); every problem is a cls::Error naming the file and tensor.
WeightFile read_safetensors(const std::string& path);

// safetensors dtype name <-> torch dtype ("F32" <-> kFloat, "BF16" <-> kBFloat16, ...).
at::ScalarType safetensors_dtype(const std::string& name);  // throws cls::Error for unknown names
std::string safetensors_dtype_name(at::ScalarType t);

struct SafetensorsEntry {
  std::string name;
  at::ScalarType dtype = at::kFloat;
  std::vector<int64_t> shape;
  at::Tensor data;  // undefined: the bytes are left as a hole (a sparse, all-zero tensor)
};

// Writes entries in the given order, atomically. Entries without data make a sparse file: the
// header is written and the file extended with ftruncate, so full-size layouts (ViT-H, 2.5 GB)
// cost neither disk nor time.
void write_safetensors(const std::string& path, const std::vector<SafetensorsEntry>& entries,
                       const std::map<std::string, std::string>& metadata = {});

}  // namespace cls
