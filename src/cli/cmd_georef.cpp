// citylangsplat georef: the city transform from the frame a Pix4D/OPF project names or the photos' EXIF
// GPS, the city mesh and ICP, with no transform given (pipeline/georeferencing.h).
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "citymodel/city_model.h"
#include "cli/commands.h"
#include "cli/transform_report.h"
#include "core/args.h"
#include "core/error.h"
#include "core/exit_codes.h"
#include "core/log.h"
#include "pipeline/georeferencing.h"
#include "scene/scene.h"

namespace cls {

int cmd_georef(int argc, char** argv) {
  Args args("georef",
            "Find the similarity that places the city model in the scene from the registered photos' EXIF GPS, "
            "with no transform given: the GPS positions into the model's CRS (PROJ; heights from the WGS 84 "
            "ellipsoid to EGM96 where proj-data has its grid), the camera centres fitted to them robustly (least "
            "median of squares: phones' outliers are rejected), then the vertical offset (ellipsoidal or sea-level "
            "heights, the phone's bias) and, when the cameras' spread is short against the GPS noise, the yaw "
            "searched so that most sparse points lie on the city mesh, and last align's ICP. A PIX4Dmapper project "
            "with its offset and output CRS, or an OPF project with a scene reference frame, starts from that "
            "frame instead (--from). Prints each step; writes the transform to --out. See docs/alignment.md.");
  std::string scene_dir, city_path, out, truth_path, from = "auto";
  CityModelOptions model;
  GeorefOptions o;
  bool json = false, no_icp = false;
  args.bind("scene", scene_dir, "scene directory (COLMAP, OPF or Pix4D) whose images carry EXIF GPS").required()
      .bind("city", city_path, "CityGML / CityJSON / CityJSONSeq city model").required()
      .bind("lod", model.lod, "level of detail: 1, 2, 3 or highest", lod_codec())
      .bind("taxonomy", model.taxonomy_path, "taxonomy JSON; the built-in one if not given")
      .bind("crs", o.crs, "the city model's CRS when its file names none or another (EPSG:N; default: its srsName / "
                          "referenceSystem)")
      .bind("out", out, "where to write the transform JSON (city CRS -> scene)").required()
      .bind("from", from, "the start: the frame the project names (frame), the photos' GPS (gps), or auto (the "
                          "frame where the scene has one)", choice_codec({"auto", "frame", "gps"}))
      .bind("frame-shift-range", o.frame_shift_range, "--from frame: metres searched horizontally about the frame")
      .bind("vertical-range", o.vertical_range, "metres searched above and below the GPS heights")
      .bind("search-gate", o.search_gate, "metres: a sparse point counts as on the model within this in the search")
      .flag("no-icp", no_icp, "stop after the search (no ICP)")
      .flag("rigid", o.icp.rigid, "ICP keeps the scale the GPS gave (6 DoF)")
      .bind("capture", o.icp.capture, "ICP's first pairing gate, metres")
      .bind("finest", o.icp.finest, "ICP's last pairing gate, metres")
      .bind("distance", o.threshold, "threshold of the printed share of points near the mesh, in metres")
      .short_name("d")
      .bind("truth", truth_path, "a known true transform (synth --gps's city/transform_true.json): print how far "
                                 "each step's transform is from it")
      .flag("json", json, "print exactly one JSON object on stdout");
  if (!args.parse(argc, argv)) return 0;
  o.refine = !no_icp;
  const std::string problem = icp_options_problem(o.icp);
  if (!problem.empty()) throw UsageError("georef: " + problem + " (--capture, --finest)");
  if (!(o.vertical_range >= 0 && std::isfinite(o.vertical_range)))
    throw UsageError("georef: --vertical-range must be a non-negative number");
  if (!(o.search_gate > 0 && std::isfinite(o.search_gate))) throw UsageError("georef: --search-gate must be positive");
  if (!(o.frame_shift_range >= 0 && std::isfinite(o.frame_shift_range)))
    throw UsageError("georef: --frame-shift-range must be a non-negative number");
  if (!(o.threshold >= 0 && std::isfinite(o.threshold))) throw UsageError("georef: --distance must be a non-negative number");

  const Scene scene = load_scene(scene_dir);
  const SemanticMesh mesh = load_city_model(city_path, load_taxonomy(model), model.lod);
  if (mesh.num_triangles() == 0) fail(city_path, "the city model has no triangles at the requested LoD");
  // Read before the work, so that a bad --truth fails first.
  const std::optional<CityTransform> truth =
      truth_path.empty() ? std::nullopt : std::optional<CityTransform>(read_city_transform(truth_path));
  const GeorefResult r = from == "frame" || (from == "auto" && scene.frame)
                             ? georeference_frame(scene, mesh, o, "georef")
                             : georeference(scene, scene_gps(scene), mesh, o, "georef");
  write_city_transform(out, r.transform);

  // Each step's transform against the truth, as (label, JSON key, difference).
  std::vector<std::tuple<const char*, const char*, TransformDifference>> errors;
  if (truth)
    errors = {{r.record.value("start", "") == "frame" ? "from frame:  " : "from GPS:    ", "start",
               transform_difference(r.start, *truth, mesh)},
              {"after search:", "searched", transform_difference(r.searched, *truth, mesh)},
              {"final:       ", "final", transform_difference(r.transform, *truth, mesh)}};
  if (json) {
    nlohmann::json j = r.record;
    j["out"] = out;
    for (const auto& [label, key, d] : errors) j["error_to_truth"][key] = difference_json(d);
    std::printf("%s\n", j.dump().c_str());
    return kExitOk;
  }
  for (size_t i = 0; i < errors.size(); ++i)
    std::printf("%s %s  %s\n", i == 0 ? "error to truth " : "               ", std::get<0>(errors[i]),
                describe(std::get<2>(errors[i])).c_str());
  std::printf("wrote %s\n", out.c_str());
  return kExitOk;
}

}  // namespace cls
