#pragma once
// Bridge between the torch-free core/npy arrays and LibTorch tensors (fixtures, LangSplat files).
#include <ATen/core/Tensor.h>

#include "core/npy.h"

namespace cls {

// A CPU tensor of the array's dtype and shape holding a copy of its data.
at::Tensor to_tensor(const NpyArray& a);
// The array of a tensor (any device; made contiguous and moved to CPU). Types without a .npy
// counterpart here (bf16, int16, ...) throw cls::Error.
NpyArray to_npy(const at::Tensor& t);

}  // namespace cls
