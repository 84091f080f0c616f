// citylangsplat query: open-vocabulary text queries on a trained language field.
#include <string>

#include "core/args.h"
#include "cli/commands.h"
#include "core/error.h"
#include "core/strings.h"
#include "query/query_job.h"

namespace cls {

int cmd_query(int argc, char** argv) {
  Args args("query",
            "Query a language model (a `train-language` output directory) with text: per-Gaussian cosine\n"
            "scores s_i = cos(q, g_i) (OUT/scores.ply, one score_<slug> property per text), a selection per\n"
            "text (OUT/selection_<slug>.ply), per-view relevance maps (cosine and LangSplat's relevancy\n"
            "against the canonical phrases object/things/stuff/texture; turbo PNG over [0, 1] + raw .npy)\n"
            "and OUT/query.json. See docs/query.md.");
  args.positional("MODEL", "language model directory (model.json, point_cloud.ply, latents, autoencoder)")
      .positional("TEXT", "query texts", /*required=*/true, /*repeated=*/true)
      .option("out", "", "output directory (empty: MODEL/query)")
      .option("level", "best", "latent level: 1, 2, 3, or best (per text the level with the highest max score)")
      .option("threshold", "", "select Gaussians with score >= T (0.5 when neither this nor --top-k is given)")
      .option("top-k", "", "select the K Gaussians with the highest scores instead")
      .option("views", "all", "views for the relevance maps: all, or comma-separated image names")
      .option("scene", "", "scene directory for the maps (empty: the one recorded in model.json)")
      .option("taxonomy", "", "taxonomy JSON for the feature provider (empty: model.json's, else the built-in one)")
      .option("device", "cpu", "where rendering, decoding and scoring run: cpu or cuda[:N] (needs a CUDA build)")
      .flag("no-maps", "skip the relevance maps (scores and selections only)")
      .flag("objects", "also answer with city objects: the CityGML/CityJSON objects ranked by the mean score of\n"
                       "their Gaussians at the query's level (printed; OUT/objects_<slug>.json and .csv)");
  if (!args.parse(argc, argv)) return 0;

  QueryOptions o;
  o.model_dir = args.get("MODEL");
  o.texts = args.rest();
  o.out_dir = args.get("out");
  o.level = args.get("level");
  if (args.has("threshold") && args.has("top-k")) throw UsageError("query: give --threshold or --top-k, not both");
  if (args.has("top-k")) {
    o.use_top_k = true;
    o.top_k = args.get_int("top-k");
  } else if (args.has("threshold")) {
    o.threshold = args.get_double("threshold");
  }
  if (args.get("views") != "all") {
    o.views = split_commas(args.get("views"));
    if (o.views.empty()) throw UsageError("query: --views needs 'all' or image names");
  }
  o.scene_dir = args.get("scene");
  o.taxonomy_path = args.get("taxonomy");
  o.maps = !args.flag_set("no-maps");
  o.objects = args.flag_set("objects");
  o.device = args.get("device");
  run_query(o);
  return 0;
}

}  // namespace cls
