#pragma once
// A minimal, data-only reader of the pickle programs inside PyTorch zip archives (data.pkl).
// It understands the opcodes pickle protocols 2-5 use for checkpoints and the handful of globals
// that rebuild tensors and containers (torch._utils._rebuild_tensor_v2, collections.OrderedDict,
// torch.jit._pickle.*, ...). Any other global becomes an inert object whose state is kept as
// data; nothing is ever imported, called or compiled. (LibTorch 1.13's own unpickler turns
// Python's OrderedDict state dicts into None, hence this reader.)
#include <ATen/core/Tensor.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace cls {

struct PyValue;
using PyRef = std::shared_ptr<PyValue>;

// A tensor as the pickle describes it: a view into the storage record data/<key>.
struct PickledTensor {
  std::string storage_key;
  at::ScalarType dtype = at::kFloat;
  int64_t storage_numel = 0;
  int64_t offset = 0;
  std::vector<int64_t> sizes, strides;
};

struct PyValue {
  enum class Kind { None, Bool, Int, Float, String, Tuple, List, Dict, Global, Object, Storage, Tensor };
  Kind kind = Kind::None;
  int64_t i = 0;
  double f = 0;
  std::string s;                                // String; Global/Object: "module.name"; Storage: key
  std::vector<PyRef> items;                     // Tuple, List; Object: constructor arguments
  std::vector<std::pair<PyRef, PyRef>> dict;    // Dict; Object: its state (attributes)
  PickledTensor tensor;                         // Tensor; Storage: dtype and numel
};

// Runs the pickle program `bytes`; errors are cls::Error prefixed with `name`.
PyRef read_pickle(const std::string& bytes, const std::string& name);

}  // namespace cls
