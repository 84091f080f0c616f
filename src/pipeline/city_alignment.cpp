#include "pipeline/city_alignment.h"

#include "core/error.h"
#include "core/log.h"
#include "raycast/alignment.h"

namespace cls {
namespace {

nlohmann::json stats_json(const AlignmentStats& s, const AlignmentStats& fine) {
  return {{"fraction_within", s.fraction_within}, {"median", s.median}, {"mean", s.mean},
          {"fraction_within_finest", fine.fraction_within}};
}

// How many of the points within the check threshold a refinement may lose and still apply (a share of
// all points): rounding of points near the threshold, not a model pulled off its points.
constexpr double kAlignCoarseLoss = 0.01;

}  // namespace

CityAlignment align_city_model(const Scene& scene, SceneCityModel& city, const std::string& mode, double threshold,
                               const std::filesystem::path& refined_transform) {
  CityAlignment a;
  a.record = {{"mode", mode}, {"applied", false}};
  // A transform refined by an earlier run stays only while it is the one used.
  std::filesystem::remove(refined_transform);
  if (mode == "off") return a;
  if (scene.points.empty() && mode == "refine")
    fail(scene.root, "--align refine: the scene has no sparse points to refine the city transform with");
  if (scene.points.empty()) {
    a.record["reason"] = "the scene has no sparse points";
    log_warn("run: --align auto: the scene has no sparse points; the given city transform is kept");
    return a;
  }
  AlignmentRefinement r;
  try {
    r = refine_alignment(sparse_points(scene), city, IcpOptions{}, threshold);
  } catch (const Error& e) {
    if (mode == "refine") throw;
    a.record["reason"] = e.what();
    log_warn(std::string("run: --align auto: ") + e.what() + "; the given city transform is kept");
    return a;
  }
  const TransformDifference change = transform_difference(r.refined, city.transform, city.mesh);
  a.record["change"] = {{"centre", change.centre}, {"max_displacement", change.max_displacement},
                        {"rotation_deg", change.rotation_deg}, {"scale", change.scale}};
  a.record["before"] = stats_json(r.before, r.fine_before);
  a.record["after"] = stats_json(r.after, r.fine_after);
  a.record["threshold"] = threshold;
  a.record["finest"] = r.fine_before.threshold;
  log_info(cat("run: align: the refinement moves the city model by up to ", change.max_displacement, " m (",
               change.rotation_deg, " deg, scale ", 100 * change.scale, "%); ", 100 * r.before.fraction_within,
               "% -> ", 100 * r.after.fraction_within, "% of sparse points within ", threshold, " m, ",
               100 * r.fine_before.fraction_within, "% -> ", 100 * r.fine_after.fraction_within, "% within ",
               r.fine_before.threshold, " m"));
  if (mode == "auto") {
    std::string keep;
    if (change.max_displacement <= kAlignApplyMetres)
      keep = cat("the refinement moves the model by at most ", kAlignApplyMetres, " m");
    else if (!(r.fine_after.fraction_within > r.fine_before.fraction_within))
      keep = cat("the refinement brings no more sparse points within ", r.fine_before.threshold, " m of the model");
    else if (r.after.fraction_within < r.before.fraction_within - kAlignCoarseLoss)
      keep = cat("the refinement takes more than ", 100 * kAlignCoarseLoss, "% of the sparse points beyond ",
                 threshold, " m of the model");
    else if (r.icp.conditioning < kIcpWeakConditioning)
      keep = cat("the points leave part of the motion unconstrained (conditioning ", r.icp.conditioning, ")");
    if (!keep.empty()) {
      a.record["reason"] = keep;
      if (change.max_displacement > kAlignApplyMetres) log_warn("run: --align auto: " + keep + "; the given transform is kept");
      return a;
    }
  }
  a.applied = true;
  a.transform = refined_transform;
  std::filesystem::create_directories(a.transform.parent_path());
  write_city_transform(a.transform.string(), r.refined);
  a.record["applied"] = true;
  a.record["transform"] = a.transform.string();
  city.transform = r.refined;
  city.vertices = scene_vertices(city.mesh, city.transform);
  log_info("run: align: using the refined city transform " + a.transform.string());
  return a;
}

}  // namespace cls
