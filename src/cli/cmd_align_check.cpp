// citylangsplat align-check: how well a scene's sparse points lie on the city mesh.
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
  args.option("scene", "", "scene directory (COLMAP or Pix4D; required)");
  add_city_mesh_options(args);
  args.option("distance", "0.5", "threshold in metres of the city model", "d")
      .option("min-fraction", cat(kMisalignedFraction),
              "the least share of sparse points within --distance for the scene to count as aligned (else exit 5)")
      .flag("json", "print exactly one JSON object on stdout");
  if (!args.parse(argc, argv)) return 0;
  if (!args.has("scene")) throw UsageError("align-check: --scene is required (see --help)");
  const double threshold = args.get_double("distance");
  if (!(threshold >= 0) || !std::isfinite(threshold))
    throw UsageError("align-check: --distance must be a non-negative number");
  const double min_fraction = args.get_double("min-fraction");
  if (!(min_fraction >= 0 && min_fraction <= 1)) throw UsageError("align-check: --min-fraction must be in [0, 1]");
  const CityMeshOptions city_options = city_mesh_options(args, "align-check");

  const Scene scene = load_scene_without_images(args.get("scene"));
  const SceneCityModel city = load_city_mesh_inputs(city_options, "align-check");

  const AlignmentStats s = check_alignment(scene, city, threshold);
  const bool aligned = s.fraction_within >= min_fraction;

  if (args.flag_set("json")) {
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
