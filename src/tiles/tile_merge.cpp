#include "tiles/tile_merge.h"

#include <ATen/ATen.h>

#include <algorithm>
#include <optional>

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/hash.h"
#include "core/log.h"
#include "core/run_layout.h"
#include "language/language_model.h"
#include "query/selection.h"
#include "tiles/tile_tasks.h"

namespace cls {
namespace fs = std::filesystem;
using json = nlohmann::json;

namespace {

constexpr const char* kTileProperty = "tile";

// Which Gaussians of `means` (N x 3) lie in `cell`.
at::Tensor in_cell(const at::Tensor& means, const TileCell& c) {
  const at::Tensor x = means.select(1, 0).to(at::kDouble), y = means.select(1, 1).to(at::kDouble);
  return x.ge(c.x0).logical_and(x.lt(c.x1)).logical_and(y.ge(c.y0)).logical_and(y.lt(c.y1));
}

// Pairs of tiles whose cells overlap (0 for a partition): with disjoint cells, a Gaussian in its own
// tile's cell lies in no other. O(tiles^2): 5e7 box tests for 10,000 tiles.
int64_t overlapping_cells(const TilePlan& plan) {
  int64_t n = 0;
  for (size_t a = 0; a < plan.tiles.size(); ++a)
    for (size_t b = a + 1; b < plan.tiles.size(); ++b) {
      const TileCell &p = plan.tiles[a].cell, &q = plan.tiles[b].cell;
      n += std::max(p.x0, q.x0) < std::min(p.x1, q.x1) && std::max(p.y0, q.y0) < std::min(p.y1, q.y1);
    }
  return n;
}

GaussianModel concat(const std::vector<GaussianModel>& parts) {
  auto cat_field = [&](at::Tensor GaussianModel::*field) {
    std::vector<at::Tensor> ts;
    for (const GaussianModel& p : parts) ts.push_back(p.*field);
    return at::cat(ts, 0);
  };
  GaussianModel m;
  m.means = cat_field(&GaussianModel::means);
  m.log_scales = cat_field(&GaussianModel::log_scales);
  m.quats = cat_field(&GaussianModel::quats);
  m.opacity_logits = cat_field(&GaussianModel::opacity_logits);
  m.sh_dc = cat_field(&GaussianModel::sh_dc);
  m.sh_rest = cat_field(&GaussianModel::sh_rest);
  for (const GaussianExtra& e : parts.front().extras) {
    std::vector<at::Tensor> ts;
    for (const GaussianModel& p : parts) {
      const GaussianExtra* x = p.extra(e.name);
      if (!x) throw Error("merge: the tiles' models differ in their PLY property '" + e.name + "'");
      ts.push_back(x->values);
    }
    m.extras.push_back({e.name, at::cat(ts, 0)});
  }
  return m;
}

}  // namespace

json merge_tiles(const fs::path& tiles_dir, const fs::path& out_dir) {
  const TilePlan plan = read_tiles_dir(tiles_dir);
  const std::vector<int> unfinished = pending_tasks(tiles_dir, plan, TilePhase::Train);
  if (!unfinished.empty())
    fail(task_marker(tiles_dir, TilePhase::Train, unfinished.front()).string(),
         "missing or of another plan or settings: tile " + plan.tiles[unfinished.front()].name +
             " has not finished training (citylangsplat tiles status)");
  const int64_t overlaps = overlapping_cells(plan);
  if (overlaps > 0) fail((tiles_dir / "tiles.json").string(), cat(overlaps, " pairs of tile cells overlap: not a partition"));
  const bool sparse = read_run_settings(tiles_dir).pipeline.field == "sparse";
  const std::string shared_hash = sparse ? "" : file_fnv1a64_hex(shared_autoencoder(tiles_dir));

  json report = {{"tiles_dir", fs::absolute(tiles_dir).string()}, {"scene", plan.scene.string()}, {"methods", json::object()}};
  for (const char* method : {"citylangsplat", "langsplat"}) {
    std::vector<fs::path> dirs;
    for (const Tile& t : plan.tiles) dirs.push_back(RunLayout(tile_run_dir(tiles_dir, t)).language(method));
    if (!fs::exists(LanguageModelFiles{dirs.front()}.model_json())) continue;  // e.g. run-tiles --baseline none
    std::vector<GaussianModel> kept;
    std::array<std::vector<at::Tensor>, 3> latents;
    // Sparse: the tiles' codebooks side by side (tile t's bases after those of the tiles before it), each
    // Gaussian's indices moved by its tile's offset; splatting still costs K per Gaussian.
    std::array<std::vector<at::Tensor>, 3> indices, weights, codebooks;
    std::array<int64_t, 3> bases{};
    std::optional<LanguageModel> first;
    std::string objects_json;
    json per_tile = json::array();
    int64_t naive_in_other = 0, outside_own = 0;
    for (size_t t = 0; t < plan.tiles.size(); ++t) {
      LanguageModel m = load_language_model(dirs[t].string());
      if (m.is_sparse() != sparse)
        fail(LanguageModelFiles{dirs[t]}.model_json().string(), cat("a ", m.field(), " language field, but run-tiles trained ",
                                                                   sparse ? "sparse" : "dense", " fields"));
      if (!sparse && file_fnv1a64_hex(LanguageModelFiles{dirs[t]}.autoencoder()) != shared_hash)
        fail(LanguageModelFiles{dirs[t]}.autoencoder().string(),
             "not the shared autoencoder " + shared_autoencoder(tiles_dir).string() + ": the latents cannot be merged");
      const std::string objects = m.objects.to_json().dump();
      if (t == 0) objects_json = objects;
      if (objects != objects_json)
        fail(LanguageModelFiles{dirs[t]}.city_objects().string(), "another city-object table than tile " + plan.tiles[0].name + "'s");
      const int64_t n = m.gaussians.size();
      const at::Tensor index = in_cell(m.gaussians.means, plan.tiles[t].cell).nonzero().select(1, 0);
      naive_in_other += n - index.size(0);  // the cells cover the plane: the rest lies in other cells
      GaussianModel part = subset_gaussians(m.gaussians, index);
      // Counted again on what is kept, as a check of this code (must be 0).
      outside_own += index.size(0) - in_cell(part.means, plan.tiles[t].cell).sum().item<int64_t>();
      part.extras.push_back({kTileProperty, at::full({index.size(0)}, static_cast<int>(t), at::kInt)});
      for (int l = 0; l < 3; ++l) {
        if (!sparse) {
          latents[l].push_back(m.latents[l].index_select(0, index));
          continue;
        }
        const SparseLevel& s = m.sparse[l];
        indices[l].push_back(s.indices.index_select(0, index) + static_cast<int32_t>(bases[l]));
        weights[l].push_back(s.weights.index_select(0, index));
        codebooks[l].push_back(s.codebook);
        bases[l] += s.codebook.size(0);
      }
      kept.push_back(std::move(part));
      per_tile.push_back({{"tile", plan.tiles[t].name}, {"gaussians", n}, {"kept", index.size(0)}});
      if (t == 0) first.emplace(std::move(m));
    }
    LanguageModel merged{concat(kept), {}, std::move(first->autoencoder), first->info, std::move(first->objects), {}};
    for (int l = 0; l < 3; ++l)
      if (sparse)
        merged.sparse[l] = {at::cat(indices[l], 0), at::cat(weights[l], 0), at::cat(codebooks[l], 0)};
      else
        merged.latents[l] = at::cat(latents[l], 0);
    merged.info["scene"] = plan.scene.string();  // the district: what evaluate, render and view show
    merged.info["merged_from"] = {{"tiles_dir", fs::absolute(tiles_dir).string()}, {"tiles", plan.tiles.size()}};
    save_language_model(RunLayout(out_dir).language(method).string(), merged);
    report["methods"][method] = {{"gaussians", merged.gaussians.size()},
                                 {"tiles", per_tile},
                                 {"in_another_tiles_cell", outside_own},
                                 {"naive_union_in_another_tiles_cell", naive_in_other}};
    log_info(cat("merge: ", method, ": ", merged.gaussians.size(), " Gaussians from ", plan.tiles.size(), " tiles; ",
                 outside_own, " in another tile's cell (a plain union would have ", naive_in_other, ")"));
  }
  if (report["methods"].empty()) fail(tiles_dir.string(), "no tile has a trained language model: run run-tiles first");
  write_text_atomic(out_dir / "merge.json", report.dump(2) + "\n");
  return report;
}

}  // namespace cls
