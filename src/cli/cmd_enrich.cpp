// citylangsplat enrich: the run's city model as CityJSON 2.0 with what the run learned of each object
// (src/export/enrich_job.h, docs/export.md).
#include "cli/commands.h"
#include "core/args.h"
#include "core/log.h"
#include "export/enrich_job.h"

namespace cls {

int cmd_enrich(int argc, char** argv) {
  Args args("enrich",
            "Write the city model of a run as CityJSON 2.0 enriched with what the run learned: for every\n"
            "CityObject (building, part, installation) and semantic surface (wall, roof, window, door, ...) in\n"
            "how many views and pixels the label maps show it, the fraction of its surface some view sees, how\n"
            "many Gaussians belong to it, the mean scores of its Gaussians for the classes of its level and\n"
            "for the TEXT queries given. Attributes of our CityJSON Extension (citylangsplat.ext.json, written\n"
            "beside OUT); the geometry is the city model's own polygons. Any input format (CityGML 1-3,\n"
            "CityJSON). See docs/export.md.");
  EnrichOptions o;
  args.positional("RUN", o.run, "a `run` output directory")
      .rest("TEXT", o.queries, "text queries whose mean score each object gets")
      .optional()
      .bind("out", o.out, "the CityJSON file to write (empty: RUN/enriched.city.json); ending in .jsonl: CityJSONSeq, a\n"
                          "feature per building, for models too large to read whole")
      .bind("method", o.method, "whose language model scores the objects: citylangsplat or langsplat")
      .bind("city", o.city, "the city model (empty: the one run.json names; it must be the one the label maps were made from)")
      .bind("sample-points", o.sample_points, "points spread over the city model's surface for the covered fraction");
  if (!args.parse(argc, argv)) return 0;
  const nlohmann::json done = run_enrich(o);
  log_info(cat("enrich: wrote ", done["file"].get<std::string>(), " (", done["objects"].get<int64_t>(), " CityObjects and ",
               done["surfaces"].get<int64_t>(), " semantic surfaces enriched, ", done["queries"].size(), " queries)"));
  return 0;
}

}  // namespace cls
