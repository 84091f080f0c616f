// citylangsplat features: per-view SAM and CityGML features in LangSplat's layout (paper 3.1-3.2).
#include <filesystem>
#include <string>

#include "cli/commands.h"
#include "core/args.h"
#include "core/error.h"
#include "core/log.h"
#include "features/feature_stage.h"
#include "features/provider_registry.h"
#include "raycast/label_map_io.h"
#include "scene/scene.h"

namespace cls {
namespace fs = std::filesystem;

int cmd_features(int argc, char** argv) {
  Args args("features",
            "Per-view language features (paper 3.1-3.2), in LangSplat's layout: OUT/<stem>_s.npy (SAM seg maps "
            "4 x H x W: default, s, m, l) and _f.npy (one feature per SAM segment), plus the CityGML branch "
            "_gml_s.npy (region ids per level 1-3), _gml_f.npy (fused (1 - alpha) f_gml + alpha f_txt, "
            "normalised) and _gml.json. Views already computed with the same inputs are skipped; "
            "OUT/features.json is written last.");
  fs::path scene_dir;
  std::string taxonomy_path;
  int resolution = 1;
  FeatureStageOptions options;
  ProviderChoice choice;
  args.bind("scene", scene_dir, "scene directory (COLMAP, OPF or Pix4D)").required();
  feature_stage_options().declare(args, options);
  provider_options().declare(args, choice);
  args.bind("resolution", resolution, "divide the image size by 1, 2, 4 or 8 (as for raycast)").short_name("r")
      .bind("taxonomy", taxonomy_path, "taxonomy JSON (default: the built-in one); must match the label maps");
  if (!args.parse(argc, argv)) return 0;
  feature_stage_options().apply(args, options);
  provider_options().apply(args, choice);
  if (!(options.alpha >= 0 && options.alpha <= 1)) throw UsageError("features: --alpha must be in [0, 1]");
  if (resolution != 1 && resolution != 2 && resolution != 4 && resolution != 8)
    throw UsageError("features: --resolution must be 1, 2, 4 or 8");

  // Inputs first, then the (possibly slow) models.
  const Taxonomy taxonomy = taxonomy_path.empty() ? Taxonomy::builtin() : Taxonomy::load(taxonomy_path);
  if (!fs::is_directory(options.labels_dir))
    fail(options.labels_dir.string(), "label map directory not found (make it with `citylangsplat raycast`)");
  check_label_legend(options.labels_dir, taxonomy);
  SceneOptions scene_options;
  scene_options.resolution_factor = resolution;
  const Scene scene = load_scene(scene_dir.string(), scene_options);
  if (scene.views.empty()) fail(scene_dir.string(), "the scene has no views");

  const ResolvedProvider provider = resolve_provider(choice, scene_dir.string(), taxonomy);
  if (!provider.provider) throw Error("features: " + provider.missing);
  if (!provider.note.empty()) log_warn("features: " + provider.note);
  const std::string warning = provider_warning(provider.name);
  if (!warning.empty()) log_warn("features: " + warning);
  const int computed = run_feature_stage(scene, *provider.provider, taxonomy, options);
  log_info(cat("features: computed ", computed, " of ", scene.views.size(), " views into ", options.out_dir.string()));
  return 0;
}

}  // namespace cls
