#include "render/render_job.h"

#include <ATen/core/grad_mode.h>
#include <torch/types.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <set>

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/run_layout.h"
#include "core/strings.h"
#include "core/image_file.h"
#include "core/log.h"
#include "core/npy.h"
#include "core/progress.h"
#include "eval/gt_projection.h"
#include "eval/labelled_points.h"
#include "query/query_job.h"
#include "query/relevance.h"
#include "query/relevance_image.h"
#include "query/selection.h"
#include "query/text_queries.h"
#include "raycast/label_export.h"
#include "raycast/label_map_io.h"
#include "render/camera_path.h"
#include "render/feature_pca.h"
#include "render/render_model.h"
#include "render/video_file.h"
#include "render/view_images.h"
#include "scene/image_loader.h"
#include "scene/view_selection.h"
#include "splat/image_tensor.h"
#include "splat/rasterize.h"
#include "splat/ssim.h"

namespace cls {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

struct Wanted {
  bool rgb = false, depth = false, features = false, labels = false;
  std::vector<std::string> texts;
};

bool is_relevance(const std::string& item) { return item.rfind("relevance:", 0) == 0; }

}  // namespace

std::vector<std::string> split_what(const std::string& what) {
  std::vector<std::string> out;
  for (const std::string& item : split_commas(what)) {
    const bool known = item == "rgb" || item == "depth" || item == "features" || item == "labels" || is_relevance(item);
    if (!known && !out.empty() && is_relevance(out.back())) out.back() += "," + item;
    else out.push_back(item);
  }
  return out;
}

