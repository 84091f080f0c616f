#include "export/export_job.h"

#include <torch/torch.h>

#include <cmath>
#include <filesystem>
#include <optional>

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/log.h"
#include "core/progress.h"
#include "core/run_layout.h"
#include "export/splat_gltf.h"
#include "export/splat_tiles.h"
#include "export/tileset.h"
#include "georef/crs_name.h"
#include "georef/proj_crs.h"
#include "language/language_model.h"
#include "language/provenance.h"
#include "query/selection.h"
#include "query/text_queries.h"
#include "raycast/label_export.h"
#include "splat/ply_gaussians.h"

namespace cls {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// What the input holds: the Gaussians, and with a language model its objects, latents and text side.
struct ExportInput {
  GaussianModel gaussians;
  std::optional<LanguageModel> model;
  fs::path model_dir;   // the language model's directory, or "" for a PLY
  fs::path labels_dir;  // where the label maps (and the city transform they used) lie, or ""
  fs::path default_out;
};

ExportInput read_input(const ExportOptions& o) {
  ExportInput in;
  const fs::path input = o.input;
  if (!fs::exists(input)) throw UsageError("export: " + input.string() + " does not exist");
  if (fs::is_regular_file(input)) {
    if (input.extension() != ".ply") throw UsageError("export: " + input.string() + " is no .ply, run output or model directory");
    in.gaussians = read_gaussians_ply(input.string());
    in.default_out = input.parent_path() / (input.stem().string() + "." + o.format);
    return in;
  }
  const RunLayout run(input);
  if (!fs::exists(LanguageModelFiles{input}.model_json()) && !fs::exists(LanguageModelFiles{run.language(o.method)}.model_json()) &&
      fs::exists(run.rgb_ply())) {
    // A run that stopped before its language fields: the photometric model, in the frame of its labels.
    log_warn("export: " + input.string() + " has no language model yet: the photometric model " + run.rgb_ply().string() +
             " goes out without city objects");
    in.gaussians = read_gaussians_ply(run.rgb_ply().string());
    in.labels_dir = run.labels();
    in.default_out = run.rgb() / ("gaussians." + o.format);
    return in;
  }
  in.model_dir = language_model_dir(input, o.method, "export");
  in.model = load_language_model(in.model_dir.string());
  in.gaussians = in.model->gaussians;
  in.labels_dir = recorded_labels_dir(in.model->info);
  in.default_out = in.model_dir / ("gaussians." + o.format);
  return in;
}

std::vector<SplatScores> query_scores(LanguageModel& model, const fs::path& model_dir, const ExportOptions& o) {
  at::NoGradGuard no_grad;
  const int fixed = parse_query_level(o.level, "--level");
  const std::string model_json = LanguageModelFiles{model_dir}.model_json().string();
  const auto provider = model_provider(model, model_json, model_taxonomy(model.info, model_json, ""));
  const std::vector<LevelScores> scores = text_level_scores(model, provider->text_features(o.queries));
  const std::vector<std::string> slugs = unique_slugs(o.queries);
  std::vector<SplatScores> out;
  for (size_t k = 0; k < o.queries.size(); ++k) {
    const LevelScores& levels = scores[k];
    SplatScores s;
    s.id = "score_" + slugs[k];
    s.text = o.queries[k];
    s.level = fixed ? fixed : levels.best;
    const at::Tensor v = levels.scores[s.level - 1].to(torch::kFloat32).contiguous();
    s.values.assign(v.data_ptr<float>(), v.data_ptr<float>() + v.numel());
    log_info(cat("export: '", s.text, "' on level ", s.level, " (highest score ", levels.max[s.level - 1], ")"));
    out.push_back(std::move(s));
  }
  return out;
}

// Every tile's Gaussians as its own glTF (the semantics' object table whole in each), written into a
// fresh OUT/tiles that replaces the old one only when all are written, then tileset.json with the glTF
// extensions they use.
void write_splat_tiles(const fs::path& out, json tileset, const SplatTileTree& tree, const GaussianModel& gaussians,
                       const SplatSemantics* semantics, const std::vector<SplatScores>& scores,
                       const SplatGltfOptions& options) {
  const fs::path dir = out / "tiles", fresh = out / "tiles.partial";
  fs::remove_all(fresh);
  fs::create_directories(fresh);
  Progress progress("export", tree.tiles.size(), "tiles");
  for (const SplatTile& tile : tree.tiles) {
    const at::Tensor index = torch::tensor(tile.splats, torch::kInt64);
    SplatSemantics tile_semantics;
    if (semantics) {
      tile_semantics.objects = semantics->objects;
      for (const int64_t i : tile.splats) tile_semantics.object_of.push_back(semantics->object_of[i]);
    }
    std::vector<SplatScores> tile_scores;
    for (const SplatScores& s : scores) {
      tile_scores.push_back({s.id, s.text, s.level, {}});
      for (const int64_t i : tile.splats) tile_scores.back().values.push_back(s.values[i]);
    }
    const GltfBuilder gltf = splat_gltf(subset_gaussians(gaussians, index), semantics ? &tile_semantics : nullptr, tile_scores, options);
    declare_gltf_extensions(tileset, gltf.json());
    gltf.write(fresh / fs::path(splat_tile_uri(tile)).filename());
    progress.advance();
  }
  fs::remove_all(dir);
  fs::rename(fresh, dir);
  write_text_atomic(out / "tileset.json", tileset.dump(1));
}

}  // namespace

