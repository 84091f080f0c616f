#include "export/enrich_job.h"

#include <torch/torch.h>

#include <cmath>
#include <filesystem>

#include "citymodel/city_objects.h"
#include "citymodel/scene_city_model.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/log.h"
#include "core/run_layout.h"
#include "eval/evaluation.h"
#include "export/city_observations.h"
#include "export/cityjson_writer.h"
#include "language/language_model.h"
#include "language/provenance.h"
#include "query/relevance.h"
#include "query/selection.h"
#include "query/text_queries.h"
#include "raycast/label_export.h"

namespace cls {
extern const char* const kCityLangSplatExtensionJson;  // generated from data/schemas/citylangsplat.ext.json by CMake

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

json parse_json_file(const fs::path& path) {
  try {
    return json::parse(read_text_file(path));
  } catch (const json::exception& e) {
    throw Error(path.string() + ": not valid JSON (" + e.what() + ")");
  }
}

// Per object, the mean over its Gaussians (those whose provenance object is it or lies in it) of the
// scores at the object's own level; NaN for an object without Gaussians.
std::vector<double> mean_scores(const std::array<at::Tensor, 3>& scores, const CityObjects& objects,
                                const std::vector<int32_t>& gaussian_object, const std::vector<ObjectObservation>& seen) {
  std::array<const float*, 3> s{};
  std::array<at::Tensor, 3> held;
  for (int l = 0; l < 3; ++l) s[l] = (held[l] = scores[l].to(torch::kFloat32).contiguous()).data_ptr<float>();
  std::vector<double> sum(objects.objects.size(), 0.0);
  for (size_t g = 0; g < gaussian_object.size(); ++g)
    for (int32_t o = gaussian_object[g]; o >= 0; o = objects.objects[o].parent) sum[o] += s[objects.objects[o].level - 1][g];
  for (size_t o = 0; o < sum.size(); ++o) sum[o] = seen[o].gaussians > 0 ? sum[o] / seen[o].gaussians : std::nan("");
  return sum;
}

// The scores of `latent` (one text) at each level.
std::array<at::Tensor, 3> level_scores(const LanguageModel& model, const at::Tensor& latent) {
  std::array<at::Tensor, 3> s;
  for (int l = 0; l < 3; ++l) s[l] = gaussian_scores(model.latents[l], latent).cpu();
  return s;
}

}  // namespace

