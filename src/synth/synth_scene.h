#pragma once
// A synthetic scene of a city model: views rendered from UAV-like cameras, the COLMAP model and
// the ground truth (label images, labelled point cloud), in memory and written to a directory.
#include <cstdint>
#include <string>
#include <vector>

#include "citymodel/semantic_mesh.h"
#include "citymodel/taxonomy.h"
#include "scene/colmap.h"
#include "synth/gt_point_cloud.h"
#include "synth/renderer.h"
#include "synth/uav_cameras.h"

namespace cls::synth {

struct SynthSettings {
  int views = 24;
  int width = 480, height = 360;
  double hfov_deg = 60;
  uint64_t seed = 1;
  int samples_per_view = 300;  // sparse point samples per view
  double point_noise = 0.01;   // sparse point noise (scene units)
  double gt_density = 400;     // GT cloud samples per m² on the city model; terrain/clutter get 1/8
  bool per_building = false;   // views around each building in turn (a district) instead of around all
  int occluders = 0;           // extra trees just in front of the facades (synth --occluders)
};

// What is wrong with the settings ("" if nothing): sizes, counts and ranges.
std::string settings_problem(const SynthSettings& s);

struct SynthScene {
  SynthGeometry geometry;
  std::vector<SynthView> views;
  std::vector<RenderedView> rendered;
  ColmapModel colmap;
  std::vector<GtPoint> gt_points;
};

// Renders everything (multithreaded, with progress). Deterministic for settings.seed.
// The mesh must have triangles and valid settings (see settings_problem).
SynthScene render_synth_scene(const SemanticMesh& mesh, const Taxonomy& taxonomy, const SynthSettings& settings);

// Writes images/, sparse/0/ (binary and text), gt/labels/, gt/legend.json and gt/points.ply
// under `dir`, each file atomically.
void write_synth_outputs(const std::string& dir, const SynthScene& scene, const Taxonomy& taxonomy);

}  // namespace cls::synth