std::array<double, 16> gltf_city_matrix(const CityTransform& scene_from_crs, const Vec3d& origin) {
  CityTransform crs_from_scene = inverse(scene_from_crs);
  for (int r = 0; r < 3; ++r) crs_from_scene.matrix[r][3] -= origin[r];
  // (E, N, U) -> glTF (E, U, -N).
  const int axis[3] = {0, 2, 1};
  const double sign[3] = {1, 1, -1};
  std::array<double, 16> m{};
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 3; ++r) m[4 * c + r] = sign[r] * crs_from_scene.matrix[axis[r]][c];
  m[15] = 1;
  return m;
}

json run_export(const ExportOptions& o) {
  if (o.format != "glb" && o.format != "gltf" && o.format != "3dtiles")
    throw UsageError("export: --format must be glb, gltf or 3dtiles, got '" + o.format + "'");
  if (!o.compress.empty() && o.compress != "none" && o.compress != "spz")
    throw UsageError("export: --compress must be none or spz, got '" + o.compress + "'");
  if (!o.spz_axes.empty() && o.spz_axes != "luf" && o.spz_axes != "cesium")
    throw UsageError("export: --spz-axes must be luf or cesium, got '" + o.spz_axes + "'");
  if (o.tile_splats < 1) throw UsageError(cat("export: --tile-splats must be at least 1, got ", o.tile_splats));
  const bool tiles = o.format == "3dtiles";
  if (tiles && !o.georeference) throw UsageError("export: a 3D Tiles tileset lies on the globe: --scene-frame does not go with it");
  const std::string compress = !o.compress.empty() ? o.compress : tiles ? "spz" : "none";
  ExportInput in = read_input(o);
  if (!o.queries.empty() && !in.model)
    throw UsageError("export: text queries need a language model (a run output or a model directory), not a PLY");
  fs::path out = o.out.empty() ? in.default_out : fs::path(o.out);
  if (tiles && o.out.empty()) out = in.default_out.replace_extension("").string() + "_3dtiles";
  if (!tiles && out.extension() != "." + o.format)
    throw UsageError("export: --out " + out.string() + " does not end in ." + o.format + " (--format " + o.format + ")");

  SplatGltfOptions options;
  options.compression = compress == "spz" ? SplatCompression::Spz : SplatCompression::None;
  const std::string spz_axes = !o.spz_axes.empty() ? o.spz_axes : tiles ? "cesium" : "luf";
  options.spz_axes = spz_axes == "luf" ? SpzAxes::Luf : SpzAxes::AsStored;
  // With the city transform: the Gaussians' centres in the city model's CRS, once, for the origin and
  // the tileset's box.
  std::optional<CityFrame> city_frame;
  std::vector<Vec3d> in_crs;
  Vec3d origin{0, 0, 0};
  json frame{{"frame", "scene"}, {"description", "the frame the model was trained in (no city transform recorded)"}};
  const fs::path transform_file = in.labels_dir.empty() ? fs::path() : in.labels_dir / kLabelsCityTransform;
  if (o.georeference && !transform_file.empty() && fs::exists(transform_file)) {
    const CityFrame& city = city_frame.emplace(read_city_frame(transform_file.string()));
    const CityTransform crs_from_scene = inverse(city.transform);
    const at::Tensor means = in.gaussians.means.to(torch::kFloat64).contiguous();
    const double* p = means.data_ptr<double>();
    Vec3d sum{0, 0, 0};
    for (int64_t i = 0; i < in.gaussians.size(); ++i) {
      in_crs.push_back(crs_from_scene.apply({p[3 * i], p[3 * i + 1], p[3 * i + 2]}));
      sum = sum + in_crs.back();
    }
    for (int a = 0; a < 3; ++a) origin[a] = std::round(sum[a] / std::max<int64_t>(1, in.gaussians.size()));
    options.node_matrix = gltf_city_matrix(city.transform, origin);
    frame = {{"frame", "city"},
             {"crs", city.crs},
             {"origin", {origin[0], origin[1], origin[2]}},
             {"transform", transform_file.string()},
             {"description", "the city model's CRS minus origin, y up: glTF (x, y, z) = (E, U, -N)"}};
  } else if (o.georeference) {
    const std::string why = "no city transform recorded with the model (" +
                            (transform_file.empty() ? std::string("no label maps") : transform_file.string() + " is missing") + ")";
    if (tiles) throw Error("export: a 3D Tiles tileset needs the city model's CRS and transform: " + why +
                           "; export a run whose `raycast` stage wrote it (this version's), or glb in the scene's frame");
    log_warn("export: " + why + ": the splats stay in the frame they were trained in");
  }
  options.extras = {{"citylangsplat", frame}};
  if (options.compression == SplatCompression::Spz)  // which axes a reader must unpack the payload to
    options.extras["citylangsplat"]["spzAxes"] = spz_axes == "luf" ? "LUF, as the extension says" : "as stored, as CesiumJS reads them";

  // The tileset's frame and tiles before anything is computed or written: PROJ must know the CRS and
  // place the origin.
  json tileset;
  SplatTileTree tile_tree;
  if (tiles) {
    const std::optional<CrsName> crs = parse_crs_name(city_frame->crs);
    if (!crs) throw Error("export: a 3D Tiles tileset needs the city model's CRS in a form PROJ reads; " + transform_file.string() +
                          " names '" + city_frame->crs + "'");
    const CrsToGeocentric to_ecef(cat("EPSG:", crs->horizontal_epsg));
    if (!to_ecef.geoid_available())
      log_warn("export: EGM96's grid is not installed (proj-data): the city model's heights go on the globe as ellipsoidal, tens of metres low");
    const double scale = inverse(city_frame->transform).scale();
    const at::Tensor sigma = std::get<0>(in.gaussians.scales().to(torch::kFloat64).sort(1)).contiguous();  // ascending
    const at::Tensor opacity = in.gaussians.opacities().to(torch::kFloat64).contiguous();
    std::vector<Vec3d> local(in_crs.size());
    std::vector<double> radii(in_crs.size()), importance(in_crs.size());
    for (size_t i = 0; i < in_crs.size(); ++i) {
      const double* s = sigma.data_ptr<double>() + 3 * i;
      local[i] = in_crs[i] - origin;
      radii[i] = 3 * scale * s[2];
      importance[i] = opacity.data_ptr<double>()[i] * s[1] * s[2];  // opacity x footprint, what a distant eye sees
    }
    tile_tree = build_splat_tiles(local, radii, importance, o.tile_splats);
    tileset = tileset_json(ecef_tile_transform(to_ecef, origin), tile_tree, {{"citylangsplat", frame}});
  }

  SplatSemantics semantics;
  const GaussianExtra* object = in.gaussians.extra(kObjectProperty);
  const bool with_semantics = in.model && !in.model->objects.objects.empty() && object;
  if (with_semantics) {
    semantics.objects = &in.model->objects;
    const at::Tensor ids = object->values.to(torch::kInt32).contiguous();
    semantics.object_of.assign(ids.data_ptr<int32_t>(), ids.data_ptr<int32_t>() + ids.numel());
  } else if (in.model) {
    log_warn("export: the model has no city object per Gaussian: the splats go out without feature IDs");
  }
  const std::vector<SplatScores> scores = o.queries.empty() ? std::vector<SplatScores>{} : query_scores(*in.model, in.model_dir, o);

  if (tiles) {
    write_splat_tiles(out, tileset, tile_tree, in.gaussians, with_semantics ? &semantics : nullptr, scores, options);
  } else {
    if (out.has_parent_path()) fs::create_directories(out.parent_path());
    splat_gltf(in.gaussians, with_semantics ? &semantics : nullptr, scores, options).write(out);
  }
  json queries = json::array();
  for (const SplatScores& s : scores) queries.push_back({{"text", s.text}, {"level", s.level}, {"property", s.id}});
  return {{"file", tiles ? (out / "tileset.json").string() : out.string()},
          {"format", o.format},
          {"compress", compress},
          {"spz_axes", compress == "spz" ? json(spz_axes) : json(nullptr)},
          {"gaussians", in.gaussians.size()},
          {"sh_degree", in.gaussians.sh_degree()},
          {"tiles", tiles ? json(tile_tree.tiles.size()) : json(nullptr)},
          {"semantics", with_semantics ? json(in.model->objects.objects.size()) : json(nullptr)},
          {"queries", queries},
          {"frame", frame}};
}

}  // namespace cls