json run_enrich(const EnrichOptions& o) {
  const fs::path root = o.run;
  const RunLayout run(root);
  if (!fs::exists(run.run_json())) throw UsageError("enrich: " + root.string() + " is no `run` output (no run.json there)");
  const fs::path out = o.out.empty() ? root / "enriched.city.json" : fs::path(o.out);
  if (out.extension() != ".json") throw UsageError("enrich: --out " + out.string() + " does not end in .json (CityJSON)");
  if (o.sample_points < 1) throw UsageError("enrich: --sample-points must be at least 1");
  const json record = parse_json_file(run.run_json());
  const json settings = record.value("settings", json::object());
  const std::string city_path = !o.city.empty() ? o.city : settings.value("city", std::string());
  if (city_path.empty()) throw Error(run.run_json().string() + " names no city model: give --city");

  at::NoGradGuard no_grad;
  const fs::path model_dir = language_model_dir(root, o.method, "enrich");
  LanguageModel model = load_language_model(model_dir.string());
  const fs::path labels = recorded_labels_dir(model.info).empty() ? run.labels() : fs::path(recorded_labels_dir(model.info));
  const fs::path transform = labels / kLabelsCityTransform;
  if (!fs::exists(transform))
    throw Error("enrich: " + transform.string() + " is missing: the label maps of this run predate the transform record; run `run` again");
  CityModelOptions city_options;
  city_options.lod = settings.value("lod", 0);
  city_options.taxonomy_path = settings.value("taxonomy", std::string());
  const SceneCityModel city = load_scene_city_model(city_path, transform.string(), city_options, "enrich");
  const CityObjects objects = city_objects(city.mesh, city.taxonomy);
  const CityObjects labelled = read_city_objects(labels / "objects.json");
  if (labelled.objects.size() != objects.objects.size())
    throw Error(cat("enrich: ", city_path, " (LoD ", city.mesh.lod, ") has ", objects.objects.size(), " city objects, the label maps ",
                    labels.string(), " were made from a model with ", labelled.objects.size(), ": not the run's city model"));
  for (size_t i = 0; i < objects.objects.size(); ++i)
    if (objects.objects[i].id != labelled.objects[i].id)
      throw Error(cat("enrich: ", city_path, " is not the city model of the label maps ", labels.string(), ": object ", i, " is '",
                      objects.objects[i].id, "' here, '", labelled.objects[i].id, "' there"));

  std::vector<int32_t> gaussian_object(model.gaussians.size(), -1);
  if (const GaussianExtra* extra = model.gaussians.extra(kObjectProperty)) {
    const at::Tensor ids = extra->values.to(torch::kInt32).contiguous();
    gaussian_object.assign(ids.data_ptr<int32_t>(), ids.data_ptr<int32_t>() + ids.numel());
    for (int32_t& g : gaussian_object)
      if (g >= static_cast<int32_t>(objects.objects.size())) g = -1;
  } else {
    log_warn("enrich: " + model_dir.string() + " has no city object per Gaussian: no Gaussian counts or scores");
  }

  SceneOptions scene_options;  // the views at the size of the label maps, as `run` loads them for its language stages
  scene_options.check_images = false;
  scene_options.resolution_factor = settings.value("resolution", 1);
  scene_options.max_side = settings.value("max_side", 0);
  if (scene_options.resolution_factor == 1) scene_options.max_height = settings.value("feature_height", 0);
  const std::string scene_dir = settings.value("scene", recorded_scene(model.info));
  const Scene scene = load_scene(scene_dir, scene_options);
  ObservationSettings observation;
  observation.sample_points = o.sample_points;
  const std::vector<ObjectObservation> seen =
      observe_city_objects(objects, city.mesh, city.vertices, scene, labels, gaussian_object, observation);

  // The classes of each level and the queries, scored by the model's own provider.
  const std::string model_json = LanguageModelFiles{model_dir}.model_json().string();
  const auto provider = model_provider(model, model_json, model_taxonomy(model.info, model_json, ""));
  std::vector<std::vector<int>> level_classes(3);
  for (size_t c = 0; c < city.taxonomy.classes.size(); ++c) level_classes[city.taxonomy.classes[c].level - 1].push_back(static_cast<int>(c));
  std::vector<std::vector<double>> class_means(city.taxonomy.classes.size());
  for (int l = 0; l < 3; ++l) {
    if (level_classes[l].empty()) continue;
    const at::Tensor latents = model.autoencoder.encode(class_prototypes(*provider, city.taxonomy, level_classes[l]));
    for (size_t k = 0; k < level_classes[l].size(); ++k)
      class_means[level_classes[l][k]] = mean_scores(level_scores(model, latents[static_cast<int64_t>(k)]), objects, gaussian_object, seen);
  }
  std::vector<std::vector<double>> query_means;
  const std::vector<std::string> slugs = unique_slugs(o.queries);
  if (!o.queries.empty()) {
    const at::Tensor latents = model.autoencoder.encode(provider->text_features(o.queries).to(torch::kFloat32));
    for (size_t q = 0; q < o.queries.size(); ++q)
      query_means.push_back(mean_scores(level_scores(model, latents[static_cast<int64_t>(q)]), objects, gaussian_object, seen));
  }

  const std::string frame_crs = read_city_frame(transform.string()).crs;
  const std::string crs = !frame_crs.empty() ? frame_crs : city.mesh.crs;
  const std::string reference_system = cityjson_reference_system(crs);
  if (reference_system.empty()) log_warn("enrich: the CRS '" + crs + "' has no EPSG code PROJ knows: metadata.referenceSystem is left out");
  CityJsonDocument doc = semantic_mesh_cityjson(city.mesh, city.taxonomy, reference_system);

  int64_t enriched_objects = 0, enriched_surfaces = 0;
  for (size_t e = 0; e < objects.objects.size(); ++e) {
    const CityJsonPlace& place = doc.places[e];
    if (place.object.empty() || (!place.is_object && place.surface < 0)) continue;
    const CityObject& object = objects.objects[e];
    const ObjectObservation& s = seen[e];
    // The object's own class and the best class of its level by mean score.
    json class_scores = json::object();
    std::string best;
    double best_score = -2;
    for (const int c : level_classes[object.level - 1]) {
      const double m = class_means[c][e];
      if (!std::isfinite(m)) continue;
      class_scores[city.taxonomy.classes[c].name] = m;
      if (m > best_score) best_score = m, best = city.taxonomy.classes[c].name;
    }
    json& cityobject = doc.document["CityObjects"][place.object];
    if (place.is_object) {
      json a{{"level", object.level},
             {"class", objects.class_name(static_cast<int32_t>(e))},
             {"views", s.views},
             {"pixels", s.pixels},
             {"coveredFraction", s.covered_fraction()},
             {"gaussians", s.gaussians}};
      if (!best.empty()) a["classScores"] = class_scores, a["bestClass"] = best;
      json queries = json::object();
      for (size_t q = 0; q < query_means.size(); ++q)
        if (std::isfinite(query_means[q][e])) queries[o.queries[q]] = query_means[q][e];
      if (!queries.empty()) a["queries"] = queries;
      cityobject["attributes"]["+citylangsplat"] = a;
      ++enriched_objects;
    } else {
      json& surface = cityobject["geometry"][0]["semantics"]["surfaces"][place.surface];
      surface["+clsViews"] = s.views;
      surface["+clsPixels"] = s.pixels;
      surface["+clsCoveredFraction"] = s.covered_fraction();
      surface["+clsGaussians"] = s.gaussians;
      if (!best.empty()) {
        surface["+clsBestClass"] = best;
        surface["+clsBestClassScore"] = best_score;
        if (object.class_id >= 0 && std::isfinite(class_means[object.class_id][e])) surface["+clsClassScore"] = class_means[object.class_id][e];
      }
      for (size_t q = 0; q < query_means.size(); ++q)
        if (std::isfinite(query_means[q][e])) surface["+clsQuery_" + slugs[q]] = query_means[q][e];
      ++enriched_surfaces;
    }
  }
  json queries = json::array();
  for (size_t q = 0; q < o.queries.size(); ++q) queries.push_back({{"text", o.queries[q]}, {"surfaceMember", "+clsQuery_" + slugs[q]}});
  json about{{"run", fs::absolute(root).lexically_normal().string()},
             {"method", o.method},
             {"cityModel", city_path},
             {"views", scene.views.size()},
             {"gaussians", model.gaussians.size()},
             {"queries", queries}};
  if (record.contains("warning") && record["warning"].is_string() && !record["warning"].get<std::string>().empty())
    about["warning"] = record["warning"];
  doc.document["+citylangsplat"] = about;
  doc.document["extensions"] = {{"CityLangSplat", {{"url", kCityJsonExtensionFile}, {"version", "1.0.0"}}}};

  if (out.has_parent_path()) fs::create_directories(out.parent_path());
  write_text_atomic(out.parent_path() / kCityJsonExtensionFile, kCityLangSplatExtensionJson);
  write_text_atomic(out, doc.document.dump());
  return {{"file", out.string()},
          {"objects", enriched_objects},
          {"surfaces", enriched_surfaces},
          {"queries", o.queries},
          {"reference_system", reference_system}};
}

}  // namespace cls