namespace {

// What to draw: the items asked for, or (none asked) everything the inputs allow but text queries.
Wanted parse_what(const std::vector<std::string>& what, bool language, bool labels_available) {
  Wanted w;
  if (what.empty()) {
    w.rgb = w.depth = true;
    w.features = language;
    w.labels = labels_available;
    return w;
  }
  for (const std::string& item : what) {
    if (item == "rgb") w.rgb = true;
    else if (item == "depth") w.depth = true;
    else if (item == "features") w.features = true;
    else if (item == "labels") w.labels = true;
    else if (is_relevance(item) && item.size() > 10) w.texts.push_back(item.substr(10));
    else throw UsageError("render: unknown --what item '" + item + "' (rgb, depth, features, relevance:TEXT, labels)");
  }
  if (!language && (w.features || !w.texts.empty()))
    throw UsageError("render: features and relevance need a language model (a train-language output directory)");
  return w;
}

// The views to draw with their split, in the order asked.
std::vector<std::pair<const SceneView*, const char*>> pick_views(const Scene& scene, const RenderOptions& o) {
  const ViewSplit split = split_views(scene, o.test_every);
  const std::set<const SceneView*> test(split.test.begin(), split.test.end());
  std::vector<const SceneView*> views;
  if (o.views == "test") {
    if (split.test.empty())
      throw UsageError("render: no test views (--test-every " + std::to_string(o.test_every) +
                       " holds none out of " + std::to_string(scene.views.size()) + "); use --views all");
    views = split.test;
  } else if (o.views == "all") {
    views = split.test;
    views.insert(views.end(), split.train.begin(), split.train.end());
    std::sort(views.begin(), views.end(), [](const SceneView* a, const SceneView* b) { return a->name < b->name; });
  } else {
    views = find_views(scene, split_commas(o.views), "render");
    if (views.empty()) throw UsageError("render: --views needs test, all or image names");
  }
  std::vector<std::pair<const SceneView*, const char*>> out;
  for (const SceneView* v : views) out.emplace_back(v, test.count(v) ? "test" : "train");
  return out;
}

RasterizeOutput render_rgb(const GaussianModel& g, const PinholeCamera& camera, const Pose& pose,
                           const at::Tensor& background) {
  RasterizeSettings s;
  s.camera = camera;
  s.pose = pose;
  s.background = background;
  return rasterize_sh(g.means, g.scales(), g.quats, g.opacities(), g.sh(), g.sh_degree(), {}, s);
}

void write_npy_map(const fs::path& path, const at::Tensor& map) {
  const at::Tensor m = map.to(torch::kCPU, torch::kFloat32).contiguous();
  write_npy(path, make_npy<float>({m.size(0), m.size(1)},
                                  std::vector<float>(m.data_ptr<float>(), m.data_ptr<float>() + m.numel())));
}

std::vector<int32_t> to_ids(const cv::Mat& m, int offset) {
  std::vector<int32_t> ids;
  ids.reserve(m.total());
  for (int y = 0; y < m.rows; ++y)
    for (int x = 0; x < m.cols; ++x)
      ids.push_back(m.type() == CV_16UC1 ? int32_t(m.at<uint16_t>(y, x)) - offset : m.at<int32_t>(y, x) - offset);
  return ids;
}

// The text side of the relevance maps.
struct Queries {
  std::vector<std::string> texts, slugs;
  std::vector<int> level;    // per text, 1..3 (LangSplat's "best": highest max Gaussian score)
  at::Tensor features;       // K x D
  at::Tensor canonical;      // M x D
};

Queries prepare_queries(const LanguageModel& model, const std::string& model_dir, const std::vector<std::string>& texts,
                        const std::string& taxonomy_path) {
  Queries q;
  q.texts = texts;
  q.slugs = unique_slugs(texts);
  const std::string model_json = LanguageModelFiles{model_dir}.model_json().string();
  const auto provider = model_provider(model, model_json, model_taxonomy(model.info, model_json, taxonomy_path));
  q.features = provider->text_features(texts).to(torch::kFloat32);
  q.canonical = provider->text_features(canonical_phrases()).to(torch::kFloat32);
  for (const LevelScores& s : text_level_scores(model, q.features)) q.level.push_back(s.best);
  return q;
}

// The label sources that exist, and the taxonomy that colours them.
struct LabelSources {
  std::vector<fs::path> map_dirs;  // per scene view, or empty
  std::optional<LabelledPoints> gt;
  std::string gt_path;
  double gt_radius = 0;
  std::vector<std::array<unsigned char, 3>> colours;
};

LabelSources find_label_sources(const RenderOptions& o, const Scene& scene, const RenderModel& model) {
  LabelSources s;
  Taxonomy taxonomy = Taxonomy::builtin();
  if (!o.labels_dir.empty()) {
    if (!fs::is_directory(o.labels_dir)) fail(o.labels_dir, "no such label map directory (the `raycast` output)");
    s.map_dirs = label_map_dirs(scene, o.labels_dir);
    const fs::path legend = fs::path(o.labels_dir) / "legend.json";
    if (o.taxonomy_path.empty() && fs::exists(legend)) taxonomy = Taxonomy::from_legend(read_text_file(legend), legend.string());
  }
  if (!o.taxonomy_path.empty()) taxonomy = Taxonomy::load(o.taxonomy_path);
  else if (s.map_dirs.empty() && model.language)
    taxonomy = model_taxonomy(model.language->info, LanguageModelFiles{o.model}.model_json().string(), "");
  if (!o.labels_dir.empty()) check_label_legend(o.labels_dir, taxonomy);
  for (const SemanticClass& c : taxonomy.classes) s.colours.push_back(c.color);

  s.gt_path = o.gt_points.empty() ? SceneFiles{scene.root}.gt_points().string() : o.gt_points;
  if (!o.gt_points.empty() && !fs::exists(o.gt_points)) fail(o.gt_points, "no such labelled point cloud");
  if (fs::exists(s.gt_path)) {
    s.gt = read_labelled_points(s.gt_path);
    for (int32_t l : s.gt->labels)
      if (l >= int32_t(s.colours.size()))
        fail(s.gt_path, "class id " + std::to_string(l) + " is outside the taxonomy's " +
                            std::to_string(s.colours.size()) + " classes (pass --taxonomy)");
    s.gt_radius = footprint_radius(*s.gt, GtProjectionOptions{});
  }
  return s;
}

// The orbit's or the interpolation's poses, through the scene's views sorted by name.
std::vector<Pose> path_poses(const RenderOptions& o, const Scene& scene, const GaussianModel& g) {
  const ViewSplit all = split_views(scene, 0);
  std::vector<Pose> poses;
  for (const SceneView* v : all.train) poses.push_back(v->pose);
  if (o.path == "interpolate") return interpolate_path(poses, o.frames);
  const at::Tensor median = std::get<0>(g.means.to(torch::kFloat64).median(0));
  const Vec3d target{median[0].item<double>(), median[1].item<double>(), median[2].item<double>()};
  return orbit_path(orbit_circle(poses, target), o.frames);
}

std::string frame_name(int k) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "frame_%04d.png", k);
  return buf;
}

