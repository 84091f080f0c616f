// citylangsplat changes: what the city model lacks and what the photos contradict (src/export/
// opening_proposals.h, enrich_job.h; docs/export.md).
#include "cli/commands.h"
#include "core/args.h"
#include "core/log.h"
#include "export/enrich_job.h"

namespace cls {

int cmd_changes(int argc, char** argv) {
  Args args("changes",
            "Find where the photos and the language field see a window or door the city model lacks, and\n"
            "surfaces the cameras see but the photos put almost no Gaussians on. Every view's rendered level-1\n"
            "field votes per pixel on the plane of the wall (roof, ...) the label map hits there; cells that\n"
            "vote window or door, away from the openings the model has, grouped into regions: each region's\n"
            "rectangle is proposed as a Window/Door surface on that wall with a confidence. Writes the\n"
            "enriched CityJSON 2.0 (as `enrich`, plus the proposals and +clsContradicted surfaces) and\n"
            "changes.json beside it; the report and the viewer show the proposals. See docs/export.md.");
  EnrichOptions o;
  o.changes = true;
  ProposalSettings& p = o.proposals;
  args.positional("RUN", o.run, "a `run` output directory")
      .rest("TEXT", o.queries, "text queries whose mean score each object gets (as `enrich`)")
      .optional()
      .bind("out", o.out, "the CityJSON file to write (empty: RUN/changes/enriched.city.json; changes.json beside it)")
      .bind("method", o.method, "whose language model: citylangsplat or langsplat")
      .bind("city", o.city, "the city model (empty: the one run.json names)")
      .bind("sample-points", o.sample_points, "points spread over the city model's surface for the covered fraction")
      .bind("cell", p.cell, "metres: the vote grid on each surface's plane")
      .bind("min-votes", p.min_votes, "pixel votes a cell needs to count")
      .bind("opening-share", p.opening_share, "a cell is an opening where more than this share of its votes is one")
      .bind("min-area", p.min_area, "square metres: smaller proposals are dropped")
      .bind("plane-distance", p.plane_distance, "metres: votes farther from their surface's plane are dropped")
      .bind("existing-margin", p.existing_margin, "metres around an opening the model has where cells do not count")
      .bind("contradiction-density", o.contradiction_density,
            "a seen surface with fewer Gaussians per m2 than this share of the median surface's is contradicted");
  if (!args.parse(argc, argv)) return 0;
  const nlohmann::json done = run_enrich(o);
  log_info(cat("changes: ", done["proposals"].get<size_t>(), " proposed openings, ", done["contradicted"].get<size_t>(),
               " contradicted surfaces; wrote ", done["file"].get<std::string>(), " and changes.json beside it"));
  return 0;
}

}  // namespace cls
