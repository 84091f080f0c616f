// Tiling: the partition on hand-made districts, tiles.json, the task bookkeeping, the task script and
// merge on hand-made tile models (the Slurm scenario is slurm_tiles_test.sh).
#include <ATen/ATen.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/subprocess.h"
#include "language/language_model.h"
#include "tiles/slurm_executor.h"
#include "tiles/task_script.h"
#include "tiles/tile_merge.h"
#include "tiles/tile_plan.h"
#include "tiles/tile_tasks.h"

namespace cls {
namespace {
namespace fs = std::filesystem;

struct TempDir {
  fs::path path;
  explicit TempDir(const std::string& name)
      : path(fs::temp_directory_path() / ("cls_tiles_" + name + "_" + std::to_string(::getpid()))) {
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~TempDir() { fs::remove_all(path); }
};

// Four 6 x 8 m houses in a row at x = 0, 10, 20, 30; view v sees house v with 1000 pixels and each
// neighbour with 100.
std::vector<BuildingFootprint> row_of_houses(int n) {
  std::vector<BuildingFootprint> f;
  for (int b = 0; b < n; ++b) f.push_back({"house" + std::to_string(b), 10.0 * b, 0, 10.0 * b + 6, 8});
  return f;
}
BuildingPixels one_view_per_house(int n) {
  BuildingPixels p(n, std::vector<int64_t>(n, 0));
  for (int v = 0; v < n; ++v) {
    p[v][v] = 1000;
    if (v > 0) p[v][v - 1] = 100;
    if (v + 1 < n) p[v][v + 1] = 100;
  }
  return p;
}

TEST(TilePartition, ViewsJoinWhereTheirShareIsReached) {
  const BuildingPixels p = one_view_per_house(4);
  // View 1 has 1200 building pixels: house 0 is 100/1200 = 8.3% of them.
  EXPECT_EQ(views_of_buildings({0}, p, 0.05), (std::vector<int>{0, 1}));
  EXPECT_EQ(views_of_buildings({0}, p, 0.09), (std::vector<int>{0}));
  EXPECT_EQ(views_of_buildings({1, 2}, p, 0.5), (std::vector<int>{1, 2}));
  EXPECT_TRUE(views_of_buildings({0}, BuildingPixels(2, std::vector<int64_t>(4, 0)), 0.0).empty());
}

TEST(TilePartition, BisectsAtTheMedianUntilTheImagesFit) {
  // min_share 0.05: a house is seen by its own view and by its neighbours' (100 of 1100 or 1200
  // pixels, >= 8%). All four have 4 views; a budget of 3 cuts the row once, at x = 18 (between the
  // centres 13 and 23): {0, 1} has views 0, 1, 2 and {2, 3} views 1, 2, 3.
  const auto two = partition_buildings(row_of_houses(4), one_view_per_house(4), 3, 0.05);
  ASSERT_EQ(two.size(), 2u);
  EXPECT_EQ(two[0].buildings, (std::vector<int>{0, 1}));
  EXPECT_EQ(two[0].views, (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(two[0].cell.x1, 18);
  EXPECT_TRUE(std::isinf(two[0].cell.x0) && std::isinf(two[0].cell.y0) && std::isinf(two[0].cell.y1));
  EXPECT_EQ(two[1].buildings, (std::vector<int>{2, 3}));
  EXPECT_EQ(two[1].views, (std::vector<int>{1, 2, 3}));
  EXPECT_EQ(two[1].cell.x0, 18);
  // A budget of 2 cuts each half again, at 8 and 28; the inner houses keep their 3 views (one
  // building is never split).
  const auto four = partition_buildings(row_of_houses(4), one_view_per_house(4), 2, 0.05);
  ASSERT_EQ(four.size(), 4u);
  const double cuts[] = {-TileCell::kInf, 8, 18, 28, TileCell::kInf};
  const std::vector<std::vector<int>> views = {{0, 1}, {0, 1, 2}, {1, 2, 3}, {2, 3}};
  for (int t = 0; t < 4; ++t) {
    EXPECT_EQ(four[t].buildings, (std::vector<int>{t}));
    EXPECT_EQ(four[t].cell.x0, cuts[t]);
    EXPECT_EQ(four[t].cell.x1, cuts[t + 1]);
    EXPECT_EQ(four[t].views, views[t]);
  }
}

TEST(TilePartition, CellsPartitionThePlaneAndHoldTheirBuildings) {
  // A 5 x 3 grid with random visibility: every point of the plane lies in exactly one cell, and every
  // building's centre in its own tile's cell.
  std::vector<BuildingFootprint> f;
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 3; ++j) f.push_back({"b", 10.0 * i, 12.0 * j, 10.0 * i + 6, 12.0 * j + 8});
  BuildingPixels p(20, std::vector<int64_t>(f.size(), 0));
  at::manual_seed(3);
  const at::Tensor r = at::randint(0, 50, {20, static_cast<int64_t>(f.size())}, at::kLong);
  for (int v = 0; v < 20; ++v)
    for (size_t b = 0; b < f.size(); ++b) p[v][b] = r[v][b].item<int64_t>();
  const auto tiles = partition_buildings(f, p, 8, 0.1);
  ASSERT_GT(tiles.size(), 1u);
  std::set<int> seen;
  for (size_t t = 0; t < tiles.size(); ++t)
    for (int b : tiles[t].buildings) {
      EXPECT_TRUE(seen.insert(b).second) << "building " << b << " in two tiles";
      EXPECT_TRUE(tiles[t].cell.contains(f[b].cx(), f[b].cy()));
    }
  EXPECT_EQ(seen.size(), f.size());
  for (double x = -20; x < 70; x += 0.75)
    for (double y = -20; y < 50; y += 0.75) {
      int owners = 0;
      for (const PlannedTile& t : tiles) owners += t.cell.contains(x, y);
      ASSERT_EQ(owners, 1) << x << ", " << y;
    }
}

TEST(TilePartition, OneBuildingIsNeverSplitAndCoincidentCentresUseTheOtherAxis) {
  const auto one = partition_buildings(row_of_houses(1), {{5}, {5}, {5}}, 1, 0.1);
  ASSERT_EQ(one.size(), 1u);
  EXPECT_EQ(one[0].views.size(), 3u);
  // Two houses with the same x centre, one above the other: the cut is in y (at 10).
  const std::vector<BuildingFootprint> stacked = {{"a", 0, 0, 6, 8}, {"b", -2, 12, 8, 20}};
  const auto tiles = partition_buildings(stacked, {{9, 0}, {0, 9}}, 1, 0.5);
  ASSERT_EQ(tiles.size(), 2u);
  EXPECT_EQ(tiles[0].cell.y1, 10);
  EXPECT_EQ(tiles[1].cell.y0, 10);
}

TEST(TilePlanFile, RoundTripsWithUnboundedSides) {
  TempDir dir("plan");
  TilePlan plan;
  plan.scene = "/data/district";
  plan.city_model = "/data/city.json";
  plan.lod = 2;
  plan.max_images = 24;
  plan.overlap = 5;
  plan.min_share = 0.2;
  plan.tiles.push_back({"tile_000", {"a", "b"}, {-TileCell::kInf, -TileCell::kInf, 18, TileCell::kInf}, {-5, -5, 21, 13}, {"0001.png"}});
  write_tile_plan(dir.path / "tiles.json", plan);
  const TilePlan back = read_tiles_dir(dir.path);
  ASSERT_EQ(back.tiles.size(), 1u);
  EXPECT_TRUE(std::isinf(back.tiles[0].cell.x0) && back.tiles[0].cell.x0 < 0);
  EXPECT_EQ(back.tiles[0].cell.x1, 18);
  EXPECT_TRUE(std::isinf(back.tiles[0].cell.y1) && back.tiles[0].cell.y1 > 0);
  EXPECT_EQ(back.tiles[0].buildings, (std::vector<std::string>{"a", "b"}));
  EXPECT_EQ(back.scene, plan.scene);
  write_text_atomic(dir.path / "tiles.json", R"({"tiles": [{"name": "../x"}]})");
  EXPECT_THROW(read_tiles_dir(dir.path), Error);
  fs::remove(dir.path / "tiles.json");
  EXPECT_THROW(read_tiles_dir(dir.path), Error);
}

TEST(TileTasks, FinishedTasksAreForgottenWhenTheSettingsChange) {
  TempDir dir("tasks");
  TilePlan plan;
  plan.tiles.resize(3);
  RunTilesSettings s;
  EXPECT_TRUE(write_run_settings(dir.path, s));
  write_text_atomic(task_marker(dir.path, TilePhase::Features, 1), "{}");
  EXPECT_EQ(pending_tasks(dir.path, plan, TilePhase::Features), (std::vector<int>{0, 2}));
  EXPECT_EQ(pending_tasks(dir.path, plan, TilePhase::Autoencoder), (std::vector<int>{0}));
  EXPECT_FALSE(write_run_settings(dir.path, s));  // the same settings keep what finished
  EXPECT_EQ(pending_tasks(dir.path, plan, TilePhase::Features).size(), 2u);
  s.language_iterations = 7;
  EXPECT_TRUE(write_run_settings(dir.path, s));
  EXPECT_EQ(pending_tasks(dir.path, plan, TilePhase::Features).size(), 3u);
  EXPECT_EQ(read_run_settings(dir.path).language_iterations, 7);
  EXPECT_EQ(parse_tile_phase("train"), TilePhase::Train);
  EXPECT_THROW(parse_tile_phase("merge"), UsageError);
}

TEST(TaskScript, RetriesFailuresButNotInterruptionsAndQuotes) {
  TempDir dir("script");
  EXPECT_EQ(shell_quote("it's"), "'it'\\''s'");
  EXPECT_EQ(array_spec({1, 3, 4}), "1,3,4");
  // A stand-in binary that fails with the exit status named in a file and counts its calls.
  const fs::path fake = dir.path / "fake bin";
  write_text_atomic(fake, "#!/bin/sh\necho x >> \"$(dirname \"$0\")/calls\"\nexit $(cat \"$(dirname \"$0\")/code\")\n");
  fs::permissions(fake, fs::perms::owner_all);
  const fs::path script = write_task_script(dir.path, TilePhase::Train, fake.string(), 2);
  auto run = [&](int code) {
    write_text_atomic(dir.path / "code", std::to_string(code));
    fs::remove(dir.path / "calls");
    const pid_t pid = spawn_logged({"bash", script.string()}, dir.path / "log", {"SLURM_ARRAY_TASK_ID=1"});
    int status = -1;
    EXPECT_EQ(wait_any_child(status), pid);
    const std::string calls = read_text_file(dir.path / "calls");
    return std::pair{status, static_cast<int>(std::count(calls.begin(), calls.end(), '\n'))};
  };
  EXPECT_EQ(run(0), (std::pair{0, 1}));
  EXPECT_EQ(run(1), (std::pair{1, 3}));      // 1 + 2 retries
  EXPECT_EQ(run(130), (std::pair{130, 1}));  // interrupted: resumed by the next run, not retried
}

// A tile's language model: n Gaussians at the given x positions (y = 0), latents = x per level.
void write_tile_model(const fs::path& dir, const std::vector<float>& xs, uint64_t ae_seed) {
  const int64_t n = static_cast<int64_t>(xs.size());
  AutoencoderConfig config;
  config.input_dim = 8;
  config.encoder_dims = {4};
  config.decoder_dims = {8};
  LanguageModel m{make_gaussians(n, 0), {}, Autoencoder(config, ae_seed), {{"method", "citylangsplat"}}, {}};
  m.gaussians.means.select(1, 0).copy_(at::tensor(xs));
  for (int l = 0; l < 3; ++l) m.latents[l] = at::tensor(xs).unsqueeze(1).repeat({1, 4}) + l;
  save_language_model(dir.string(), m);
}

TEST(TileMerge, KeepsEachTilesOwnCellAndRefusesOtherAutoencoders) {
  TempDir dir("merge");
  TilePlan plan;
  plan.scene = "/data/district";
  plan.tiles.push_back({"tile_000", {"a"}, {-TileCell::kInf, -TileCell::kInf, 10, TileCell::kInf}, {}, {"0.png"}});
  plan.tiles.push_back({"tile_001", {"b"}, {10, -TileCell::kInf, TileCell::kInf, TileCell::kInf}, {}, {"1.png"}});
  write_tile_plan(dir.path / "tiles.json", plan);
  // Both tiles trained Gaussians across the seam at x = 10.
  write_tile_model(tile_run_dir(dir.path, plan.tiles[0]) / "language" / "citylangsplat", {1, 9.5, 10, 12}, 1);
  write_tile_model(tile_run_dir(dir.path, plan.tiles[1]) / "language" / "citylangsplat", {8, 10, 11}, 1);
  const nlohmann::json r = merge_tiles(dir.path, dir.path / "merged");
  const auto& m = r["methods"]["citylangsplat"];
  EXPECT_EQ(m["gaussians"], 4);  // 1 and 9.5 of tile 0, 10 and 11 of tile 1
  EXPECT_EQ(m["in_another_tiles_cell"], 0);
  EXPECT_EQ(m["naive_union_in_another_tiles_cell"], 3);  // 10 and 12 of tile 0, 8 of tile 1
  const LanguageModel merged = load_language_model((dir.path / "merged" / "language" / "citylangsplat").string());
  const at::Tensor x = merged.gaussians.means.select(1, 0);
  ASSERT_EQ(x.size(0), 4);
  EXPECT_TRUE(at::equal(x, at::tensor({1.0f, 9.5f, 10.0f, 11.0f})));
  EXPECT_TRUE(at::equal(merged.latents[2].select(1, 0), x + 2));  // the latents travel with their Gaussians
  EXPECT_TRUE(at::equal(merged.gaussians.extra("tile")->values, at::tensor({0, 0, 1, 1}, at::kInt)));
  EXPECT_EQ(merged.info["scene"], "/data/district");

  write_tile_model(tile_run_dir(dir.path, plan.tiles[1]) / "language" / "citylangsplat", {8, 10, 11}, 2);
  EXPECT_THROW(merge_tiles(dir.path, dir.path / "merged2"), Error);
}

}  // namespace
}  // namespace cls