void check_options(const RenderOptions& o) {
  if (o.model.empty()) throw UsageError("render: no model given");
  if (o.out_dir.empty()) throw UsageError("render: --out is required");
  if (!o.path.empty() && o.path != "orbit" && o.path != "interpolate")
    throw UsageError("render: --path must be orbit or interpolate, got '" + o.path + "'");
  if (o.frames < 2) throw UsageError("render: --frames must be at least 2");
  if (!(o.fps > 0)) throw UsageError("render: --fps must be positive");
  if (o.test_every < 0) throw UsageError("render: --test-every must not be negative");
}

}  // namespace

json render_views(const RenderOptions& o) {
  check_options(o);
  at::NoGradGuard no_grad;
  const RenderModel model = load_render_model(o.model);
  const std::string scene_dir = o.scene_dir.empty() ? model.recorded_scene : o.scene_dir;
  if (scene_dir.empty()) throw UsageError("render: the model records no scene; pass --scene DIR");
  SceneOptions scene_options;
  scene_options.resolution_factor = o.resolution;
  scene_options.check_images = false;  // a missing photo only drops that view's comparison
  return render_views(model, load_scene(scene_dir, scene_options), o);
}

json render_views(const RenderModel& model, const Scene& scene, const RenderOptions& o) {
  check_options(o);
  at::NoGradGuard no_grad;
  const std::string& scene_dir = scene.root;
  const auto views = pick_views(scene, o);

  const bool gt_exists = !o.gt_points.empty() || fs::exists(SceneFiles{scene_dir}.gt_points());
  const Wanted want = parse_what(o.what, model.language.has_value(), !o.labels_dir.empty() || gt_exists);
  LabelSources labels;
  json notes = json::array();
  auto note = [&](const std::string& s) {
    log_info("render: " + s);
    notes.push_back(s);
  };
  if (want.labels) {
    labels = find_label_sources(o, scene, model);
    if (labels.map_dirs.empty() && !labels.gt) {
      throw UsageError("render: labels need label maps (--labels DIR, the raycast output) or a labelled point cloud (" +
                       labels.gt_path + " does not exist)");
    }
    if (labels.map_dirs.empty()) note("no label maps (--labels DIR): only the ground truth is drawn");
    if (!labels.gt) note("no ground truth (" + labels.gt_path + "): only the label maps are drawn");
  }
  std::optional<Queries> queries;
  if (!want.texts.empty()) queries = prepare_queries(*model.language, o.model, want.texts, o.taxonomy_path);

  const fs::path out(o.out_dir);
  fs::create_directories(out);
  const at::Tensor background = torch::full({3}, o.white_background ? 1.0f : 0.0f);
  const GaussianModel& g = model.gaussians;
  std::array<std::optional<FeaturePca>, 3> pca;  // fitted on the first view, so colours agree across views
  ImageLoader loader;
  json views_json = json::array();
  double psnr_sum = 0, ssim_sum = 0;
  int compared = 0;
  {
    Progress progress("render views", views.size(), "views");
    for (const auto& [view, split] : views) {
      const std::string stem = view_stem(view->name);
      const fs::path dir = out / "views" / stem;
      const std::string rel = "views/" + stem + "/";
      json files = json::object();
      json record{{"name", view->name}, {"split", split}, {"width", view->camera.width}, {"height", view->camera.height}};
      if (want.rgb || want.depth) {
        const RasterizeOutput r = render_rgb(g, view->camera, view->pose, background);
        const at::Tensor rgb = r.image.clamp(0, 1);
        if (want.rgb) {
          const cv::Mat render_bgr = tensor_to_image(rgb);
          write_image(dir / "rgb.png", render_bgr);
          files["rgb"] = rel + "rgb.png";
          if (fs::is_regular_file(view->image_path)) {
            const cv::Mat photo = loader.load(*view);
            write_image(dir / "photo.png", photo);
            write_image(dir / "compare.png", side_by_side({photo, render_bgr}));
            files["photo"] = rel + "photo.png";
            files["compare"] = rel + "compare.png";
            const at::Tensor photo_t = image_to_tensor(photo);
            record["psnr"] = psnr(rgb, photo_t);
            record["ssim"] = ssim(rgb, photo_t).item<double>();
            psnr_sum += record["psnr"].get<double>();
            ssim_sum += record["ssim"].get<double>();
            ++compared;
          } else {
            note("no photo for " + view->name + " (" + view->image_path + "): no PSNR / SSIM");
          }
        }
        if (want.depth) {
          const at::Tensor depth = expected_depth(r.depth, r.alpha);
          const at::Tensor covered = r.alpha.to(torch::kCPU) >= kCoveredAlpha;
          const MapRange range = depth_range(depth, covered);
          write_image(dir / "depth.png", colour_depth(depth, covered, range));
          write_npy_map(dir / "depth.npy", depth);
          files["depth"] = rel + "depth.png";
          record["depth_range"] = {range.lo, range.hi};
        }
      }
      if (want.features) {
        for (int l = 1; l <= 3; ++l) {
          const RenderedLatents r = model.language->is_sparse()  // a sparse field's PCA runs on its rendered weights
                                        ? render_sparse(g, model.language->sparse[l - 1], view->camera, view->pose)
                                        : render_latents(g, model.language->latents[l - 1], view->camera, view->pose);
          if (!pca[l - 1]) pca[l - 1] = fit_feature_pca(r.latents, r.alpha >= kCoveredAlpha);
          const std::string name = "features_level" + std::to_string(l);
          write_image(dir / (name + ".png"), tensor_to_image(apply_feature_pca(*pca[l - 1], r.latents)));
          files[name] = rel + name + ".png";
        }
      }
      if (queries) {
        std::map<int, std::vector<int64_t>> texts_of_level;
        for (size_t k = 0; k < queries->texts.size(); ++k) texts_of_level[queries->level[k]].push_back(int64_t(k));
        for (const auto& [level, ks] : texts_of_level) {
          const RelevanceMaps m = relevance_maps(*model.language, level, *view,
                                                 queries->features.index_select(0, torch::tensor(ks)), queries->canonical);
          for (size_t j = 0; j < ks.size(); ++j) {
            const std::string name = "relevance_" + queries->slugs[size_t(ks[j])];
            write_image(dir / (name + ".png"), colour_map(m.relevancy[int64_t(j)], MapRange{kRelevancyRange[0], kRelevancyRange[1]}));
            write_npy_map(dir / (name + ".npy"), m.relevancy[int64_t(j)]);
            files[name] = rel + name + ".png";
          }
        }
      }
      if (want.labels) {
        const int H = view->camera.height, W = view->camera.width;
        if (!labels.map_dirs.empty()) {
          const fs::path maps = labels.map_dirs[size_t(view - scene.views.data())];
          for (int l = 1; l <= 3; ++l) {
            const std::string level = "level" + std::to_string(l);
            const fs::path file = maps / (level + ".png");
            const cv::Mat ids = read_label_png(file, CV_16UC1, H, W);
            double max_label = 0;
            cv::minMaxLoc(ids, nullptr, &max_label);
            if (max_label > double(labels.colours.size()))
              fail(file.string(), cat("label ", max_label, " is not in the legend's ", labels.colours.size(),
                                      " classes (label maps of another taxonomy?)"));
            const std::string name = l == 1 ? "labels" : "labels_" + level;
            write_image(dir / (name + ".png"), colourise(to_ids(ids, 1), H, W, labels.colours, cv::Vec3b(0, 0, 0)));
            files[name] = rel + name + ".png";
          }
        }
        if (labels.gt) {
          const cv::Mat ids = project_gt_labels(*labels.gt, view->camera, view->pose, labels.gt_radius, GtProjectionOptions{});
          write_image(dir / "labels_gt.png", colourise(to_ids(ids, 0), H, W, labels.colours, cv::Vec3b(0, 0, 0)));
          files["labels_gt"] = rel + "labels_gt.png";
        }
      }
      record["files"] = files;
      views_json.push_back(record);
      progress.advance();
    }
  }

  json result{{"model", fs::absolute(o.model).string()},
              {"model_kind", model.kind},
              {"ply", fs::absolute(model.ply).string()},
              {"scene", fs::absolute(scene_dir).string()},
              {"what", json::array()},
              {"views", views_json},
              {"background", o.white_background ? "white" : "black"},
              {"depth_colormap", "turbo (OpenCV COLORMAP_TURBO) of the expected depth over the view's depth_range "
                                 "(2nd-98th percentile where alpha >= 0.5): dark blue = near, dark red = far, black = "
                                 "not covered; raw float32 depth.npy beside it (0 = empty)"}};
  for (const auto& [on, name] : {std::pair(want.rgb, "rgb"), std::pair(want.depth, "depth"),
                                 std::pair(want.features, "features"), std::pair(want.labels, "labels")})
    if (on) result["what"].push_back(name);
  if (queries) {
    json q = json::array();
    for (size_t k = 0; k < queries->texts.size(); ++k) {
      result["what"].push_back("relevance:" + queries->texts[k]);
      q.push_back({{"text", queries->texts[k]}, {"slug", queries->slugs[k]}, {"level", queries->level[k]}});
    }
    result["queries"] = q;
    result["relevance_colormap"] = "turbo of LangSplat's relevancy over [0, 1]; raw float32 .npy beside each PNG";
  }
  if (compared > 0) {
    result["mean_psnr"] = psnr_sum / compared;
    result["mean_ssim"] = ssim_sum / compared;
  }

  if (!o.path.empty()) {
    // Intrinsics of the first view by name, cut to an even size for the video's 4:2:0 chroma.
    PinholeCamera camera = split_views(scene, 0).train.front()->camera;
    camera.width -= camera.width % 2;
    camera.height -= camera.height % 2;
    const std::vector<Pose> poses = path_poses(o, scene, g);
    const cv::Size size(camera.width, camera.height);
    VideoFile rgb_video(out / "path" / "rgb.mp4", o.fps, size);
    json files{{"rgb_mp4", "path/rgb.mp4"}, {"rgb_frames", "path/rgb"}};
    std::unique_ptr<VideoFile> overlay_video;
    std::string overlay;
    if (queries) {
      overlay = "relevance_" + queries->slugs[0];
      overlay_video = std::make_unique<VideoFile>(out / "path" / (overlay + ".mp4"), o.fps, size);
      files[overlay + "_mp4"] = "path/" + overlay + ".mp4";
      files[overlay + "_frames"] = "path/" + overlay;
    }
    Progress progress("render " + o.path, poses.size(), "frames");
    // One factorisation of the decoder's last layer for every frame.
    const bool sparse = model.language && model.language->is_sparse();
    const std::optional<LinearHeadDecoder> decoder =
        overlay_video && !sparse ? std::optional(linear_head_decoder(*model.language->autoencoder)) : std::nullopt;
    for (size_t k = 0; k < poses.size(); ++k) {
      const cv::Mat frame = tensor_to_image(render_rgb(g, camera, poses[k], background).image);
      write_image(out / "path" / "rgb" / frame_name(int(k)), frame);
      rgb_video.write(frame);
      if (overlay_video) {
        const int level = queries->level[0];
        const RelevanceMaps m =
            sparse ? relevance_maps(g, model.language->sparse[level - 1], camera, poses[k], queries->features.slice(0, 0, 1),
                                    queries->canonical)
                   : relevance_maps(g, model.language->latents[level - 1], *decoder, camera, poses[k],
                                    queries->features.slice(0, 0, 1), queries->canonical);
        const cv::Mat o_frame = relevance_overlay(frame, m.relevancy[0]);
        write_image(out / "path" / overlay / frame_name(int(k)), o_frame);
        overlay_video->write(o_frame);
      }
      progress.advance();
    }
    rgb_video.finish();
    if (overlay_video) overlay_video->finish();
    result["path"] = {{"kind", o.path},
                      {"frames", poses.size()},
                      {"fps", o.fps},
                      {"width", camera.width},
                      {"height", camera.height},
                      {"codec", rgb_video.codec()},
                      {"files", files}};
    if (queries) result["path"]["relevance_text"] = queries->texts[0];
  }
  if (!notes.empty()) result["notes"] = notes;
  write_text_atomic(out / "render.json", result.dump(2) + "\n");
  return result;
}

}  // namespace cls
