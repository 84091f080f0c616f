#include "synth/synth_job.h"

#include <unistd.h>

#include <cstdio>
#include <filesystem>

#include <nlohmann/json.hpp>
#include <optional>

#include "citymodel/city_model.h"
#include "citymodel/city_transform.h"
#include "georef/crs_name.h"
#include "georef/proj_crs.h"
#include "scene/exif_gps.h"
#include "core/atomic_file.h"
#include "core/hash.h"
#include "core/error.h"
#include "core/log.h"
#include "core/run_layout.h"
#include "synth/box.h"
#include "synth/drop_openings.h"

namespace cls::synth {

namespace fs = std::filesystem;

namespace {

bool is_empty_dir(const fs::path& p) { return fs::is_directory(p) && fs::directory_iterator(p) == fs::directory_iterator(); }

// What keeps the job from writing `out` ("" if nothing).
std::string output_problem(const SynthJob& job) {
  const fs::path out(job.out_dir);
  if (!fs::exists(out) || is_empty_dir(out)) return "";
  if (!fs::is_directory(out)) return "exists and is not a directory";
  if (!job.overwrite) return "exists and is not empty (pass --overwrite to replace a previous synth output)";
  if (!fs::exists(SceneFiles{out}.config())) return "is not a synth output (no scene.json): refusing to replace it";
  return "";
}

// The model the pipeline is given: the rendered one, or --given-city read at --given-lod; with openings
// dropped.
GivenCityModel given_city_model(const SynthJob& job, const SemanticMesh& mesh, const std::string& city_bytes,
                                const Taxonomy& taxonomy) {
  GivenCityModel given{job.city_path, city_bytes, mesh.lod};
  if (!job.given_city_path.empty()) {
    const SemanticMesh other = load_city_model(job.given_city_path, taxonomy, job.given_lod);
    if (other.triangles.empty()) fail(job.given_city_path, "the given city model has no surfaces at the chosen LoD");
    given = {job.given_city_path, read_text_file(job.given_city_path), other.lod};
  }
  if (job.drop_openings > 0) {
    DroppedOpenings d = drop_openings(given.path, given.bytes, job.drop_openings, job.settings.seed);
    given.bytes = std::move(d.text);
    given.openings_dropped = d.dropped;
    given.openings_total = d.total;
  }
  return given;
}

}  // namespace

namespace {

// A scene with GPS and no deliberate error is left for the pipeline to georeference.
bool names_city_transform(const SynthJob& job) { return !job.gps.enabled || job.city_error.any(); }

}  // namespace

std::string synth_scene_json(const SynthJob& job, const std::string& city_bytes, const std::string& taxonomy_bytes,
                             const GivenCityModel& given) {
  const SynthSettings& s = job.settings;
  const std::string city_file = fs::path(job.city_path).filename().string();
  const std::string given_file = fs::path(given.path).filename().string();
  nlohmann::ordered_json generator = {
      {"program", "citylangsplat synth"},
      {"version", CLS_VERSION},
      {"city_source", city_file},
      {"city_fnv1a64", fnv1a64_hex(city_bytes)},
      {"lod_option", job.lod},
      {"taxonomy", job.taxonomy_path.empty() ? std::string("builtin") : fs::path(job.taxonomy_path).filename().string()},
      {"taxonomy_fnv1a64", job.taxonomy_path.empty() ? std::string() : fnv1a64_hex(taxonomy_bytes)},
      {"views", s.views},
      {"width", s.width},
      {"height", s.height},
      {"hfov_deg", s.hfov_deg},
      {"seed", s.seed},
      {"samples_per_view", s.samples_per_view},
      {"point_noise", s.point_noise},
      {"gt_density", s.gt_density},
      {"gt_context_density", s.gt_density / 8},
  };
  if (s.per_building) generator["rig"] = "per-building";  // absent: the orbit rig (older scene.json stay equal)
  if (s.occluders > 0) generator["occluders"] = s.occluders;
  if (job.gps.enabled) generator["gps"] = {{"error", gps_error_text(job.gps)}, {"truth", "city/transform_true.json"}};
  if (job.city_error.any())
    generator["city_error"] = {{"t", job.city_error.metres},
                               {"r", job.city_error.degrees},
                               {"s", job.city_error.scale},
                               {"truth", "city/transform_true.json"}};
  // Absent unless used, so older scene.json stay equal.
  if (!job.given_city_path.empty())
    generator["given_city"] = {{"source", given_file}, {"fnv1a64", fnv1a64_hex(given.bytes)}, {"lod_option", job.given_lod}};
  if (job.drop_openings > 0)
    generator["drop_openings"] = {
        {"fraction", job.drop_openings}, {"dropped", given.openings_dropped}, {"of", given.openings_total}};
  nlohmann::ordered_json scene = {
      {"city_model", "city/" + given_file},
      {"city_transform", "city/transform.json"},
      {"lod", given.lod},
      {"generator", generator},
  };
  if (!names_city_transform(job)) scene.erase("city_transform");
  return scene.dump(2) + "\n";
}

bool run_synth_job(const SynthJob& job) {
  const std::string problem = settings_problem(job.settings);
  if (!problem.empty()) throw UsageError("synth: " + problem);
  if (job.out_dir.empty()) throw UsageError("synth: --out is required");
  if (!(job.drop_openings >= 0 && job.drop_openings <= 1))
    throw UsageError("synth: --drop-openings: expected a fraction in [0, 1], got " + std::to_string(job.drop_openings));
  const fs::path out = fs::absolute(job.out_dir).lexically_normal();
  if (out.filename().empty() || out == out.root_path()) throw UsageError("synth: --out must name a directory");

  const Taxonomy taxonomy = load_taxonomy({job.lod, job.taxonomy_path});
  const std::string taxonomy_bytes = job.taxonomy_path.empty() ? std::string() : read_text_file(job.taxonomy_path);
  const SemanticMesh mesh = load_city_model(job.city_path, taxonomy, job.lod);
  if (mesh.triangles.empty()) fail(job.city_path, "the city model has no surfaces to render at the chosen LoD");
  const std::string city_bytes = read_text_file(job.city_path);
  const GivenCityModel given = given_city_model(job, mesh, city_bytes, taxonomy);
  const std::string scene_json = synth_scene_json(job, city_bytes, taxonomy_bytes, given);

  if (job.skip_if_same && fs::exists(SceneFiles{out}.config()) && read_text_file(SceneFiles{out}.config()) == scene_json) {
    log_info("synth: " + out.string() + " is up to date");
    return false;
  }
  const std::string bad_output = output_problem(job);
  if (!bad_output.empty()) fail(job.out_dir, bad_output);

  std::optional<GpsProjection> projection;
  if (job.gps.enabled) projection.emplace(city_model_crs(job.city_path, mesh.crs, "").horizontal_epsg);  // the model's own CRS
  const SynthScene scene = render_synth_scene(mesh, taxonomy, job.settings);

  // Stage beside the destination (same file system), then swap it in.
  const fs::path staging = out.parent_path() / ("." + out.filename().string() + ".synth-tmp" + std::to_string(::getpid()));
  try {
    fs::remove_all(staging);
    fs::create_directories(staging);
    write_synth_outputs(staging.string(), scene, taxonomy);
    const fs::path given_file = staging / "city" / fs::path(given.path).filename();
    write_text_atomic(given_file, given.bytes);
    if (job.drop_openings > 0) load_city_model(given_file.string(), taxonomy, given.lod);  // the edit still reads
    CityTransform to_scene;
    for (int i = 0; i < 3; ++i) to_scene.matrix[i][3] = -mesh.origin[i];
    if (job.gps.enabled) {
      std::vector<Vec3d> centres;
      for (const SynthView& v : scene.views)
        centres.push_back(v.pose.center() + Vec3d{mesh.origin[0], mesh.origin[1], mesh.origin[2]});
      const std::vector<GpsFix> fixes = spoilt_gps(centres, *projection, job.gps, job.settings.seed);
      for (size_t i = 0; i < fixes.size(); ++i) write_exif_gps((staging / "images" / scene.views[i].name).string(), fixes[i]);
    }
    if (job.city_error.any()) {
      // About the model's bounding-box centre in the scene frame, so the error does not grow with the
      // distance to the CRS origin.
      Box3d bounds;
      for (const auto& v : mesh.vertices) bounds.extend({v[0], v[1], v[2]});
      write_city_transform((staging / "city" / "transform_true.json").string(), to_scene);
      to_scene = city_error_transform(job.city_error, job.settings.seed, bounds.center()) * to_scene;
    }
    if (!names_city_transform(job)) write_city_transform((staging / "city" / "transform_true.json").string(), to_scene);
    else write_city_transform((staging / "city" / "transform.json").string(), to_scene);
    write_text_atomic(SceneFiles{staging}.config(), scene_json);
    if (fs::exists(out)) fs::remove_all(out);
    fs::rename(staging, out);
  } catch (const fs::filesystem_error& e) {
    std::error_code ec;
    fs::remove_all(staging, ec);
    fail(job.out_dir, std::string("cannot write the scene: ") + e.code().message());
  } catch (...) {
    std::error_code ec;
    fs::remove_all(staging, ec);
    throw;
  }
  log_info("synth: wrote " + out.string());
  return true;
}

}  // namespace cls::synth
