#include "export/enrich_job.h"

#include <torch/torch.h>

#include <cmath>
#include <filesystem>
#include <map>

#include "citymodel/city_objects.h"
#include "citymodel/scene_city_model.h"
#include "core/atomic_file.h"
#include "core/image_file.h"
#include "core/error.h"
#include "core/log.h"
#include "core/progress.h"
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
#include "raycast/label_map_io.h"
#include "scene/image_loader.h"

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


// Where each proposal is best seen, for the report: the view that looks at it most squarely (its centre in
// the image, at the label map's depth within 5 %), that view's photo at the label maps' size written to
// OUT_DIR/views/<stem>.jpg, and the rectangle's corners in its pixels. null for a proposal no view sees.
std::vector<json> proposal_views(const std::vector<OpeningProposal>& proposals, const SceneCityModel& city, const Scene& scene,
                                 const std::vector<fs::path>& dirs, const fs::path& out_dir) {
  const Vec3d origin{city.mesh.origin[0], city.mesh.origin[1], city.mesh.origin[2]};
  const auto in_scene = [&](const Vec3d& crs_local) { return city.transform.apply(crs_local + origin); };
  std::vector<double> best(proposals.size(), 0.0);
  std::vector<int> view_of(proposals.size(), -1);
  for (size_t k = 0; k < scene.views.size() && !proposals.empty(); ++k) {
    const SceneView& view = scene.views[k];
    const FloatImage depth = read_pfm(dirs[k] / "depth.pfm");
    const PinholeCamera& c = view.camera;
    for (size_t i = 0; i < proposals.size(); ++i) {
      const auto& q = proposals[i].corners;
      const Vec3d centre = in_scene(0.25 * (q[0] + q[1] + q[2] + q[3]));
      const Vec3d normal = normalized(cross(in_scene(q[1]) - in_scene(q[0]), in_scene(q[3]) - in_scene(q[0])));
      const Vec3d p = view.pose.R * centre + view.pose.t;
      if (!(p.z > 0)) continue;
      const double u = c.fx * p.x / p.z + c.cx, v = c.fy * p.y / p.z + c.cy;
      if (!(u >= 0 && u < c.width && v >= 0 && v < c.height) || depth.width != c.width || depth.height != c.height) continue;
      const double d = depth.data[static_cast<size_t>(v) * c.width + static_cast<size_t>(u)];
      if (!(d > 0) || std::abs(d - p.z) > 0.05 * d) continue;
      const double squarely = -dot(normalized(centre - view.pose.center()), normal) / p.z;
      if (squarely > best[i]) best[i] = squarely, view_of[i] = static_cast<int>(k);
    }
  }
  std::vector<json> out(proposals.size());
  ImageLoader loader;
  std::map<int, std::string> written;
  for (size_t i = 0; i < proposals.size(); ++i) {
    if (view_of[i] < 0) continue;
    const SceneView& view = scene.views[view_of[i]];
    std::string& image = written[view_of[i]];
    if (image.empty()) {
      image = "views/" + dirs[view_of[i]].filename().string() + ".jpg";
      write_image(out_dir / image, loader.load(view));
    }
    json polygon = json::array();
    for (const Vec3d& q : proposals[i].corners) {
      const Vec3d p = view.pose.R * in_scene(q) + view.pose.t;
      polygon.push_back({view.camera.fx * p.x / p.z + view.camera.cx, view.camera.fy * p.y / p.z + view.camera.cy});
    }
    out[i] = {{"name", view.name}, {"image", image}, {"width", view.camera.width}, {"height", view.camera.height},
              {"polygon", polygon}};
  }
  return out;
}

