#pragma once
// Where everything of a `run` lives: the one place that spells its output layout (docs/pipeline.md
// draws the tree). The pipeline writes through it; the report, the viewer, tiles and merge read
// through it. A layout with an empty root gives the paths relative to the run directory (the report's
// links). LanguageModelFiles names the files of a language model directory (language/<method> of a run,
// or train-language's and merge's --out), SceneFiles what the pipeline reads from a scene directory
// besides the scene itself.
#include <filesystem>
#include <string>

namespace cls {

class RunLayout {
 public:
  using path = std::filesystem::path;
  explicit RunLayout(path root = {}) : root_(std::move(root)) {}
  static RunLayout of_scene(const path& scene_dir) { return RunLayout(scene_dir / "citylangsplat"); }

  const path& root() const { return root_; }
  path run_json() const { return root_ / "run.json"; }
  path report_page() const { return root_ / "report" / "index.html"; }
  path georef_transform() const { return root_ / "georef" / "transform.json"; }  // run --georef's transform
  path align_transform() const { return root_ / "align" / "transform.json"; }  // run --align's refined transform
  path labels() const { return root_ / "labels"; }                             // raycast's label maps
  path features() const { return root_ / "features"; }
  path autoencoder() const { return root_ / "autoencoder.safetensors"; }
  path langsplat_autoencoder() const { return root_ / "autoencoder-langsplat.safetensors"; }
  path rgb() const { return root_ / "rgb"; }  // train-rgb's output (the photometric model)
  path rgb_ply() const { return rgb() / "point_cloud.ply"; }
  path render() const { return root_ / "render"; }
  path languages() const { return root_ / "language"; }  // one language model per method
  path language(const std::string& method) const { return languages() / method; }
  path queries() const { return root_ / "query"; }
  path query(const std::string& method) const { return queries() / method; }
  path eval() const { return root_ / "eval"; }
  path changes() const { return root_ / "changes"; }  // `changes`: enriched.city.json, changes.json, views/

  // A stage's stamp (stage.h): in its output directory, or beside its output file.
  static path stamp_in(const path& dir) { return dir / "stage.json"; }
  static path stamp_beside(const path& file) { return file.parent_path() / (file.stem().string() + ".stage.json"); }
  // A training stage's record of the inputs its checkpoint belongs to, and the checkpoint.
  static path training_started(const path& dir) { return dir / "started.json"; }
  static path checkpoints(const path& dir) { return dir / "checkpoints"; }

 private:
  path root_;
};

// A language model directory (language/language_model.h says what each file holds), in a run or alone.
struct LanguageModelFiles {
  std::filesystem::path dir;
  std::filesystem::path model_json() const { return dir / "model.json"; }  // written last: marks a complete model
  std::filesystem::path geometry() const { return dir / "point_cloud.ply"; }
  std::filesystem::path latents() const { return dir / "latents.safetensors"; }
  std::filesystem::path autoencoder() const { return dir / "autoencoder.safetensors"; }
  std::filesystem::path sparse() const { return dir / "sparse.safetensors"; }  // a sparse field's codes and codebooks
  std::filesystem::path city_objects() const { return dir / "city_objects.json"; }
  std::filesystem::path queries() const { return dir / "query"; }  // `query`'s output unless --out says otherwise
};

// What the pipeline reads from a scene directory besides the scene (synth writes all of it).
struct SceneFiles {
  std::filesystem::path dir;
  std::filesystem::path config() const { return dir / "scene.json"; }         // city model, transform, taxonomy, LoD
  std::filesystem::path gt_points() const { return dir / "gt" / "points.ply"; }  // labelled points (evaluation)
  std::filesystem::path gt_labels() const { return dir / "gt" / "labels"; }      // per-view GT labels (image-segments)
  std::filesystem::path gt_legend() const { return dir / "gt" / "legend.json"; }  // the GT labels' classes
};

}  // namespace cls
