#include "models/weights/weight_file.h"

#include <ATen/ATen.h>

#include <fstream>
#include <sstream>

#include "core/error.h"
#include "models/weights/safetensors.h"
#include "models/weights/torch_archive.h"

namespace cls {

std::string shape_string(const std::vector<int64_t>& shape) {
  std::ostringstream s;
  s << '[';
  for (size_t i = 0; i < shape.size(); ++i) s << (i ? ", " : "") << shape[i];
  s << ']';
  return s.str();
}

void WeightFile::add(const std::string& name, TensorInfo info, Loader load) {
  if (!entries_.emplace(name, Entry{std::move(info), std::move(load)}).second)
    fail(source_, "duplicate tensor '" + name + "'");
}

void WeightFile::add(const std::string& name, const at::Tensor& tensor) {
  TensorInfo info{tensor.scalar_type(), std::vector<int64_t>(tensor.sizes().begin(), tensor.sizes().end())};
  add(name, std::move(info), [tensor] { return tensor; });
}

void WeightFile::remove(const std::string& name) { entries_.erase(name); }

std::vector<std::string> WeightFile::names() const {
  std::vector<std::string> out;
  out.reserve(entries_.size());
  for (const auto& [name, entry] : entries_) out.push_back(name);
  return out;
}

const TensorInfo& WeightFile::info(const std::string& name) const {
  const auto it = entries_.find(name);
  if (it == entries_.end()) fail(source_, "no tensor '" + name + "'");
  return it->second.info;
}

const WeightFile::Loader& WeightFile::loader(const std::string& name) const {
  const auto it = entries_.find(name);
  if (it == entries_.end()) fail(source_, "no tensor '" + name + "'");
  return it->second.load;
}

at::Tensor WeightFile::get(const std::string& name) const {
  const TensorInfo& expected = info(name);
  at::Tensor t;
  try {
    t = loader(name)();
  } catch (const Error&) {
    throw;
  } catch (const std::exception& e) {
    fail(source_, "tensor '" + name + "': " + e.what());
  }
  const std::vector<int64_t> shape(t.sizes().begin(), t.sizes().end());
  if (shape != expected.shape || t.scalar_type() != expected.dtype)
    fail(source_, "tensor '" + name + "' materialised as " + c10::toString(t.scalar_type()) + " " +
                      shape_string(shape) + ", expected " + c10::toString(expected.dtype) + " " +
                      shape_string(expected.shape));
  return t;
}

at::Tensor WeightFile::get(const std::string& name, at::ScalarType dtype) const {
  at::Tensor t = get(name);
  return t.scalar_type() == dtype ? t : t.to(dtype);
}

WeightFile load_weight_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(path, "cannot open weight file");
  char head[8] = {0};
  in.read(head, sizeof head);
  const std::streamsize got = in.gcount();
  if (got >= 4 && head[0] == 'P' && head[1] == 'K' && head[2] == 3 && head[3] == 4)
    return read_torch_archive(path);
  // Legacy torch.save (before PyTorch 1.6, or _use_new_zipfile_serialization=False) starts with a
  // pickled magic number: protocol opcode 0x80, protocol 2, then LONG1 ...
  if (got >= 2 && static_cast<unsigned char>(head[0]) == 0x80 && head[1] <= 5)
    fail(path, "legacy (pre-zip) PyTorch pickle: not supported. Convert it once with a recent PyTorch: "
               "python3 -c \"import torch; torch.save(torch.load('" + path + "', map_location='cpu'), "
               "'converted.pt')\" (or save a .safetensors file)");
  return read_safetensors(path);
}

}  // namespace cls
