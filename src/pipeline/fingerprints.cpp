#include "pipeline/fingerprints.h"

#include <cstdio>
#include <nlohmann/json.hpp>

#include "core/atomic_file.h"
#include "core/hash.h"

namespace cls {
namespace fs = std::filesystem;
namespace {

uint64_t hash_views(const Scene& scene, uint64_t h) {
  for (const SceneView& v : scene.views) {
    const PinholeCamera& c = v.camera;
    char buf[512];
    std::snprintf(buf, sizeof buf, "%s|%.17g %.17g %.17g %.17g %d %d|", v.name.c_str(), c.fx, c.fy, c.cx, c.cy,
                  c.width, c.height);
    std::string s = buf;
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) s += std::to_string(v.pose.R.m[i][j]) + " ";
      s += std::to_string(v.pose.t[i]) + ";";
    }
    h = fnv1a64(s, h);
  }
  return h;
}

}  // namespace

std::string views_fingerprint(const Scene& scene) { return hex64(hash_views(scene, fnv1a64("views"))); }

std::string images_fingerprint(const Scene& scene) {
  uint64_t h = hash_views(scene, fnv1a64("images"));
  for (const SceneView& v : scene.views) h = fnv1a64(read_text_file(v.image_path), h);
  return hex64(h);
}

std::string file_fingerprint(const fs::path& file) { return file.empty() ? "" : file_fnv1a64_hex(file); }

std::string taxonomy_fingerprint(const Taxonomy& taxonomy) {
  nlohmann::json classes = nlohmann::json::array();
  for (const SemanticClass& c : taxonomy.classes)
    classes.push_back({{"name", c.name}, {"level", c.level}, {"source_types", c.source_types}, {"prompts", c.prompts},
                       {"color", c.color}});
  return hex64(fnv1a64(classes.dump()));
}

std::string features_fingerprint(const fs::path& features_dir) {
  const std::string text = read_text_file(features_dir / "features.json");
  uint64_t h = fnv1a64(text);
  const nlohmann::json index = nlohmann::json::parse(text);  // named: a temporary would dangle in the loop
  for (const auto& view : index.at("views"))
    h = fnv1a64(read_text_file(features_dir / (view.at("features").get<std::string>() + "_gml.json")), h);
  return hex64(h);
}

}  // namespace cls
