#pragma once
// A weight container read from disk: tensor name -> dtype, shape and a loader that materialises
// the tensor only when asked (safetensors are memory-mapped, so an unused tensor costs nothing).
// Every reader (safetensors, torch.save zip, TorchScript archive) produces one; the key-layout
// mapping (layouts.h) produces a renamed/derived one on top.
#include <ATen/core/Tensor.h>

#include <functional>
#include <map>
#include <string>
#include <vector>

namespace cls {

struct TensorInfo {
  at::ScalarType dtype = at::kFloat;
  std::vector<int64_t> shape;
};

std::string shape_string(const std::vector<int64_t>& shape);  // "[768, 3, 16, 16]"

class WeightFile {
 public:
  using Loader = std::function<at::Tensor()>;

  WeightFile() = default;
  explicit WeightFile(std::string source) : source_(std::move(source)) {}

  // The file (or description) errors name.
  const std::string& source() const { return source_; }

  // Registers a tensor; a duplicate name is a cls::Error.
  void add(const std::string& name, TensorInfo info, Loader load);
  void add(const std::string& name, const at::Tensor& tensor);  // an already materialised tensor
  void remove(const std::string& name);

  bool contains(const std::string& name) const { return entries_.count(name) != 0; }
  size_t size() const { return entries_.size(); }
  std::vector<std::string> names() const;  // sorted
  // cls::Error "<file>: no tensor '<name>'" when absent.
  const TensorInfo& info(const std::string& name) const;
  const Loader& loader(const std::string& name) const;

  // The tensor in its stored dtype (CPU). The loader's result is checked against info().
  at::Tensor get(const std::string& name) const;
  // The tensor converted to `dtype`.
  at::Tensor get(const std::string& name, at::ScalarType dtype) const;

  std::map<std::string, std::string> metadata;  // safetensors __metadata__ and similar

 private:
  struct Entry {
    TensorInfo info;
    Loader load;
  };
  std::string source_;
  std::map<std::string, Entry> entries_;
};

// Reads any supported container, chosen by content: safetensors, zip-format torch.save / TorchScript
// archives. Legacy (pre-zip) pickles and unknown formats give a cls::Error saying what to do.
WeightFile load_weight_file(const std::string& path);

}  // namespace cls
