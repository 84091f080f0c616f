#include "pipeline/georeferencing.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/error.h"
#include "core/log.h"
#include "georef/crs_name.h"
#include "georef/proj_crs.h"
#include "raycast/closest_point.h"

namespace cls {
namespace {

// The search scores at most this many sparse points (an even stride through them): the share near the
// mesh is settled long before, and each candidate costs a closest-point query per point.
constexpr size_t kSearchPoints = 2000;
// ICP's turn is trusted up to twice the searched yaw range, and at least this (the GPS fit's tilt).
constexpr double kIcpTrustedTurnDeg = 5;
// About the relative scale error ICP's scale pass takes out on a building (a 0.4 m gate over about 10 m):
// a GPS fit whose scale is less certain than this (in three standard errors) starts ICP from several scales.
constexpr double kIcpScaleReach = 0.03;
// The scale starts span at most (1 + this)^3: beyond, GPS and cameras do not describe the same scene.
constexpr double kScaleStartsMaxSigma = 0.1;
// Of the points ICP leaves within the coarse threshold, at least this share lies within its finest gate
// when the pairs are on their own surfaces (synth's 1 cm noise: 0.95; SfM's few centimetres: over 0.8).
constexpr double kIcpOnSurfaceShare = 0.7;

CityTransform translation(Vec3d t) { return similarity_transform(1, Mat3d::identity(), t); }

// A rotation of `degrees` about the vertical through `centre`.
CityTransform yaw_about(double degrees, Vec3d centre) {
  const Mat3d R = axis_angle_to_rotation(Vec3d{0, 0, degrees * M_PI / 180});
  return similarity_transform(1, R, centre - R * centre);
}

// Share of `points` within `gate` of the mesh once moved by `m`.
double share_within(const ClosestPointQuery& mesh, const std::vector<Vec3d>& points, const CityTransform& m, double gate) {
  return alignment_stats(distances_after(mesh, points, m, 1), gate).fraction_within;
}

// Mean truncated squared distance of `points` to the mesh once moved by `m` (distances capped at
// `gate`): a robust least-squares cost that, unlike a count within the gate, still falls while points
// approach their surfaces, so that the yaw that puts facade points on their walls wins.
double truncated_cost(const ClosestPointQuery& mesh, const std::vector<Vec3d>& points, const CityTransform& m, double gate) {
  double sum = 0;
  for (double d : distances_after(mesh, points, m, 1)) sum += std::pow(std::min(d, gate), 2);
  return sum / static_cast<double>(points.size());
}

struct Candidate {
  double yaw = 0, dx = 0, dy = 0, dz = 0, cost = INFINITY;
  // The motion of the points: the yaw about the vertical through `centre`, then the shift.
  CityTransform motion(Vec3d centre) const { return translation({dx, dy, dz}) * yaw_about(yaw, centre); }
};

// The best of `grid` (each candidate scored); among equal costs the middle one (a facade seen only from
// the side costs the same over the height of its wall).
Candidate best_of(const ClosestPointQuery& mesh, const std::vector<Vec3d>& points, Vec3d centre,
                  std::vector<Candidate> grid, double gate) {
  for (Candidate& c : grid) c.cost = truncated_cost(mesh, points, c.motion(centre), gate);
  double best = INFINITY;
  for (const Candidate& c : grid) best = std::min(best, c.cost);
  std::vector<Candidate> tied;
  for (const Candidate& c : grid)
    if (c.cost == best) tied.push_back(c);
  return tied[tied.size() / 2];
}

std::vector<double> steps(double lo, double hi, double step) {
  std::vector<double> v;
  const int n = static_cast<int>(std::floor((hi - lo) / step + 1e-9));
  for (int i = 0; i <= n; ++i) v.push_back(lo + i * step);
  return v;
}

std::string metres(double m) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2f m", m);
  return text;
}

// Steps 3 and 4 from `start` (scene -> the model's local frame, CRS minus its origin): the search
// against the mesh, within r.yaw_range_deg and r.horizontal_range as the start leaves them open and
// options.vertical_range, then ICP. Sets r.searched, r.transform, the search's and ICP's fields and
// their part of r.record.
void search_and_refine(const Scene& scene, const SemanticMesh& mesh, const GeorefOptions& options,
                       const std::string& context, const CityTransform& start, GeorefResult& r) {
  const CityTransform to_local = translation({-mesh.origin[0], -mesh.origin[1], -mesh.origin[2]});
  // Step 3: vertical offset and yaw against the mesh, the sparse points placed by the GPS similarity.
  CityTransform searched_local = start;
  if (scene.points.empty()) {
    r.icp_problem = "the scene has no sparse points";
    log_warn(cat(context, ": the scene has no sparse points: heights and position stay as the start (GPS or the project's frame) gives them, and no ICP"));
  } else {
    const ClosestPointQuery local_mesh(scene_vertices(mesh, to_local), mesh.triangles);
    const size_t stride = (scene.points.size() + kSearchPoints - 1) / kSearchPoints;
    std::vector<Vec3d> points;
    Vec3d centre{};
    for (size_t i = 0; i < scene.points.size(); i += stride) {
      points.push_back(start.apply(scene.points[i].xyz));
      centre = centre + points.back();
    }
    centre = (1.0 / points.size()) * centre;
    double radius = 0;  // horizontal reach of the points about their centre
    for (const Vec3d& p : points) radius = std::max(radius, std::hypot(p.x - centre.x, p.y - centre.y));
    const double gate = options.search_gate;
    const double yaw_step = radius > 0 ? std::min(5.0, (gate / 2) / radius * 180 / M_PI) : 5.0;
    if (r.yaw_range_deg < yaw_step) r.yaw_range_deg = 0;
    r.search_fraction_before = share_within(local_mesh, points, CityTransform::identity(), gate);
    // Coordinate descent over the grids: the height first (the largest error), then yaw with height,
    // then the horizontal shift, then the height finely. The scale is left to ICP: a search of it
    // against the truncated cost prefers points spread beyond the model (FZK-Haus: +30 % from -0.4 %).
    std::vector<Candidate> grid;
    for (double dz : steps(-options.vertical_range, options.vertical_range, gate / 2)) grid.push_back({0, 0, 0, dz});
    Candidate c = best_of(local_mesh, points, centre, grid, gate);
    if (r.yaw_range_deg > 0) {
      grid.clear();
      for (double yaw : steps(-r.yaw_range_deg, r.yaw_range_deg, yaw_step))
        for (double dz : steps(c.dz - 2 * gate, c.dz + 2 * gate, gate / 2)) grid.push_back({yaw, 0, 0, dz});
      c = best_of(local_mesh, points, centre, grid, gate);
    }
    grid.clear();
    for (double dx : steps(-r.horizontal_range, r.horizontal_range, gate / 2))
      for (double dy : steps(-r.horizontal_range, r.horizontal_range, gate / 2)) grid.push_back({c.yaw, dx, dy, c.dz});
    c = best_of(local_mesh, points, centre, grid, gate);
    grid.clear();
    for (double dz : steps(c.dz - gate, c.dz + gate, gate / 8)) grid.push_back({c.yaw, c.dx, c.dy, dz});
    c = best_of(local_mesh, points, centre, grid, gate / 4);
    r.vertical_offset = c.dz;
    r.yaw_deg = c.yaw;
    r.horizontal_shift = std::hypot(c.dx, c.dy);
    const CityTransform found = c.motion(centre);
    r.search_fraction = share_within(local_mesh, points, found, gate);
    searched_local = found * start;
    log_info(cat(context, ": search against the city model: vertical offset ", metres(c.dz), " (searched +-",
                 options.vertical_range, " m)",
                 r.yaw_range_deg > 0 ? cat(", yaw ", c.yaw, " deg (searched +-", r.yaw_range_deg, " deg)") : std::string(),
                 ", horizontal shift ", metres(r.horizontal_shift), " (searched +-", metres(r.horizontal_range), "); ", 100 * r.search_fraction_before, "% -> ", 100 * r.search_fraction, "% of the sparse points within ",
                 gate, " m of the model"));
  }
  r.searched = inverse(searched_local) * to_local;
  r.transform = r.searched;

  // Step 4: ICP from there.
  if (!options.refine && r.icp_problem.empty()) r.icp_problem = "not asked for";
  if (r.icp_problem.empty()) {
    // ICP's scale pass takes out a few percent (its first gate over the points' reach); the GPS may leave
    // the scale open by more on a small building (bench/georef.sh: FZK-Haus at 8 m noise, 14 % off). ICP
    // then starts from scales spread over three standard errors of the GPS fit's, and the start that puts
    // the most points on the surfaces (within the finest gate) wins: a wrong scale leaves fewer there.
    const std::vector<Vec3d> points = sparse_points(scene);
    Vec3d centre{};
    for (const Vec3d& p : points) centre = centre + (1.0 / points.size()) * p;
    std::vector<double> scales = {1};
    const double sigma = std::min(r.scale_sigma, kScaleStartsMaxSigma);
    if (sigma > kIcpScaleReach / 3)
      for (int k = 1; k <= 3; ++k) scales.push_back(std::pow(1 + sigma, k)), scales.push_back(std::pow(1 + sigma, -k));
    std::string last_problem;
    double start_scale = 1;
    for (double f : scales) {
      SceneCityModel placed;
      placed.mesh = mesh;
      placed.transform = translation(centre) * similarity_transform(f, Mat3d::identity(), -f * centre) * r.searched;
      placed.vertices = scene_vertices(mesh, placed.transform);
      try {
        AlignmentRefinement a = refine_alignment(points, placed, options.icp, options.threshold);
        if (!r.icp || a.fine_after.fraction_within > r.icp->fine_after.fraction_within) r.icp = std::move(a), start_scale = f;
      } catch (const Error& e) {
        last_problem = e.what();
      }
    }
    if (!r.icp) r.icp_problem = last_problem;
    if (scales.size() > 1 && r.icp)
      log_info(cat(context, ": ICP from ", scales.size(), " scales within +-", 100 * (std::pow(1 + sigma, 3) - 1),
                   "% of the GPS's (three standard errors): the start at ", 100 * (start_scale - 1), "% puts the most points on the model"));
    r.record["icp_scale_starts"] = scales.size();
    r.record["icp_start_scale"] = start_scale;
    if (r.icp) {
      const TransformDifference change = transform_difference(r.icp->refined, r.searched, mesh);
      log_info(cat(context, ": ICP moves the model by up to ", metres(change.max_displacement), " (", change.rotation_deg,
                   " deg, scale ", 100 * change.scale, "%); ", 100 * r.icp->before.fraction_within, "% -> ",
                   100 * r.icp->after.fraction_within, "% of sparse points within ", options.threshold, " m, ",
                   100 * r.icp->fine_after.fraction_within, "% within ", r.icp->fine_after.threshold, " m"));
      // ICP may turn the model as far as the start leaves the yaw open, and a few degrees of tilt beyond.
      const double turn = std::max(2 * r.yaw_range_deg, kIcpTrustedTurnDeg);
      if (r.icp->icp.conditioning < kIcpWeakConditioning)
        r.icp_problem = cat("the sparse points leave part of the motion unconstrained (conditioning ",
                            r.icp->icp.conditioning, ")");
      else if (change.rotation_deg > turn)
        r.icp_problem = cat("it turns the model by ", change.rotation_deg, " deg, more than the start leaves open (", turn,
                            " deg): it may have slid onto other surfaces, and cannot be trusted");
      else
        r.transform = r.icp->refined;
    }
    if (r.icp_problem.empty()) {
      // ICP ended where the points' pairs hold it, which need not be the truth: pairs slid onto other
      // surfaces leave many points near but not on the model (bench/georef.sh, the LoD2 district at 8 m
      // GPS noise: 17 % within 0.1 m of the 30 % within 0.5 m).
      const double on_surface = r.icp->after.fraction_within > 0
                                    ? r.icp->fine_after.fraction_within / r.icp->after.fraction_within : 0;
      if (on_surface < kIcpOnSurfaceShare)
        r.warnings.push_back(cat("only ", 100 * on_surface, "% of the points within ", options.threshold, " m of the model lie within ",
                                 r.icp->fine_after.threshold, " m: ICP may have slid onto other surfaces"));
      for (const std::string& w : r.warnings)
        log_warn(cat(context, ": ", w, "; check the label maps' outlines on the photos (report), or give a transform"));
    }
    if (!r.icp_problem.empty())
      log_warn(cat(context, ": ICP: ", r.icp_problem, "; the searched transform is kept"));
  }

  r.record["vertical_offset"] = r.vertical_offset;
  r.record["yaw_deg"] = r.yaw_deg;
  r.record["yaw_range_deg"] = r.yaw_range_deg;
  r.record["horizontal_shift"] = r.horizontal_shift;
  r.record["horizontal_range"] = r.horizontal_range;
  r.record["search"] = {{"gate", options.search_gate},
                        {"fraction_before", r.search_fraction_before},
                        {"fraction_after", r.search_fraction}};
  if (r.icp)
    r.record["icp"] = {{"applied", r.icp_problem.empty()},
                       {"conditioning", r.icp->icp.conditioning},
                       {"fraction_within", r.icp->after.fraction_within},
                       {"fraction_within_finest", r.icp->fine_after.fraction_within},
                       {"threshold", options.threshold},
                       {"finest", r.icp->fine_after.threshold}};
  if (!r.icp_problem.empty()) r.record["icp_problem"] = r.icp_problem;
  r.record["warnings"] = r.warnings;
}

}  // namespace

