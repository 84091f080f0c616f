#pragma once
// A glTF 2.0 asset assembled in memory, one binary buffer, written as .glb or as .gltf + .bin.
// Hand-written rather than tinygltf (Debian's libtinygltf): our assets are JSON objects of extensions
// (KHR_gaussian_splatting, EXT_mesh_features, EXT_structural_metadata) that nlohmann-json already
// spells, tinygltf would take them as its own Value trees, and its writer puts a .gltf's buffer beside
// it non-atomically or embeds it as base64; what is left is the GLB container (a 12-byte header and two
// chunks). Khronos' glTF-Validator checks what this writes (tests/export).
#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace cls {

// glTF accessor component types and buffer view targets.
enum GltfComponent : int {
  kGltfByte = 5120,
  kGltfUnsignedByte = 5121,
  kGltfShort = 5122,
  kGltfUnsignedShort = 5123,
  kGltfUnsignedInt = 5125,
  kGltfFloat = 5126,
};
constexpr int kGltfArrayBuffer = 34962;  // vertex attributes

class GltfBuilder {
 public:
  GltfBuilder();

  nlohmann::json& json() { return json_; }
  const nlohmann::json& json() const { return json_; }
  const std::vector<uint8_t>& binary() const { return binary_; }

  // Appends `bytes` to the buffer at an offset aligned to `alignment` (and 4, as GLB chunks and vertex
  // attributes need) and adds a buffer view; its index. `target` 0 leaves it out (metadata tables).
  int add_view(const void* data, size_t bytes, int target = 0, size_t alignment = 4);
  // A view of `count` elements of `type` ("SCALAR", "VEC3" ...) and `component`, plus its accessor; the
  // accessor's index. `min`/`max` (per component) are written when given, as POSITION requires. `data`
  // null: an accessor without a buffer view, whose values an extension supplies (SPZ).
  int add_accessor(const void* data, int64_t count, const std::string& type, int component, bool normalized = false,
                   const std::vector<double>& min = {}, const std::vector<double>& max = {});
  // Adds `name` to extensionsUsed (and extensionsRequired when `required`), once.
  void use_extension(const std::string& name, bool required = false);

  // The finished asset (buffers[0] sized to the binary) as GLB bytes, or as .gltf JSON naming `bin_uri`.
  std::string glb() const;
  std::string gltf_json(const std::string& bin_uri) const;

  // Atomic writes: `path` ending in .glb gets the container, else path (.gltf) and path's stem + .bin.
  void write(const std::filesystem::path& path) const;

 private:
  nlohmann::json json_;
  std::vector<uint8_t> binary_;
};

// Number of components of an accessor type ("SCALAR" 1 ... "MAT4" 16); 0 for anything else.
int gltf_type_components(const std::string& type);
// Bytes of one component; 0 for an unknown component type.
int gltf_component_bytes(int component);

}  // namespace cls
