#include "models/weights/npy_tensor.h"

#include <ATen/ATen.h>

#include <cstring>

#include "core/error.h"

namespace cls {
namespace {

at::ScalarType scalar_type_of(NpyType t) {
  switch (t) {
    case NpyType::F16: return at::kHalf;
    case NpyType::F32: return at::kFloat;
    case NpyType::F64: return at::kDouble;
    case NpyType::I32: return at::kInt;
    case NpyType::I64: return at::kLong;
    case NpyType::U8: return at::kByte;
    case NpyType::Bool: return at::kBool;
  }
  throw Error("unreachable npy type");
}

}  // namespace

at::Tensor to_tensor(const NpyArray& a) {
  const size_t bytes = static_cast<size_t>(a.numel()) * a.item_size();
  if (a.data.size() != bytes) throw Error("to_tensor: array data size does not match its shape");
  at::Tensor t = at::empty(a.shape, at::TensorOptions().dtype(scalar_type_of(a.type())));
  if (bytes) std::memcpy(t.data_ptr(), a.data.data(), bytes);
  return t;
}

NpyArray to_npy(const at::Tensor& tensor) {
  const at::Tensor t = tensor.detach().to(at::kCPU).contiguous();
  NpyArray a;
  switch (t.scalar_type()) {
    case at::kHalf: a.dtype = "<f2"; break;
    case at::kFloat: a.dtype = "<f4"; break;
    case at::kDouble: a.dtype = "<f8"; break;
    case at::kInt: a.dtype = "<i4"; break;
    case at::kLong: a.dtype = "<i8"; break;
    case at::kByte: a.dtype = "|u1"; break;
    case at::kBool: a.dtype = "|b1"; break;
    default:
      throw Error(std::string("to_npy: no .npy type for tensor dtype ") + c10::toString(t.scalar_type()));
  }
  a.shape.assign(t.sizes().begin(), t.sizes().end());
  a.data.resize(static_cast<size_t>(t.numel()) * t.element_size());
  if (!a.data.empty()) std::memcpy(a.data.data(), t.data_ptr(), a.data.size());
  return a;
}

}  // namespace cls
