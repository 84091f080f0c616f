#include "models/weights/torch_archive.h"

#include <ATen/ATen.h>
#include <caffe2/serialize/inline_container.h>
#include <torch/csrc/jit/api/compilation_unit.h>
#include <torch/csrc/jit/serialization/import_read.h>

#include "core/error.h"

namespace cls {
namespace {

// Walks the unpickled value and records every tensor under its dotted path.
void collect_tensors(const c10::IValue& v, const std::string& prefix, WeightFile& out) {
  auto join = [&](const std::string& key) { return prefix.empty() ? key : prefix + "." + key; };
  if (v.isTensor()) {
    if (prefix.empty()) fail(out.source(), "archive holds a single tensor, not a dict of named tensors");
    out.add(prefix, v.toTensor());
  } else if (v.isObject()) {
    const auto obj = v.toObject();
    const auto type = obj->type();
    for (size_t i = 0; i < type->numAttributes(); ++i)
      collect_tensors(obj->getSlot(i), join(type->getAttributeName(i)), out);
  } else if (v.isGenericDict()) {
    for (const auto& item : v.toGenericDict()) {
      const c10::IValue& key = item.key();
      if (key.isString()) collect_tensors(item.value(), join(key.toStringRef()), out);
      else if (key.isInt()) collect_tensors(item.value(), join(std::to_string(key.toInt())), out);
    }
  } else if (v.isList() || v.isTuple()) {
    // Lists of tensors (rare in checkpoints) are named by index.
    const std::vector<c10::IValue> items =
        v.isList() ? v.toListRef().vec() : v.toTupleRef().elements().vec();
    for (size_t i = 0; i < items.size(); ++i) collect_tensors(items[i], join(std::to_string(i)), out);
  }
}

}  // namespace

WeightFile read_torch_archive(const std::string& path) {
  WeightFile out(path);
  c10::IValue root;
  try {
    caffe2::serialize::PyTorchStreamReader reader(path);
    if (!reader.hasRecord("data.pkl"))
      fail(path, "zip archive without data.pkl: not a PyTorch checkpoint");
    auto cu = std::make_shared<torch::jit::CompilationUnit>();
    // Scripted classes (TorchScript archives) resolve to empty class types; no code is loaded.
    torch::jit::TypeResolver resolve = [cu](const c10::QualifiedName& name) {
      c10::ClassTypePtr type = cu->get_class(name);
      if (!type) {
        type = c10::ClassType::create(name, cu);
        cu->register_type(type);
      }
      return c10::StrongTypePtr(cu, type);
    };
    // Each object becomes a fresh attribute bag holding the pickled state (a dict of attributes
    // for modules; anything else is kept as "__state__").
    torch::jit::ObjLoader load_object = [cu](const c10::StrongTypePtr& type, c10::IValue state) {
      auto bag = c10::ClassType::create(type.type_->expect<c10::ClassType>()->name(), cu);
      std::vector<std::pair<std::string, c10::IValue>> attributes;
      if (state.isGenericDict()) {
        for (const auto& item : state.toGenericDict())
          if (item.key().isString()) attributes.emplace_back(item.key().toStringRef(), item.value());
      } else {
        attributes.emplace_back("__state__", state);
      }
      for (const auto& [name, value] : attributes) bag->addAttribute(name, value.type());
      auto obj = c10::ivalue::Object::create(c10::StrongTypePtr(cu, bag), attributes.size());
      for (size_t i = 0; i < attributes.size(); ++i) obj->setSlot(i, attributes[i].second);
      return obj;
    };
    root = torch::jit::readArchiveAndTensors("data", "", "data/", resolve, load_object, at::Device(at::kCPU), reader);
  } catch (const Error&) {
    throw;
  } catch (const std::exception& e) {
    std::string what = e.what();
    if (const size_t nl = what.find('\n'); nl != std::string::npos) what.resize(nl);  // drop c10 backtraces
    fail(path, "cannot read PyTorch zip archive (corrupt or truncated?): " + what);
  }
  collect_tensors(root, "", out);
  if (out.size() == 0) fail(path, "PyTorch archive holds no tensors");
  return out;
}

}  // namespace cls
