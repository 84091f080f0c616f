#pragma once
// Raycasts every view of a scene and writes its label maps (the `raycast` stage of the pipeline).
#include <filesystem>
#include <vector>

#include "citymodel/scene_city_model.h"
#include "scene/scene.h"

namespace cls {

// OUT/<image name without extension>: the image stem for flat names, keeping sub-folders so two
// images "a/1.jpg" and "b/1.jpg" do not collide. cls::Error for names that would leave OUT, so a
// caller can check the scene before it writes anything.
std::vector<std::filesystem::path> label_map_dirs(const Scene& scene, const std::filesystem::path& out);

constexpr const char* kLabelsCityTransform = "city_transform.json";

struct LabelExportSummary {
  size_t views = 0;
  double mean_coverage = 0;  // mean fraction of pixels with M_t = 1
};

// Writes OUT/<view>/{level1,level2,level3,building,coverage}.png, depth.pfm, object.npy, preview.png
// for every view, with progress, then OUT/objects.json (the city objects object.npy indexes),
// OUT/city_mesh.ply (the mesh in the scene frame, mesh_ply.h), OUT/city_transform.json (the transform
// with the city model's CRS: read_city_frame) and OUT/legend.json last (its presence marks a finished
// export).
LabelExportSummary export_label_maps(const Scene& scene, const SceneCityModel& city, const std::filesystem::path& out);

}  // namespace cls