// `changes`: every view's rendered level-1 field votes on the surfaces' planes (opening_proposals.h): the best
// class per pixel among the classes of levels 1 and 2 (level 1 carries the part classes where a face has no
// opening: the subpart fallback), the cosine of the decoded feature with each class's prototype. Then the
// proposals as Window/Door surfaces of their building's geometry (on their wall), and the surfaces the
// photos contradict; returns changes.json's content.
json add_changes(CityJsonDocument& doc, const EnrichOptions& o, const LanguageModel& model, const SceneCityModel& city,
                 const CityObjects& objects, const std::vector<ObjectObservation>& seen, const Scene& scene,
                 const fs::path& labels, FeatureProvider& provider, const fs::path& out_dir) {
  const SemanticMesh& mesh = city.mesh;
  const CityTransform crs_from_scene = inverse(city.transform);
  const double metres = crs_from_scene.scale();  // per scene unit
  const Vec3d origin{mesh.origin[0], mesh.origin[1], mesh.origin[2]};
  std::vector<int> classes, openings;
  for (size_t c = 0; c < city.taxonomy.classes.size(); ++c)
    if (city.taxonomy.classes[c].level <= 2) classes.push_back(static_cast<int>(c));
  for (const char* name : {"window", "door"})
    if (city.taxonomy.find(name) >= 0) openings.push_back(city.taxonomy.find(name));
  const at::Tensor prototypes = class_prototypes(provider, city.taxonomy, classes);
  OpeningVotes votes(objects, mesh, openings, o.proposals);
  const std::vector<fs::path> dirs = label_map_dirs(scene, labels);
  Progress progress("changes: votes", scene.views.size(), "views");
  for (size_t k = 0; k < scene.views.size(); ++k) {
    const SceneView& view = scene.views[k];
    const int W = view.camera.width, H = view.camera.height;
    const auto [object, depth] = read_view_hits(dirs[k], W, H);
    const DecodedView decoded = render_decoded(model, 1, view);
    const at::Tensor best = cosine_maps(decoded.features, prototypes).argmax(0).to(torch::kInt32).contiguous();  // H x W
    const int32_t* b = best.data_ptr<int32_t>();
    const Mat3d Rt = transpose(view.pose.R);
    const PinholeCamera& c = view.camera;
    for (int v = 0; v < H; ++v)
      for (int u = 0; u < W; ++u) {
        const size_t p = static_cast<size_t>(v) * W + u;
        const double d = depth.data[p];
        if (!(d > 0) || !votes.has_plane(object[p])) continue;
        const Vec3d camera{(u + 0.5 - c.cx) / c.fx * d, (v + 0.5 - c.cy) / c.fy * d, d};
        votes.add(object[p], crs_from_scene.apply(Rt * (camera - view.pose.t)) - origin, classes[b[p]]);
      }
    progress.advance();
  }
  progress.finish();
  const std::vector<OpeningProposal> proposals = votes.proposals();
  const std::vector<json> pictures = proposal_views(proposals, city, scene, dirs, out_dir);

  json& vertices = doc.document["vertices"];
  json listed = json::array();
  for (size_t k = 0; k < proposals.size(); ++k) {
    const OpeningProposal& p = proposals[k];
    const CityJsonPlace& wall = doc.places[p.surface];
    const std::string name = city.taxonomy.classes[p.class_id].name;
    const std::string id = cat("proposal-", k + 1);
    json corners = json::array();
    for (const Vec3d& c : p.corners) corners.push_back({c.x + origin.x, c.y + origin.y, c.z + origin.z});
    int32_t building = p.surface;
    while (objects.objects[building].parent >= 0) building = objects.objects[building].parent;
    listed.push_back({{"id", id},
                      {"class", name},
                      {"surface", objects.objects[p.surface].id},
                      {"surfaceClass", objects.class_name(p.surface)},
                      {"building", objects.objects[building].id},
                      {"corners", corners},
                      {"width", p.width},
                      {"height", p.height},
                      {"cells", p.cells},
                      {"votes", p.votes},
                      {"confidence", p.confidence},
                      {"view", pictures[k]}});
    if (wall.object.empty()) continue;  // a face of no CityObject: listed, not drawn
    json& geometry = doc.document["CityObjects"][wall.object]["geometry"][0];
    json ring = json::array();
    for (const Vec3d& c : p.corners) {
      ring.push_back(vertices.size());
      vertices.push_back({std::llround(c.x * 1000.0), std::llround(c.y * 1000.0), std::llround(c.z * 1000.0)});
    }
    json& semantics = geometry["semantics"];
    if (!semantics.contains("surfaces")) semantics = {{"surfaces", json::array()}, {"values", json::array()}};
    const size_t index = semantics["surfaces"].size();
    json surface{{"type", name == "door" ? "Door" : "Window"},
                 {"+clsProposed", true},
                 {"+clsProposal", id},
                 {"+clsConfidence", p.confidence},
                 {"+clsVotes", p.votes}};
    if (wall.surface >= 0) {
      surface["parent"] = wall.surface;
      semantics["surfaces"][wall.surface]["children"].push_back(index);
    }
    semantics["surfaces"].push_back(surface);
    geometry["boundaries"].push_back(json::array({ring}));
    semantics["values"].push_back(index);
  }

  // Surfaces the cameras see well but the photos put (almost) no Gaussians on.
  std::vector<double> densities;
  const double m2 = metres * metres;
  for (size_t e = 0; e < objects.objects.size(); ++e)
    if (objects.objects[e].level == 2 && seen[e].seen_area * m2 >= o.contradiction_seen_area)
      densities.push_back(seen[e].gaussians / (seen[e].seen_area * m2));
  std::sort(densities.begin(), densities.end());
  const double median = densities.empty() ? 0.0 : densities[densities.size() / 2];
  json contradicted = json::array();
  for (size_t e = 0; e < objects.objects.size(); ++e) {
    const ObjectObservation& s = seen[e];
    if (objects.objects[e].level != 2 || s.seen_area * m2 < o.contradiction_seen_area) continue;
    const double density = s.gaussians / (s.seen_area * m2);
    if (density >= o.contradiction_density * median) continue;
    contradicted.push_back({{"id", objects.objects[e].id},
                            {"class", objects.class_name(static_cast<int32_t>(e))},
                            {"seenArea", s.seen_area * m2},
                            {"coveredFraction", s.covered_fraction()},
                            {"gaussians", s.gaussians},
                            {"gaussiansPerM2", density},
                            {"medianGaussiansPerM2", median}});
    const CityJsonPlace& place = doc.places[e];
    if (place.surface >= 0)
      doc.document["CityObjects"][place.object]["geometry"][0]["semantics"]["surfaces"][place.surface]["+clsContradicted"] = true;
  }
  const ProposalSettings& ps = o.proposals;
  return {{"proposals", listed},
          {"contradicted", contradicted},
          {"crs", mesh.crs},
          {"settings",
           {{"cell", ps.cell}, {"min_votes", ps.min_votes}, {"opening_share", ps.opening_share}, {"min_area", ps.min_area},
            {"plane_distance", ps.plane_distance}, {"existing_margin", ps.existing_margin},
            {"contradiction_density", o.contradiction_density}, {"contradiction_seen_area", o.contradiction_seen_area}}}};
}

}  // namespace

