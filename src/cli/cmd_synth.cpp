// citylangsplat synth: a synthetic scene (images, COLMAP model, ground truth) of a city model.
#include <string>

#include "citymodel/city_model.h"
#include "core/args.h"
#include "cli/commands.h"
#include "core/error.h"
#include "synth/synth_job.h"

namespace cls {

namespace {
uint64_t parse_seed(const std::string& text) {
  const bool digits = !text.empty() && text.size() <= 20 &&
                      text.find_first_not_of("0123456789") == std::string::npos;
  if (!digits) throw UsageError("--seed: expected a non-negative integer, got '" + text + "'");
  try {
    return std::stoull(text);
  } catch (const std::exception&) {
    throw UsageError("--seed: out of range: '" + text + "'");
  }
}
}  // namespace

int cmd_synth(int argc, char** argv) {
  const synth::SynthSettings defaults;
  Args args("synth",
            "Render a synthetic scene of a city model from UAV-like oblique views: photo-like images with\n"
            "procedural materials, a terrain plane and clutter that is not in the model, a COLMAP model\n"
            "(binary and text) with sparse points, label images (level-1 classes) and a labelled point\n"
            "cloud (gt/points.ply). Deterministic for a seed.");
  args.option("city", "", "city model file (CityGML, CityJSON, CityJSONSeq)")
      .option("out", "", "output scene directory")
      .option("views", std::to_string(defaults.views), "number of views")
      .option("width", std::to_string(defaults.width), "image width (pixels)")
      .option("height", std::to_string(defaults.height), "image height (pixels)")
      .option("hfov", "60", "horizontal field of view (degrees)")
      .option("seed", "1", "random seed: cameras, clutter, materials, lighting, points")
      .option("lod", "0", "LoD to read: 1, 2, 3, or 0 / highest")
      .option("taxonomy", "", "taxonomy JSON (default: the built-in one)")
      .option("points-per-view", std::to_string(defaults.samples_per_view), "sparse point samples per view")
      .option("point-noise", "0.01", "standard deviation of the sparse points' noise (scene units)")
      .option("gt-density", "400", "ground-truth cloud samples per square unit on the city model (1/8 of it on terrain and clutter)")
      .option("city-error", "", "give the pipeline a wrong city transform: t=METRES,r=DEGREES,s=FRACTION (seeded "
                                "direction and axis, about the model's centre); the exact one goes to "
                                "city/transform_true.json (default: none)")
      .option("occluders", "0", "extra trees just in front of the facades (hiding parts of them in the images)")
      .option("given-city", "", "give the pipeline this model of the same place and CRS instead (e.g. the "
                                "building's LoD2 model); images and ground truth show --city (default: --city)")
      .option("given-lod", "0", "LoD to read from --given-city: 1, 2, 3, or 0 / highest")
      .option("drop-openings", "0", "fraction of the given model's windows and doors merged into the surface "
                                    "they sit in (seeded choice); the images and ground truth keep them")
      .flag("per-building", "a district: split the views over the buildings, each share circling its own building")
      .flag("overwrite", "replace an existing synth output in --out")
      .flag("skip-if-same", "do nothing if --out holds a scene generated with the same settings and inputs");
  if (!args.parse(argc, argv)) return 0;
  if (!args.has("city")) throw UsageError("synth: --city is required");
  if (!args.has("out")) throw UsageError("synth: --out is required");

  synth::SynthJob job;
  job.city_path = args.get("city");
  job.out_dir = args.get("out");
  job.lod = parse_lod_option(args.get("lod"));
  job.taxonomy_path = args.get("taxonomy");
  job.settings.views = args.get_int("views");
  job.settings.width = args.get_int("width");
  job.settings.height = args.get_int("height");
  job.settings.hfov_deg = args.get_double("hfov");
  job.settings.seed = parse_seed(args.get("seed"));
  job.settings.samples_per_view = args.get_int("points-per-view");
  job.settings.point_noise = args.get_double("point-noise");
  job.settings.gt_density = args.get_double("gt-density");
  job.settings.per_building = args.flag_set("per-building");
  job.settings.occluders = args.get_int("occluders");
  if (args.has("city-error")) job.city_error = synth::parse_city_error(args.get("city-error"));
  job.given_city_path = args.get("given-city");
  job.given_lod = parse_lod_option(args.get("given-lod"));
  job.drop_openings = args.get_double("drop-openings");
  job.overwrite = args.flag_set("overwrite");
  job.skip_if_same = args.flag_set("skip-if-same");
  synth::run_synth_job(job);
  return 0;
}

}  // namespace cls
