#pragma once
// `citylangsplat synth` as a library call: loads the city model, renders the synthetic scene and
// writes the scene directory all at once (staged beside it and renamed into place), so a
// directory with a scene.json is always complete.
#include <string>

#include "synth/city_error.h"
#include "synth/gps_error.h"
#include "synth/synth_scene.h"

namespace cls::synth {

struct SynthJob {
  std::string city_path;
  std::string out_dir;
  int lod = 0;                // 1, 2, 3, or 0 for the highest LoD in the file
  std::string taxonomy_path;  // "" = the built-in taxonomy
  SynthSettings settings;
  CityError city_error;       // put into city/transform.json; the exact one goes to city/transform_true.json
  // EXIF GPS in the photos (the model's CRS must be known). Without city_error, the scene then names no
  // city transform: the pipeline georeferences from the GPS; the truth goes to city/transform_true.json.
  GpsError gps;
  // What the pipeline is given instead of the model the scene shows (the truth stays in the images and gt/):
  std::string given_city_path;  // another model of the same place in the same CRS (e.g. its LoD2); "" = city_path
  int given_lod = 0;            // LoD read from given_city_path (0: its highest)
  double drop_openings = 0;     // fraction of the given model's openings merged into their surfaces
  bool overwrite = false;     // replace an existing synth output (a directory with scene.json)
  bool skip_if_same = false;  // do nothing if out_dir/scene.json equals what this job would write
};

// Layout of the scene directory:
//   scene.json                  {"city_model", "city_transform", "lod", "generator": {...}}
//   city/<given model file> (city_path, or given_city_path; with drop_openings, the edited model),
//   city/transform.json (source CRS -> scene frame: translation by -origin, times the
//   city_error_transform when city_error.any(), then with the exact one in city/transform_true.json;
//   with gps.enabled and no city_error, only transform_true.json and no "city_transform" in scene.json)
//   images/NNNN.png, sparse/0/{cameras,images,points3D}.{bin,txt}
//   gt/labels/NNNN.png, gt/legend.json, gt/points.ply (settings.gt_density points per m² on the
//   city model, 1/8 of that on clutter and on the terrain near the building; class -1 off the model)
// All inputs and the output directory are checked before anything is rendered or written
// (cls::UsageError for bad settings, cls::Error naming the file otherwise).
// Returns false when skip_if_same found the output up to date, true when it wrote it.
bool run_synth_job(const SynthJob& job);

// The scene.json a job writes (tested: it decides skip_if_same).
// `given` is the model the pipeline reads (its file, LoD and, with drop_openings, the openings dropped).
struct GivenCityModel {
  std::string path, bytes;
  int lod = 0;
  int openings_dropped = 0, openings_total = 0;
};
std::string synth_scene_json(const SynthJob& job, const std::string& city_bytes, const std::string& taxonomy_bytes,
                             const GivenCityModel& given);

}  // namespace cls::synth
