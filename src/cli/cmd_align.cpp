// citylangsplat align: refine the city-to-scene similarity from the scene's own geometry (ICP).
#include <ATen/ATen.h>

#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli/city_mesh_inputs.h"
#include "cli/commands.h"
#include "cli/transform_report.h"
#include "core/args.h"
#include "core/error.h"
#include "core/exit_codes.h"
#include "core/log.h"
#include "raycast/alignment.h"
#include "scene/scene.h"
#include "splat/ply_gaussians.h"

namespace cls {
namespace {

// Centres of the model's Gaussians at least `min_opacity` opaque: the surfaces the photos show.
std::vector<Vec3d> gaussian_centres(const std::string& path, double min_opacity) {
  const GaussianModel model = read_gaussians_ply(path);
  const at::Tensor keep = (model.opacities() >= min_opacity).logical_and(model.means.isfinite().all(1));
  const at::Tensor means = model.means.index({keep}).to(at::kDouble).contiguous();
  const double* m = means.data_ptr<double>();
  std::vector<Vec3d> out(means.size(0));
  for (size_t i = 0; i < out.size(); ++i) out[i] = {m[3 * i], m[3 * i + 1], m[3 * i + 2]};
  if (out.empty()) fail(path, cat("no Gaussian is at least ", min_opacity, " opaque"));
  return out;
}

nlohmann::json stats_json(const AlignmentStats& s) {
  return {{"fraction_within", s.fraction_within}, {"median", s.median}, {"mean", s.mean}};
}

}  // namespace

int cmd_align(int argc, char** argv) {
  Args args("align",
            "Refine the similarity that places the city model in the scene (--city-transform) from the scene's "
            "own geometry: robust point-to-plane ICP of the sparse points (and, with --gaussians, the centres of "
            "a photometric model's opaque Gaussians) onto the city mesh, Huber-weighted, pairs beside the mesh's "
            "edges left out (terrain, trees, clutter), the pairing gate halving from --capture to --finest; "
            "rigid first, then (unless --rigid) with the scale from 4x --finest down. Prints the point-to-mesh "
            "distances before and after and the change applied; writes the refined transform to --out. See "
            "docs/alignment.md for the capture range.");
  std::string scene_dir, out, gaussians, truth_path;
  CityMeshOptions city_options;
  IcpOptions icp;
  double min_opacity = 0.5, threshold = 0.5;
  bool json = false;
  args.bind("scene", scene_dir, "scene directory (COLMAP, OPF or Pix4D)").required();
  city_options.bind(args)
      .bind("out", out, "where to write the refined transform JSON")
      .required()
      .bind("gaussians", gaussians, "also fit the centres of this 3DGS PLY's Gaussians (train-rgb's point_cloud.ply)")
      .bind("min-opacity", min_opacity, "with --gaussians: only Gaussians at least this opaque")
      .flag("rigid", icp.rigid, "keep the scale (6 DoF: rotation and translation only)")
      .bind("capture", icp.capture, "first pairing gate in metres of the city model: how far off the start may be")
      .bind("finest", icp.finest, "last pairing gate in metres (the gates halve from --capture down to it)")
      .bind("iterations", icp.max_iterations, "at most this many iterations per gate")
      .bind("distance", threshold, "threshold of the printed share of points near the mesh, in metres")
      .short_name("d")
      .bind("truth", truth_path, "a known true transform (e.g. synth --city-error's city/transform_true.json): print "
                                 "how far the given and the refined transforms are from it")
      .flag("json", json, "print exactly one JSON object on stdout");
  if (!args.parse(argc, argv)) return 0;
  const std::string problem = icp_options_problem(icp);
  if (!problem.empty()) throw UsageError("align: " + problem + " (--capture, --finest, --iterations)");
  if (!(threshold >= 0) || !std::isfinite(threshold)) throw UsageError("align: --distance must be a non-negative number");
  if (!(min_opacity >= 0 && min_opacity <= 1)) throw UsageError("align: --min-opacity must be in [0, 1]");

  const Scene scene = load_scene_without_images(scene_dir);
  std::vector<Vec3d> points = sparse_points(scene);
  const size_t sparse = points.size();
  if (!gaussians.empty()) {
    const auto centres = gaussian_centres(gaussians, min_opacity);
    points.insert(points.end(), centres.begin(), centres.end());
  }
  const SceneCityModel city = load_city_mesh_inputs(city_options, "align");
  const bool has_truth = !truth_path.empty();
  const CityTransform truth = has_truth ? read_city_transform(truth_path) : CityTransform{};

  const AlignmentRefinement r = refine_alignment(points, city, icp, threshold);
  write_city_transform(out, r.refined);
  const TransformDifference change = transform_difference(r.refined, city.transform, city.mesh);
  const double unit = city.transform.scale();  // scene units per metre of the city model

  if (json) {
    nlohmann::json stages = nlohmann::json::array();
    for (const auto& s : r.icp.stages)
      stages.push_back({{"gate", s.gate / unit}, {"scale", s.scale}, {"iterations", s.iterations}, {"pairs", s.pairs},
                        {"rms", s.rms / unit}});
    nlohmann::json j = {{"points", points.size()},     {"sparse_points", sparse},
                        {"rigid", icp.rigid},          {"threshold", threshold},
                        {"before", stats_json(r.before)}, {"after", stats_json(r.after)},
                        {"stages", stages},            {"conditioning", r.icp.conditioning},
                        {"change", difference_json(change)}, {"out", out}};
    if (has_truth)
      j["error_to_truth"] = {{"before", difference_json(transform_difference(city.transform, truth, city.mesh))},
                             {"after", difference_json(transform_difference(r.refined, truth, city.mesh))}};
    std::printf("%s\n", j.dump().c_str());
  } else {
    std::printf("points             %zu (%zu sparse, %zu Gaussian centres)\n", points.size(), sparse,
                points.size() - sparse);
    std::printf("%-18s %12s %12s\n", "", "before", "after");
    std::printf("%-18s %11.2f%% %11.2f%%\n", cat("within ", threshold, " m").c_str(), 100 * r.before.fraction_within,
                100 * r.after.fraction_within);
    std::printf("%-18s %12.4g %12.4g\n", "median distance", r.before.median, r.after.median);
    std::printf("%-18s %12.4g %12.4g\n", "mean distance", r.before.mean, r.after.mean);
    std::printf("%-10s %-6s %10s %8s %12s\n", "gate (m)", "scale", "iterations", "pairs", "rms (m)");
    for (const auto& s : r.icp.stages)
      std::printf("%-10.4g %-6s %10d %8zu %12.4g\n", s.gate / unit, s.scale ? "yes" : "no", s.iterations, s.pairs,
                  s.rms / unit);
    std::printf("change applied     %s\n", describe(change).c_str());
    if (has_truth) {
      std::printf("error to truth     before: %s\n", describe(transform_difference(city.transform, truth, city.mesh)).c_str());
      std::printf("                   after:  %s\n", describe(transform_difference(r.refined, truth, city.mesh)).c_str());
    }
    std::printf("wrote %s\n", out.c_str());
  }
  if (r.icp.conditioning < kIcpWeakConditioning)
    log_warn(cat("align: the paired surfaces leave part of the motion unconstrained (conditioning ",
                 r.icp.conditioning, "; e.g. only one facade is seen): check the refined transform"));
  return kExitOk;
}

}  // namespace cls