std::vector<std::optional<GpsFix>> scene_gps(const Scene& scene) {
  std::vector<std::optional<GpsFix>> gps;
  gps.reserve(scene.views.size());
  for (const SceneView& v : scene.views) gps.push_back(read_exif_gps(v.image_path));
  return gps;
}

GeorefResult georeference(const Scene& scene, const std::vector<std::optional<GpsFix>>& gps, const SemanticMesh& mesh,
                          const GeorefOptions& options, const std::string& context) {
  GeorefResult r;
  const CrsName crs = city_model_crs(mesh.source_path, mesh.crs, options.crs);
  r.epsg = crs.horizontal_epsg;
  const GpsProjection projection(r.epsg);
  // The model's own height datum through its geoid where PROJ has the grid (national geoids: installed by
  // the user), else EGM96 (proj-data), else none: the vertical search takes up what is left.
  const std::optional<GeoidHeights> national =
      crs.vertical_epsg ? std::optional<GeoidHeights>(std::in_place, crs.horizontal_epsg, crs.vertical_epsg) : std::nullopt;
  const bool use_national = national && national->available();
  const Egm96Geoid geoid;
  r.images = scene.views.size();

  // Step 1: camera centres (scene) and GPS positions (CRS minus the mesh's origin, EGM96 heights).
  std::vector<Vec3d> centres, positions;
  double undulation_sum = 0;
  size_t undulations = 0;
  for (size_t i = 0; i < gps.size(); ++i) {
    if (!gps[i]) continue;
    ++r.fixes;
    if (!gps[i]->altitude) {
      ++r.without_altitude;
      continue;
    }
    const std::array<double, 2> xy = projection.project(gps[i]->latitude, gps[i]->longitude);
    double height = *gps[i]->altitude;
    std::optional<double> n = geoid.undulation(gps[i]->latitude, gps[i]->longitude);
    if (use_national) {
      const std::optional<double> h = national->height(gps[i]->latitude, gps[i]->longitude, height);
      n = h ? std::optional<double>(height - *h) : std::nullopt;
    }
    if (n) {
      height -= *n;
      undulation_sum += *n;
      ++undulations;
    }
    centres.push_back(scene.views[i].pose.center());
    positions.push_back({xy[0] - mesh.origin[0], xy[1] - mesh.origin[1], height - mesh.origin[2]});
  }
  if (undulations > 0) r.undulation = undulation_sum / static_cast<double>(undulations);
  log_info(cat(context, ": ", r.fixes, " of ", r.images, " registered photos carry a GPS position (",
               r.fixes - r.without_altitude, " with an altitude); the city model's CRS: EPSG:", r.epsg));
  if (centres.size() < 3)
    fail(scene.root, cat("georeferencing needs at least 3 registered photos with a GPS position and altitude in their "
                         "EXIF; ", centres.size(), " of ", r.images, " have one"));

  // Step 2: scene -> local CRS.
  r.gps = robust_similarity(centres, positions);
  std::vector<double> rejected;
  for (size_t i = 0; i < centres.size(); ++i)
    if (!r.gps.inlier[i]) rejected.push_back(r.gps.residuals[i]);
  std::sort(rejected.rbegin(), rejected.rend());
  std::string rejected_text;
  for (size_t i = 0; i < std::min<size_t>(rejected.size(), 5); ++i) rejected_text += (i ? ", " : " (") + metres(rejected[i]);
  if (!rejected.empty()) rejected_text += rejected.size() > 5 ? ", ...)" : ")";
  log_info(cat(context, ": GPS: ", r.gps.inliers, " of ", centres.size(), " positions agree with the cameras within ",
               metres(r.gps.threshold), " (RMS ", metres(r.gps.rms), "); ", rejected.size(), " rejected", rejected_text,
               "; ", r.gps.transform.scale(), " m per scene unit"));
  r.geoid = !r.undulation ? "" : use_national ? national->operation() : "EGM96";
  log_info(!r.undulation ? cat(context, ": heights: as written (the EGM96 grid egm96_15.gtx of proj-data is not "
                                        "installed); the vertical search finds the datum")
           : use_national ? cat(context, ": heights: WGS 84 ellipsoid -> EPSG:", crs.vertical_epsg, " through PROJ's ",
                                r.geoid, " (N = ", metres(*r.undulation), ")")
                          : cat(context, ": heights: WGS 84 ellipsoid -> EGM96 geoid (N = ", metres(*r.undulation),
                                ", proj-data's egm96_15.gtx)",
                                crs.vertical_epsg ? cat("; the grid of EPSG:", crs.vertical_epsg,
                                                        "'s own geoid is not installed (PROJ_DATA): the vertical search "
                                                        "takes up the difference")
                                                  : std::string()));
  const CityTransform to_local = translation({-mesh.origin[0], -mesh.origin[1], -mesh.origin[2]});
  r.start = inverse(r.gps.transform) * to_local;

  // How far the yaw may be off: three standard errors of the GPS fit's rotation about the vertical.
  Vec3d mean{};
  size_t inliers = 0;
  for (size_t i = 0; i < positions.size(); ++i)
    if (r.gps.inlier[i]) mean = mean + positions[i], ++inliers;
  mean = (1.0 / inliers) * mean;
  double spread = 0;
  for (size_t i = 0; i < positions.size(); ++i)
    if (r.gps.inlier[i]) spread += std::pow(positions[i].x - mean.x, 2) + std::pow(positions[i].y - mean.y, 2);
  spread = std::sqrt(spread / inliers);
  r.yaw_range_deg = spread > 0 ? std::min(180.0, 3 * std::atan(r.gps.rms / (spread * std::sqrt(inliers))) * 180 / M_PI) : 180;
  // The fit's scale standard error: the per-axis noise over the inlier positions' 3D spread.
  double spread3 = 0;
  for (size_t i = 0; i < positions.size(); ++i)
    if (r.gps.inlier[i]) spread3 += dot(positions[i] - mean, positions[i] - mean);
  r.scale_sigma = spread3 > 0 ? (r.gps.rms / std::sqrt(3.0)) / std::sqrt(spread3) : kScaleStartsMaxSigma;
  // How far the model may be off horizontally at the points: three standard errors of the GPS fit's
  // centre, and a gate.
  r.horizontal_range = std::min(options.vertical_range, 3 * r.gps.rms / std::sqrt(inliers) + options.search_gate);
  r.record = {{"start", "gps"},
              {"crs", cat("EPSG:", r.epsg)},
              {"images", r.images},
              {"fixes", r.fixes},
              {"without_altitude", r.without_altitude},
              {"used", r.gps.inliers},
              {"rejected", rejected.size()},
              {"gps_threshold", r.gps.threshold},
              {"gps_rms", r.gps.rms},
              {"scene_scale", r.gps.transform.scale()},
              {"geoid", r.undulation ? nlohmann::json(r.geoid) : nlohmann::json(nullptr)},
              {"undulation", r.undulation ? nlohmann::json(*r.undulation) : nlohmann::json(nullptr)}};
  search_and_refine(scene, mesh, options, context, r.gps.transform, r);
  return r;
}

