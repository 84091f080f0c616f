// The georef stage: the city transform from the frame a photogrammetry project names (--georef frame)
// or from the photos' EXIF GPS (--georef gps), pipeline/georeferencing.h; with auto and no city
// transform given, the frame when the scene has one, else GPS when at least 3 photos carry it. Its
// transform is written to the run's georef transform (RunLayout::georef_transform) and used from then
// on (align refines from it).
#include <filesystem>

#include "core/log.h"
#include "pipeline/georeferencing.h"
#include "pipeline/stages.h"

namespace cls {

std::vector<Stage> georef_stages(RunContext& run) {
  Stage s;
  s.name = "georef";
  s.run = [&run] {
    const PipelineConfig& c = run.config;
    const std::filesystem::path out = run.layout.georef_transform();
    std::filesystem::remove(out);  // a transform of an earlier run stays only while it is the one used
    if (c.georef == "off") return StageReport::with(StageStatus::Skipped, "--georef off");
    if (c.georef == "auto" && !c.city_transform.empty())
      return StageReport::with(StageStatus::Skipped, "a city transform is given");
    GeorefOptions options;
    options.crs = c.crs;
    options.threshold = c.align_distance;
    GeorefResult g;
    if (c.georef == "frame" || (c.georef == "auto" && run.scene.frame)) {
      g = georeference_frame(run.scene, run.city.mesh, options, "run: georef");
    } else {
      const std::vector<std::optional<GpsFix>> gps = scene_gps(run.scene);
      size_t usable = 0;
      for (const auto& f : gps) usable += f && f->altitude;
      if (c.georef == "auto" && usable < 3)
        return StageReport::with(StageStatus::Skipped,
                                 cat(usable, " of ", gps.size(), " photos carry a GPS position with an altitude; 3 are needed"));
      g = georeference(run.scene, gps, run.city.mesh, options, "run: georef");
    }
    std::filesystem::create_directories(out.parent_path());
    write_city_transform(out.string(), g.transform);
    run.city.transform = g.transform;
    run.city.vertices = scene_vertices(run.city.mesh, run.city.transform);
    run.city_transform = out.string();
    nlohmann::json record = g.record;
    record["transform"] = out.string();
    log_info("run: georef: using the city transform " + out.string());
    return StageReport::done(record);
  };
  return {s};
}

}  // namespace cls