json run_enrich(const EnrichOptions& o) {
  const fs::path root = o.run;
  const RunLayout run(root);
  if (!fs::exists(run.run_json())) throw UsageError("enrich: " + root.string() + " is no `run` output (no run.json there)");
  const fs::path out = !o.out.empty() ? fs::path(o.out) : o.changes ? run.changes() / "enriched.city.json" : root / "enriched.city.json";
  const bool sequence = out.extension() == ".jsonl";
  if (out.extension() != ".json" && !sequence)
    throw UsageError("enrich: --out " + out.string() + " does not end in .json (CityJSON) or .jsonl (CityJSONSeq)");
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
    const std::vector<LevelScores> scores = text_level_scores(model, class_prototypes(*provider, city.taxonomy, level_classes[l]));
    for (size_t k = 0; k < level_classes[l].size(); ++k)
      class_means[level_classes[l][k]] = mean_scores(scores[k].scores, objects, gaussian_object, seen);
  }
  std::vector<std::vector<double>> query_means;
  const std::vector<std::string> slugs = unique_slugs(o.queries);
  if (!o.queries.empty()) {
    const std::vector<LevelScores> scores = text_level_scores(model, provider->text_features(o.queries));
    for (size_t q = 0; q < o.queries.size(); ++q) query_means.push_back(mean_scores(scores[q].scores, objects, gaussian_object, seen));
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
  json changes;
  if (o.changes) changes = add_changes(doc, o, model, city, objects, seen, scene, labels, *provider, out.parent_path());
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
  if (sequence) {
    std::string text;
    for (const json& line : cityjson_sequence(doc.document)) text += line.dump() + "\n";
    write_text_atomic(out, text);
  } else {
    write_text_atomic(out, doc.document.dump());
  }
  if (o.changes) write_text_atomic(out.parent_path() / "changes.json", changes.dump(1));
  return {{"file", out.string()},
          {"proposals", o.changes ? changes["proposals"].size() : 0},
          {"contradicted", o.changes ? changes["contradicted"].size() : 0},
          {"objects", enriched_objects},
          {"surfaces", enriched_surfaces},
          {"queries", o.queries},
          {"reference_system", reference_system}};
}

}  // namespace cls
