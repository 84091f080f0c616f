// citylangsplat query: open-vocabulary text queries on a trained language field.
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/args.h"
#include "cli/commands.h"
#include "core/error.h"
#include "core/strings.h"
#include "query/query_job.h"

namespace cls {
namespace {

// --views: "all" (no names) or comma-separated image names.
Codec<std::vector<std::string>> views_codec() {
  Codec<std::vector<std::string>> c = default_codec<std::vector<std::string>>();
  c.text = [text = c.text](const std::vector<std::string>& views) { return views.empty() ? "all" : text(views); };
  c.parse = [](const std::string& s) {
    if (s == "all") return std::vector<std::string>();
    std::vector<std::string> views = split_commas(s);
    if (views.empty()) throw std::invalid_argument("needs 'all' or image names");  // "query: --views needs ..."
    return views;
  };
  return c;
}

}  // namespace

int cmd_query(int argc, char** argv) {
  Args args("query",
            "Query a language model (a `train-language` output directory) with text: per-Gaussian cosine\n"
            "scores s_i = cos(q, g_i) (OUT/scores.ply, one score_<slug> property per text), a selection per\n"
            "text (OUT/selection_<slug>.ply), per-view relevance maps (cosine and LangSplat's relevancy\n"
            "against the canonical phrases object/things/stuff/texture; turbo PNG over [0, 1] + raw .npy)\n"
            "and OUT/query.json. See docs/query.md.");
  QueryOptions o;
  std::optional<double> threshold;
  std::optional<int64_t> top_k;
  args.positional("MODEL", o.model_dir, "language model directory (model.json, point_cloud.ply, latents, autoencoder)")
      .rest("TEXT", o.texts, "query texts")
      .bind("out", o.out_dir, "output directory (empty: MODEL/query)")
      .bind("level", o.level, "latent level: 1, 2, 3, or best (per text the level with the highest max score)")
      .bind("threshold", threshold, "select Gaussians with score >= T (0.5 when neither this nor --top-k is given)",
            optional_codec<double>())
      .bind("top-k", top_k, "select the K Gaussians with the highest scores instead", optional_codec<int64_t>())
      .bind("views", o.views, "views for the relevance maps: all, or comma-separated image names", views_codec())
      .bind("scene", o.scene_dir, "scene directory for the maps (empty: the one recorded in model.json)")
      .bind("taxonomy", o.taxonomy_path, "taxonomy JSON for the feature provider (empty: model.json's, else the built-in one)")
      .bind("device", o.device, "where rendering, decoding and scoring run: cpu or cuda[:N] (needs a CUDA build)")
      .flag("no-maps", o.maps, "skip the relevance maps (scores and selections only)", false)
      .flag("objects", o.objects, "also answer with city objects: the CityGML/CityJSON objects ranked by the mean score of\n"
                                  "their Gaussians at the query's level (printed; OUT/objects_<slug>.json and .csv)");
  if (!args.parse(argc, argv)) return 0;
  if (threshold && top_k) throw UsageError("query: give --threshold or --top-k, not both");
  if (top_k) {
    o.use_top_k = true;
    o.top_k = *top_k;
  } else if (threshold) {
    o.threshold = *threshold;
  }
  run_query(o);
  return 0;
}

}  // namespace cls
