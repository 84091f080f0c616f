#include "tiles/tile_merge.h"

#include <ATen/ATen.h>

#include <optional>

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/hash.h"
#include "core/log.h"
#include "language/language_model.h"
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

// How many of `means` lie in the cell of a tile other than `own` (tile index per Gaussian).
int64_t in_other_cells(const at::Tensor& means, const at::Tensor& own, const TilePlan& plan) {
  int64_t n = 0;
  for (size_t t = 0; t < plan.tiles.size(); ++t)
    n += in_cell(means, plan.tiles[t].cell).logical_and(own.ne(static_cast<int>(t))).sum().item<int64_t>();
  return n;
}

GaussianModel concat(const std::vector<GaussianModel>& parts) {
  GaussianModel m;
  auto cat = [&](at::Tensor GaussianModel::*field) {
    std::vector<at::Tensor> ts;
    for (const GaussianModel& p : parts) ts.push_back(p.*field);
    return at::cat(ts, 0);
  };
  m.means = cat(&GaussianModel::means);
  m.log_scales = cat(&GaussianModel::log_scales);
  m.quats = cat(&GaussianModel::quats);
  m.opacity_logits = cat(&GaussianModel::opacity_logits);
  m.sh_dc = cat(&GaussianModel::sh_dc);
  m.sh_rest = cat(&GaussianModel::sh_rest);
  for (const GaussianExtra& e : parts.front().extras) {
    std::vector<at::Tensor> ts;
    for (const GaussianModel& p : parts) ts.push_back(p.extra(e.name)->values);
    m.extras.push_back({e.name, at::cat(ts, 0)});
  }
  return m;
}

GaussianModel select(const GaussianModel& g, const at::Tensor& index) {
  GaussianModel m;
  m.means = g.means.index_select(0, index);
  m.log_scales = g.log_scales.index_select(0, index);
  m.quats = g.quats.index_select(0, index);
  m.opacity_logits = g.opacity_logits.index_select(0, index);
  m.sh_dc = g.sh_dc.index_select(0, index);
  m.sh_rest = g.sh_rest.index_select(0, index);
  for (const GaussianExtra& e : g.extras) m.extras.push_back({e.name, e.values.index_select(0, index)});
  return m;
}

}  // namespace

json merge_tiles(const fs::path& tiles_dir, const fs::path& out_dir) {
  const TilePlan plan = read_tiles_dir(tiles_dir);
  json report = {{"tiles_dir", fs::absolute(tiles_dir).string()}, {"scene", plan.scene.string()}, {"methods", json::object()}};
  for (const char* method : {"citylangsplat", "langsplat"}) {
    std::vector<fs::path> dirs;
    for (const Tile& t : plan.tiles) dirs.push_back(tile_run_dir(tiles_dir, t) / "language" / method);
    const bool any = std::any_of(dirs.begin(), dirs.end(), [](const fs::path& d) { return fs::exists(d / "model.json"); });
    if (!any) continue;
    std::vector<GaussianModel> kept;
    std::array<std::vector<at::Tensor>, 3> latents;
    std::vector<at::Tensor> owners;
    std::optional<LanguageModel> first;
    std::string ae_hash, objects_json;
    json per_tile = json::array();
    int64_t naive_in_other = 0;
    for (size_t t = 0; t < plan.tiles.size(); ++t) {
      if (!fs::exists(dirs[t] / "model.json"))
        fail((dirs[t] / "model.json").string(), "missing: tile " + plan.tiles[t].name + " has not finished training (run-tiles)");
      LanguageModel m = load_language_model(dirs[t].string());
      const std::string hash = file_fnv1a64_hex(dirs[t] / "autoencoder.safetensors");
      const std::string objects = m.objects.to_json().dump();
      if (t == 0) {
        ae_hash = hash, objects_json = objects;
      } else if (hash != ae_hash) {
        fail((dirs[t] / "autoencoder.safetensors").string(),
             "another autoencoder than tile " + plan.tiles[0].name + "'s: the latents cannot be merged (run-tiles trains one shared)");
      } else if (objects != objects_json) {
        fail((dirs[t] / "city_objects.json").string(), "another city-object table than tile " + plan.tiles[0].name + "'s");
      }
      const int64_t n = m.gaussians.size();
      naive_in_other += in_other_cells(m.gaussians.means, at::full({n}, static_cast<int>(t), at::kInt), plan);
      const at::Tensor index = in_cell(m.gaussians.means, plan.tiles[t].cell).nonzero().select(1, 0);
      GaussianModel part = select(m.gaussians, index);
      part.extras.push_back({kTileProperty, at::full({index.size(0)}, static_cast<int>(t), at::kInt)});
      owners.push_back(part.extras.back().values);
      for (int l = 0; l < 3; ++l) latents[l].push_back(m.latents[l].index_select(0, index));
      kept.push_back(std::move(part));
      per_tile.push_back({{"tile", plan.tiles[t].name}, {"gaussians", n}, {"kept", index.size(0)}});
      if (t == 0) first.emplace(std::move(m));
    }
    LanguageModel merged{concat(kept),
                         {at::cat(latents[0], 0), at::cat(latents[1], 0), at::cat(latents[2], 0)},
                         std::move(first->autoencoder),
                         first->info,
                         std::move(first->objects)};
    merged.info["scene"] = plan.scene.string();  // the district: what evaluate, render and view show
    merged.info["merged_from"] = {{"tiles_dir", fs::absolute(tiles_dir).string()}, {"tiles", plan.tiles.size()}};
    const int64_t outside = in_other_cells(merged.gaussians.means, at::cat(owners, 0), plan);
    save_language_model((out_dir / "language" / method).string(), merged);
    report["methods"][method] = {{"gaussians", merged.gaussians.size()},
                                 {"tiles", per_tile},
                                 {"in_another_tiles_cell", outside},
                                 {"naive_union_in_another_tiles_cell", naive_in_other}};
    log_info(cat("merge: ", method, ": ", merged.gaussians.size(), " Gaussians from ", plan.tiles.size(),
                 " tiles; ", outside, " in another tile's cell (a plain union would have ", naive_in_other, ")"));
  }
  if (report["methods"].empty()) fail(tiles_dir.string(), "no tile has a trained language model: run run-tiles first");
  write_text_atomic(out_dir / "merge.json", report.dump(2) + "\n");
  return report;
}

}  // namespace cls
