// citylangsplat align-check: how well a scene's sparse points lie on the city mesh.
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli/city_mesh_inputs.h"
#include "cli/commands.h"
#include "core/args.h"
#include "core/error.h"
#include "core/exit_codes.h"
#include "core/log.h"
#include "raycast/alignment.h"
#include "scene/scene.h"

namespace cls {

int cmd_align_check(int argc, char** argv) {
  Args args("align-check",
            "Distance from every sparse point of the scene to the nearest city-mesh triangle, in the "
            "city model's units (metres): the share within -d, median and mean. A low share means the "
            "model and the scene are misaligned (check --city-transform) before any training. Exits with status "
            "5 when the share is below --min-fraction, so a script can stop before training.");
  std::string scene_dir;
  CityMeshOptions city_options;
  double threshold = 0.5, min_fraction = kMisalignedFraction;
  bool json = false;
  args.bind("scene", scene_dir, "scene directory (COLMAP, OPF or Pix4D)").required();
  city_options.bind(args)
      .bind("distance", threshold, "threshold in metres of the city model")
      .short_name("d")
      .bind("min-fraction", min_fraction,
            "the least share of sparse points within --distance for the scene to count as aligned (else exit 5)")
      .flag("json", json, "print exactly one JSON object on stdout");
  if (!args.parse(argc, argv)) return 0;
  if (!(threshold >= 0) || !std::isfinite(threshold))
    throw UsageError("align-check: --distance must be a non-negative number");
  if (!(min_fraction >= 0 && min_fraction <= 1)) throw UsageError("align-check: --min-fraction must be in [0, 1]");

  const Scene scene = load_scene_without_images(scene_dir);
  const SceneCityModel city = load_city_mesh_inputs(city_options, "align-check");

  const AlignmentStats s = check_alignment(scene, city, threshold);
  const bool aligned = s.fraction_within >= min_fraction;

  if (json) {
    const nlohmann::json j = {{"points", s.points},       {"triangles", city.mesh.num_triangles()},
                              {"threshold", s.threshold}, {"fraction_within", s.fraction_within},
                              {"median", s.median},       {"mean", s.mean},
                              {"aligned", aligned}};
    std::printf("%s\n", j.dump().c_str());
  } else {
    std::printf("points           %zu\n", s.points);
    std::printf("triangles        %zu\n", city.mesh.num_triangles());
    std::printf("within %-9g %.2f%%\n", s.threshold, 100 * s.fraction_within);
    std::printf("median distance  %.4g\n", s.median);
    std::printf("mean distance    %.4g\n", s.mean);
  }
  if (!aligned)
    log_warn(cat("align-check: only ", 100 * s.fraction_within, "% of the sparse points lie within ", threshold,
                 " m of the city mesh (median ", s.median, " m), fewer than --min-fraction ", min_fraction,
                 ": the model and the scene look misaligned; check --city-transform"));
  return aligned ? kExitOk : kExitMisaligned;
}

}  // namespace cls
