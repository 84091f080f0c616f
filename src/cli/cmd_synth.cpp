// citylangsplat synth: a synthetic scene (images, COLMAP model, ground truth) of a city model.
#include <cstdint>
#include <string>

#include "citymodel/city_model.h"
#include "core/args.h"
#include "cli/commands.h"
#include "core/error.h"
#include "core/log.h"
#include "synth/city_error.h"
#include "synth/synth_job.h"

namespace cls {

namespace {

// --city-error as text: t=METRES,r=DEGREES,s=FRACTION ("" for none).
Codec<synth::CityError> city_error_codec() {
  Codec<synth::CityError> c;
  c.text = [](const synth::CityError& e) {
    return e.any() ? cat("t=", e.metres, ",r=", e.degrees, ",s=", e.scale) : std::string();
  };
  c.parse = [](const std::string& text) { return synth::parse_city_error(text); };
  return c;
}

Codec<synth::GpsError> gps_error_codec() {
  Codec<synth::GpsError> c;
  c.text = [](const synth::GpsError& e) { return synth::gps_error_text(e); };
  c.parse = [](const std::string& text) { return synth::parse_gps_error(text); };
  return c;
}

}  // namespace

int cmd_synth(int argc, char** argv) {
  Args args("synth",
            "Render a synthetic scene of a city model from UAV-like oblique views: photo-like images with\n"
            "procedural materials, a terrain plane and clutter that is not in the model, a COLMAP model\n"
            "(binary and text) with sparse points, label images (level-1 classes) and a labelled point\n"
            "cloud (gt/points.ply). Deterministic for a seed.");
  synth::SynthJob job;
  synth::SynthSettings& settings = job.settings;
  args.bind("city", job.city_path, "city model file (CityGML, CityJSON, CityJSONSeq)")
      .required()
      .bind("out", job.out_dir, "output scene directory")
      .required()
      .bind("views", settings.views, "number of views")
      .bind("width", settings.width, "image width (pixels)")
      .bind("height", settings.height, "image height (pixels)")
      .bind("hfov", settings.hfov_deg, "horizontal field of view (degrees)")
      .bind("seed", settings.seed, "random seed: cameras, clutter, materials, lighting, points")
      .bind("lod", job.lod, "LoD to read: 1, 2, 3, or 0 / highest", lod_codec())
      .default_text("0")
      .bind("taxonomy", job.taxonomy_path, "taxonomy JSON (default: the built-in one)")
      .bind("points-per-view", settings.samples_per_view, "sparse point samples per view")
      .bind("point-noise", settings.point_noise, "standard deviation of the sparse points' noise (scene units)")
      .bind("gt-density", settings.gt_density,
            "ground-truth cloud samples per square unit on the city model (1/8 of it on terrain and clutter)")
      .bind("city-error", job.city_error,
            "give the pipeline a wrong city transform: t=METRES,r=DEGREES,s=FRACTION (seeded "
            "direction and axis, about the model's centre); the exact one goes to "
            "city/transform_true.json (default: none)",
            city_error_codec())
      .bind("gps", job.gps,
            "write EXIF GPS into the photos, spoilt as phones spoil it: on (h=3,v=3,datum=50,outliers=0.1,"
            "outlier-m=30), or any of h=METRES (easting and northing noise, each), v=METRES (height noise), "
            "datum=METRES (added to every height), outliers=FRACTION (of photos moved by outlier-m=METRES); the "
            "model's CRS must be known. Without --city-error the scene then names no city transform (run "
            "georeferences it), and the truth goes to city/transform_true.json (default: none)",
            gps_error_codec())
      .bind("occluders", settings.occluders, "extra trees just in front of the facades (hiding parts of them in the images)")
      .bind("given-city", job.given_city_path,
            "give the pipeline this model of the same place and CRS instead (e.g. the "
            "building's LoD2 model); images and ground truth show --city (default: --city)")
      .bind("given-lod", job.given_lod, "LoD to read from --given-city: 1, 2, 3, or 0 / highest", lod_codec())
      .default_text("0")
      .bind("drop-openings", job.drop_openings,
            "fraction of the given model's windows and doors merged into the surface "
            "they sit in (seeded choice); the images and ground truth keep them")
      .flag("per-building", settings.per_building,
            "a district: split the views over the buildings, each share circling its own building")
      .flag("overwrite", job.overwrite, "replace an existing synth output in --out")
      .flag("skip-if-same", job.skip_if_same,
            "do nothing if --out holds a scene generated with the same settings and inputs");
  if (!args.parse(argc, argv)) return 0;
  synth::run_synth_job(job);
  return 0;
}

}  // namespace cls
