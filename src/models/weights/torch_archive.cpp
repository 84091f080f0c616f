#include "models/weights/torch_archive.h"

#include <ATen/ATen.h>
#include <caffe2/serialize/inline_container.h>

#include <cstring>

#include "core/error.h"
#include "models/weights/pickle_reader.h"

namespace cls {
namespace {

using Reader = caffe2::serialize::PyTorchStreamReader;

std::string first_line(const std::string& what) {
  const size_t nl = what.find('\n');
  return nl == std::string::npos ? what : what.substr(0, nl);  // drop c10 backtraces
}

// The tensor a pickled view describes, read from its storage record; bounds are checked first.
at::Tensor materialise(const std::shared_ptr<Reader>& reader, const PickledTensor& t, const std::string& path,
                       const std::string& name) {
  const std::string record = "data/" + t.storage_key;
  const size_t item = c10::elementSize(t.dtype);
  at::Tensor storage = at::empty({t.storage_numel}, at::TensorOptions().dtype(t.dtype));
  try {
    if (!reader->hasRecord(record)) fail(path, "tensor '" + name + "': storage record " + record + " is missing");
    auto [data, size] = reader->getRecord(record);
    if (size < static_cast<size_t>(t.storage_numel) * item)
      fail(path, "tensor '" + name + "': storage record " + record + " has " + std::to_string(size) +
                     " bytes, needs " + std::to_string(t.storage_numel * item));
    if (t.storage_numel) std::memcpy(storage.data_ptr(), data.get(), static_cast<size_t>(t.storage_numel) * item);
  } catch (const Error&) {
    throw;
  } catch (const std::exception& e) {
    fail(path, "tensor '" + name + "': cannot read " + record + ": " + first_line(e.what()));
  }
  return storage.as_strided(t.sizes, t.strides, t.offset).contiguous();
}

// The view must stay inside its storage (a corrupt pickle must not read out of bounds).
void check_bounds(const PickledTensor& t, const std::string& path, const std::string& name) {
  int64_t last = t.offset;
  bool empty = false;
  for (size_t d = 0; d < t.sizes.size(); ++d) {
    if (t.sizes[d] < 0 || t.strides[d] < 0) fail(path, "tensor '" + name + "': negative size or stride");
    if (t.sizes[d] == 0) empty = true;
    else last += (t.sizes[d] - 1) * t.strides[d];
  }
  if (t.offset < 0 || (!empty && last >= t.storage_numel))
    fail(path, "tensor '" + name + "': view exceeds its storage of " + std::to_string(t.storage_numel) + " elements");
}

void collect(const PyRef& v, const std::string& prefix, const std::shared_ptr<Reader>& reader, WeightFile& out) {
  auto join = [&](const std::string& key) { return prefix.empty() ? key : prefix + "." + key; };
  switch (v->kind) {
    case PyValue::Kind::Tensor: {
      if (prefix.empty()) fail(out.source(), "archive holds a single tensor, not a dict of named tensors");
      check_bounds(v->tensor, out.source(), prefix);
      const PickledTensor t = v->tensor;
      const std::string path = out.source(), name = prefix;
      out.add(prefix, TensorInfo{t.dtype, t.sizes}, [reader, t, path, name] { return materialise(reader, t, path, name); });
      break;
    }
    case PyValue::Kind::Dict:
    case PyValue::Kind::Object:  // scripted modules: attributes; other objects: their state
      for (const auto& [key, value] : v->dict) {
        if (key->kind == PyValue::Kind::String) collect(value, join(key->s), reader, out);
        else if (key->kind == PyValue::Kind::Int) collect(value, join(std::to_string(key->i)), reader, out);
      }
      break;
    case PyValue::Kind::List:
    case PyValue::Kind::Tuple:
      for (size_t i = 0; i < v->items.size(); ++i) collect(v->items[i], join(std::to_string(i)), reader, out);
      break;
    default:
      break;
  }
}

}  // namespace

WeightFile read_torch_archive(const std::string& path) {
  WeightFile out(path);
  std::shared_ptr<Reader> reader;
  std::string pickle;
  try {
    reader = std::make_shared<Reader>(path);
    if (!reader->hasRecord("data.pkl")) fail(path, "zip archive without data.pkl: not a PyTorch checkpoint");
    auto [data, size] = reader->getRecord("data.pkl");
    pickle.assign(static_cast<const char*>(data.get()), size);
  } catch (const Error&) {
    throw;
  } catch (const std::exception& e) {
    fail(path, "cannot read PyTorch zip archive (corrupt or truncated?): " + first_line(e.what()));
  }
  collect(read_pickle(pickle, path), "", reader, out);
  if (out.size() == 0) fail(path, "PyTorch archive holds no tensors");
  return out;
}

}  // namespace cls