GeorefResult georeference_frame(const Scene& scene, const SemanticMesh& mesh, const GeorefOptions& options,
                                const std::string& context) {
  if (!scene.frame) fail(scene.root, "the scene names no frame in a CRS (a PIX4Dmapper offset, an OPF scene reference frame, a COLMAP model in absolute coordinates)");
  const SceneFrame& frame = *scene.frame;
  GeorefResult r;
  r.epsg = city_model_crs(mesh.source_path, mesh.crs, options.crs).horizontal_epsg;
  r.images = scene.views.size();
  const std::string city_crs = cat("EPSG:", r.epsg);
  std::string frame_crs = frame.crs;
  if (frame_crs.empty()) {
    frame_crs = city_crs;
    log_warn(cat(context, ": ", frame.source, " names no CRS: taken to be the city model's (", city_crs, ")"));
  }
  // City CRS -> frame CRS, as a similarity fitted to PROJ's transformation of a grid over the model
  // (+-1 km about its origin, +-200 m for ECEF): exact where both CRSs are the same, and within
  // millimetres across a city block between two projections of one datum, or to ECEF. Heights pass
  // unchanged into a projected frame; into a geocentric one (a COLMAP model model_aligner put into ECEF
  // from GPS) they become ellipsoidal through EGM96 where its grid is installed (the vertical search
  // takes up the rest).
  const bool geocentric = is_geocentric_crs(frame_crs).value_or(false);
  const std::optional<CrsTransform> crs =
      geocentric ? std::nullopt : std::optional<CrsTransform>(std::in_place, city_crs, frame_crs, "a photogrammetry project's frame");
  const std::optional<CrsToGeocentric> to_geocentric =
      geocentric ? std::optional<CrsToGeocentric>(std::in_place, city_crs, frame_crs) : std::nullopt;
  auto in_frame_crs = [&](const Vec3d& local) {
    const double x = mesh.origin[0] + local.x, y = mesh.origin[1] + local.y, z = mesh.origin[2] + local.z;
    if (to_geocentric) {
      const auto xyz = (*to_geocentric)(x, y, z);
      if (!xyz) fail(frame.source, cat("PROJ cannot place the city model's position (", city_crs, ") in ", frame_crs));
      return Vec3d{(*xyz)[0], (*xyz)[1], (*xyz)[2]};
    }
    const auto xy = crs->forward(x, y);
    if (!xy) fail(frame.source, cat("its CRS cannot represent the city model's position (", city_crs, ")"));
    return Vec3d{(*xy)[0], (*xy)[1], z};
  };
  const Vec3d reference = in_frame_crs({});
  // ECEF follows the Earth's curvature, which a similarity does not: 3 mm at 200 m, 8 cm at 1 km.
  const double reach = geocentric ? 200 : 1000;
  std::vector<Vec3d> local, in_frame;
  for (double x : {-reach, 0.0, reach})
    for (double y : {-reach, 0.0, reach})
      for (double z : {0.0, reach / 10}) {
        local.push_back({x, y, z});
        in_frame.push_back(in_frame_crs(local.back()) - reference);
      }
  const SimilarityFit fit = robust_similarity(local, in_frame);
  double fit_error = 0;
  for (double e : fit.residuals) fit_error = std::max(fit_error, e);
  // local -> scene: scene = scale * (frame CRS) + shift, the frame CRS = fit(local) + reference.
  const CityTransform local_to_scene =
      translation(frame.scale * reference + frame.shift) * similarity_transform(frame.scale, Mat3d::identity(), {}) * fit.transform;
  const CityTransform to_local = translation({-mesh.origin[0], -mesh.origin[1], -mesh.origin[2]});
  r.start = local_to_scene * to_local;
  log_info(cat(context, ": the scene's frame from ", frame.source, ": ", frame_crs.size() > 60 ? frame_crs.substr(0, 57) + "..." : frame_crs,
               ", scale ", frame.scale, ", shift ", metres(frame.shift.x), " ", metres(frame.shift.y), " ", metres(frame.shift.z),
               frame_crs == city_crs ? std::string() : cat("; to the city model's ", city_crs, " within ", metres(fit_error))));
  // The frame's orientation comes from all cameras: only its position and heights are searched
  // (a project georeferenced by the drone's GPS alone is metres off, its heights often more).
  r.yaw_range_deg = 0;
  r.horizontal_range = options.frame_shift_range;
  r.record = {{"start", "frame"},
              {"crs", city_crs},
              {"frame", frame.source},
              {"frame_crs", frame_crs},
              {"frame_scale", frame.scale},
              {"frame_shift", {frame.shift.x, frame.shift.y, frame.shift.z}},
              {"crs_fit_error", fit_error},
              {"images", r.images}};
  search_and_refine(scene, mesh, options, context, inverse(local_to_scene), r);
  return r;
}

}  // namespace cls
