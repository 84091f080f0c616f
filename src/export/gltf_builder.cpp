#include "export/gltf_builder.h"

#include <algorithm>
#include <cstring>
#include <stdexcept>

#include "core/atomic_file.h"
#include "core/endian.h"

namespace cls {
namespace {

constexpr uint32_t kGlbMagic = 0x46546C67;      // "glTF"
constexpr uint32_t kGlbJsonChunk = 0x4E4F534A;  // "JSON"
constexpr uint32_t kGlbBinChunk = 0x004E4942;   // "BIN\0"

void append_u32(std::string& s, uint32_t v) {
  static_assert(host_is_little_endian(), "GLB is little-endian; add a byte swap for this host");
  s.append(reinterpret_cast<const char*>(&v), 4);
}

}  // namespace

int gltf_type_components(const std::string& type) {
  if (type == "SCALAR") return 1;
  if (type == "VEC2") return 2;
  if (type == "VEC3") return 3;
  if (type == "VEC4" || type == "MAT2") return 4;
  if (type == "MAT3") return 9;
  if (type == "MAT4") return 16;
  return 0;
}

int gltf_component_bytes(int component) {
  switch (component) {
    case kGltfByte:
    case kGltfUnsignedByte: return 1;
    case kGltfShort:
    case kGltfUnsignedShort: return 2;
    case kGltfUnsignedInt:
    case kGltfFloat: return 4;
    default: return 0;
  }
}

GltfBuilder::GltfBuilder() {
  json_ = {{"asset", {{"version", "2.0"}}},
           {"buffers", nlohmann::json::array()},
           {"bufferViews", nlohmann::json::array()},
           {"accessors", nlohmann::json::array()}};
}

int GltfBuilder::add_view(const void* data, size_t bytes, int target, size_t alignment) {
  if (alignment < 4) alignment = 4;
  binary_.resize((binary_.size() + alignment - 1) / alignment * alignment, 0);
  const size_t offset = binary_.size();
  binary_.resize(offset + bytes);
  if (bytes) std::memcpy(binary_.data() + offset, data, bytes);
  nlohmann::json view{{"buffer", 0}, {"byteOffset", offset}, {"byteLength", bytes}};
  if (target) view["target"] = target;
  json_["bufferViews"].push_back(view);
  return static_cast<int>(json_["bufferViews"].size()) - 1;
}

int GltfBuilder::add_accessor(const void* data, int64_t count, const std::string& type, int component, bool normalized,
                              const std::vector<double>& min, const std::vector<double>& max) {
  const int components = gltf_type_components(type), bytes = gltf_component_bytes(component);
  if (!components || !bytes || count < 0) throw std::logic_error("gltf: accessor of type " + type + " / " +
                                                                 std::to_string(component));
  nlohmann::json accessor{{"componentType", component}, {"count", count}, {"type", type}};
  if (data) accessor["bufferView"] = add_view(data, static_cast<size_t>(count) * components * bytes, kGltfArrayBuffer);
  if (normalized) accessor["normalized"] = true;
  if (!min.empty()) accessor["min"] = min;
  if (!max.empty()) accessor["max"] = max;
  json_["accessors"].push_back(accessor);
  return static_cast<int>(json_["accessors"].size()) - 1;
}

void GltfBuilder::use_extension(const std::string& name, bool required) {
  auto add_to = [&](const char* list) {
    nlohmann::json& names = json_[list];
    if (names.is_null()) names = nlohmann::json::array();
    if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
  };
  add_to("extensionsUsed");
  if (required) add_to("extensionsRequired");
}

std::string GltfBuilder::glb() const {
  nlohmann::json j = json_;
  j["buffers"] = nlohmann::json::array({{{"byteLength", binary_.size()}}});
  std::string text = j.dump();
  text.resize((text.size() + 3) / 4 * 4, ' ');  // the JSON chunk is padded with spaces
  const size_t bin = (binary_.size() + 3) / 4 * 4;
  std::string out;
  out.reserve(12 + 8 + text.size() + 8 + bin);
  append_u32(out, kGlbMagic);
  append_u32(out, 2);
  append_u32(out, static_cast<uint32_t>(12 + 8 + text.size() + (binary_.empty() ? 0 : 8 + bin)));
  append_u32(out, static_cast<uint32_t>(text.size()));
  append_u32(out, kGlbJsonChunk);
  out += text;
  if (!binary_.empty()) {
    append_u32(out, static_cast<uint32_t>(bin));
    append_u32(out, kGlbBinChunk);
    out.append(reinterpret_cast<const char*>(binary_.data()), binary_.size());
    out.resize(out.size() + (bin - binary_.size()), '\0');
  }
  return out;
}

std::string GltfBuilder::gltf_json(const std::string& bin_uri) const {
  nlohmann::json j = json_;
  j["buffers"] = nlohmann::json::array({{{"byteLength", binary_.size()}, {"uri", bin_uri}}});
  return j.dump(1);
}

void GltfBuilder::write(const std::filesystem::path& path) const {
  if (path.extension() == ".glb") {
    write_text_atomic(path, glb());
    return;
  }
  std::filesystem::path bin = path;
  bin.replace_extension(".bin");
  // The buffer first: a reader that finds the .gltf finds its buffer complete.
  write_text_atomic(bin, std::string(reinterpret_cast<const char*>(binary_.data()), binary_.size()));
  write_text_atomic(path, gltf_json(bin.filename().string()));
}

}  // namespace cls
