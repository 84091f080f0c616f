#pragma once
// Georeferencing from the photos' GPS (issue 34, docs/alignment.md "From the photos' GPS"): the city
// transform found without a hand-written JSON, in four steps:
//   1. the registered photos' EXIF GPS in the city model's CRS (PROJ); heights from the WGS 84
//      ellipsoid to the model's height datum where PROJ has its geoid grid, else to EGM96 (proj-data);
//   2. the similarity from the SfM camera centres to those positions, robust to phones' outliers
//      (least median of squares, georef/robust_similarity.h);
//   3. what GPS cannot resolve, searched against the city mesh: the vertical offset (a phone's height
//      may be ellipsoidal or above sea level, plus its own bias), when the cameras' spread is short
//      against the GPS noise the yaw, and the horizontal shift the GPS noise leaves (beyond ICP's
//      capture); the cost is the sparse points' truncated squared distance to the mesh;
//   4. point-to-plane ICP of the sparse points onto the mesh (align's refinement).
// A photogrammetry project that names its frame in a CRS (PIX4Dmapper's offset and output CRS, an OPF
// scene reference frame: Scene::frame) starts from that frame instead of steps 1-2
// (georeference_frame). `georef` runs it alone, `run --georef` before the label maps.
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "citymodel/scene_city_model.h"
#include "georef/robust_similarity.h"
#include "raycast/alignment.h"
#include "scene/exif_gps.h"
#include "scene/scene.h"

namespace cls {

struct GeorefOptions {
  std::string crs;               // EPSG:N; "": the city model's own (srsName / referenceSystem)
  double vertical_range = 100;   // metres searched above and below the GPS heights (after EGM96)
  double search_gate = 2;        // metres: a point counts as on the mesh within this in the coarse search
  double frame_shift_range = 5;  // metres searched horizontally about a project's frame (georeference_frame)
  bool refine = true;            // step 4 (ICP)
  IcpOptions icp;                // step 4's gates, in metres of the city model
  double threshold = 0.5;        // metres: the printed share of points near the mesh
};

struct GeorefResult {
  CityTransform transform;   // city CRS -> scene frame: the final one
  CityTransform start;       // after step 2: GPS alone (EGM96 heights), or the project's frame
  CityTransform searched;    // after step 3
  int epsg = 0;
  size_t images = 0, fixes = 0, without_altitude = 0;
  SimilarityFit gps;                  // over the fixes with an altitude, in metres of the CRS
  std::optional<double> undulation;   // mean geoid height N subtracted from the GPS heights
  std::string geoid;                  // which: "EGM96", or PROJ's transformation to the model's height datum
  double vertical_offset = 0;         // step 3: metres added to the GPS heights
  double yaw_deg = 0;                 // step 3: rotation about the vertical through the points
  double yaw_range_deg = 0;           // how far the yaw was searched (0: not)
  double horizontal_shift = 0;        // step 3: metres the points moved horizontally
  double horizontal_range = 0;        // how far the shift was searched (in x and in y)
  double search_fraction_before = 0, search_fraction = 0;  // share of points within search_gate, before / after
  double scale_sigma = 0;             // the GPS fit's scale standard error, relative (0: not from GPS)
  std::vector<std::string> warnings;  // why the result may not be trusted though ICP ran
  std::optional<AlignmentRefinement> icp;
  std::string icp_problem;            // why step 4 did not run or failed ("" when it ran)
  nlohmann::json record;              // run.json's "georef", georef --json
};

// The GPS positions of the scene's views (nullopt for a photo without one), in view order.
std::vector<std::optional<GpsFix>> scene_gps(const Scene& scene);

// cls::Error when the CRS is unknown,
// fewer than 3 registered photos carry a GPS position with an altitude, or they lie on a line. Logs each
// step with `context` ("georef", "run: georef").
GeorefResult georeference(const Scene& scene, const std::vector<std::optional<GpsFix>>& gps,
                          const SemanticMesh& mesh, const GeorefOptions& options, const std::string& context);

// The same from the frame the scene's source names (Scene::frame: a PIX4Dmapper project's offset and
// output CRS, an OPF scene reference frame) instead of GPS: the frame's CRS taken into the city
// model's through PROJ, then steps 3 (vertical offset and a horizontal shift within
// options.frame_shift_range; no yaw) and 4. cls::Error when the scene names no frame, or PROJ does
// not know its CRS.
GeorefResult georeference_frame(const Scene& scene, const SemanticMesh& mesh, const GeorefOptions& options,
                                const std::string& context);

}  // namespace cls
