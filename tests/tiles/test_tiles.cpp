// Tiling: the partition on hand-made districts, tiles.json, the task bookkeeping, the task script and
// merge on hand-made tile models (the Slurm scenario is slurm_tiles_test.sh).
#include <ATen/ATen.h>
#include <gtest/gtest.h>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <set>
#include <cstdlib>

#include "citymodel/city_objects.h"
#include "citymodel/scene_city_model.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/subprocess.h"
#include "language/language_model.h"
#include "models/temp_dir.h"
#include "query/relevance.h"
#include "tiles/local_executor.h"
#include "tiles/slurm_executor.h"
#include "tiles/task_script.h"
#include "tiles/tile_merge.h"
#include "tiles/tile_plan.h"
#include "tiles/tile_scene.h"
#include "tiles/tile_tasks.h"

namespace cls {
namespace {
namespace fs = std::filesystem;

using test::TempDir;

// From a dense views x buildings table.
BuildingPixels sparse(const std::vector<std::vector<int64_t>>& dense) {
  BuildingPixels p(dense.size());
  for (size_t v = 0; v < dense.size(); ++v)
    for (size_t b = 0; b < dense[v].size(); ++b)
      if (dense[v][b] > 0) {
        p[v].pixels.push_back({static_cast<int32_t>(b), dense[v][b]});
        p[v].total += dense[v][b];
      }
  return p;
}

// n 6 x 8 m houses in a row at x = 0, 10, 20, ...; view v sees house v with 1000 pixels and each
// neighbour with 100.
std::vector<BuildingFootprint> row_of_houses(int n) {
  std::vector<BuildingFootprint> f;
  for (int b = 0; b < n; ++b) f.push_back({"house" + std::to_string(b), 10.0 * b, 0, 10.0 * b + 6, 8});
  return f;
}
BuildingPixels one_view_per_house(int n) {
  std::vector<std::vector<int64_t>> p(n, std::vector<int64_t>(n, 0));
  for (int v = 0; v < n; ++v) {
    p[v][v] = 1000;
    if (v > 0) p[v][v - 1] = 100;
    if (v + 1 < n) p[v][v + 1] = 100;
  }
  return sparse(p);
}

std::vector<char> set_of(std::initializer_list<int> buildings, size_t n) {
  std::vector<char> in(n, 0);
  for (int b : buildings) in[b] = 1;
  return in;
}

TEST(TilePartition, ViewsJoinWhereTheirShareIsReached) {
  const BuildingPixels p = one_view_per_house(4);
  // View 1 has 1200 building pixels: house 0 is 100/1200 = 8.3% of them.
  EXPECT_EQ(views_of_buildings(set_of({0}, 4), p, 0.05), (std::vector<int>{0, 1}));
  EXPECT_EQ(views_of_buildings(set_of({0}, 4), p, 0.09), (std::vector<int>{0}));
  EXPECT_EQ(views_of_buildings(set_of({1, 2}, 4), p, 0.5), (std::vector<int>{1, 2}));
  EXPECT_TRUE(views_of_buildings(set_of({0}, 4), sparse({{0, 0, 0, 0}, {0, 0, 0, 0}}), 0.0).empty());
}

TEST(TilePartition, ACameraStandingInATilesCellJoinsIt) {
  // Two houses at x = 0..6 and 10..16, cut at x = 8. View 0 stands at x = 3 and sees house 0; view 1
  // stands at x = 5, in house 0's cell, but looks at house 1 only; view 2 stands at x = 30 and sees
  // house 1; view 3 has no known position.
  BuildingPixels p = sparse({{1000, 0}, {0, 1000}, {0, 1000}, {0, 1000}});
  const double x[] = {3, 5, 30};
  for (int v = 0; v < 3; ++v) p[v].camera_x = x[v], p[v].camera_y = 4;
  const TileCell left{-TileCell::kInf, -TileCell::kInf, 8, TileCell::kInf};
  EXPECT_EQ(views_of_tile(set_of({0}, 2), left, p, 0.2), (std::vector<int>{0, 1}));
  EXPECT_EQ(views_of_buildings(set_of({0}, 2), p, 0.2), (std::vector<int>{0}));
  // The partition: budget 3 splits the pair; view 1 is in both tiles, view 3 only in house 1's.
  const auto tiles = partition_buildings(row_of_houses(2), p, 3, 0.2).tiles;
  ASSERT_EQ(tiles.size(), 2u);
  EXPECT_EQ(tiles[0].cell.x1, 8);
  EXPECT_EQ(tiles[0].views, (std::vector<int>{0, 1}));
  EXPECT_EQ(tiles[1].views, (std::vector<int>{1, 2, 3}));
  // Cameras in the cell count toward the budget: two views that see a house each (positions unknown)
  // fit a budget of 3, but two more cameras that stand at x = 1 and see no building make the pair split.
  BuildingPixels crowded = sparse({{1000, 0}, {0, 1000}, {0, 0}, {0, 0}});
  for (int v = 2; v < 4; ++v) crowded[v].camera_x = 1, crowded[v].camera_y = 1;
  const auto split = partition_buildings(row_of_houses(2), crowded, 3, 0.2).tiles;
  ASSERT_EQ(split.size(), 2u);
  EXPECT_EQ(split[0].views, (std::vector<int>{0, 2, 3}));
  EXPECT_EQ(split[1].views, (std::vector<int>{1}));
  EXPECT_EQ(partition_buildings(row_of_houses(2), crowded, 4, 0.2).tiles.size(), 1u);
}

TEST(TilePartition, BisectsAtTheMedianUntilTheImagesFit) {
  // min_share 0.05: a house is seen by its own view and by its neighbours' (100 of 1100 or 1200
  // pixels, >= 8%). All four have 4 views; a budget of 3 cuts the row once, at x = 18 (between the
  // centres 13 and 23): {0, 1} has views 0, 1, 2 and {2, 3} views 1, 2, 3.
  const auto two = partition_buildings(row_of_houses(4), one_view_per_house(4), 3, 0.05).tiles;
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
  const auto four = partition_buildings(row_of_houses(4), one_view_per_house(4), 2, 0.05).tiles;
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
  std::vector<std::vector<int64_t>> dense(20, std::vector<int64_t>(f.size(), 0));
  at::manual_seed(3);
  const at::Tensor r = at::randint(1, 50, {20, static_cast<int64_t>(f.size())}, at::kLong);
  for (int v = 0; v < 20; ++v)
    for (size_t b = 0; b < f.size(); ++b) dense[v][b] = r[v][b].item<int64_t>();
  const auto tiles = partition_buildings(f, sparse(dense), 8, 0.1).tiles;
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

TEST(TilePartition, UnseenBuildingsAreLeftOutAndTheWiderAxisIsCut) {
  // House 2 of 3 is seen by no view: no tile holds it, the other two still split, and the cells cover it.
  const auto p = partition_buildings(row_of_houses(3), sparse({{1000, 0, 0}, {0, 1000, 0}}), 1, 0.5);
  EXPECT_EQ(p.unseen, (std::vector<int>{2}));
  ASSERT_EQ(p.tiles.size(), 2u);
  EXPECT_TRUE(p.tiles[1].cell.contains(23, 4));
  // One building with more views than the budget stays one tile.
  const auto one = partition_buildings(row_of_houses(1), sparse({{5}, {5}, {5}}), 1, 0.1).tiles;
  ASSERT_EQ(one.size(), 1u);
  EXPECT_EQ(one[0].views.size(), 3u);
  // Two houses one above the other (same x centre, y centres 4 and 16): the cut is in y, at 10.
  const std::vector<BuildingFootprint> stacked = {{"a", 0, 0, 6, 8}, {"b", -2, 12, 8, 20}};
  const auto tiles = partition_buildings(stacked, sparse({{9, 0}, {0, 9}}), 1, 0.5).tiles;
  ASSERT_EQ(tiles.size(), 2u);
  EXPECT_EQ(tiles[0].cell.y1, 10);
  EXPECT_EQ(tiles[1].cell.y0, 10);
  EXPECT_TRUE(std::isinf(tiles[0].cell.x0) && std::isinf(tiles[0].cell.x1));
}

TEST(TileScene, ATileKeepsThePointsItsImagesSeeWhereverTheyLie) {
  // Image 1 sees point 10 (1 km away) and 11; image 2 sees 11 and 12.
  ColmapModel all;
  all.cameras[1] = Camera{};
  // Image 1 also claims point 12, whose track does not list it (an inconsistent model): that
  // observation is reset, and point 12 stays out of tile a.
  all.images[1] = {1, {1, 0, 0, 0}, {0, 0, 0}, 1, "a.png", {{5, 5, 10}, {6, 6, 11}, {9, 9, 12}}};
  all.images[2] = {2, {1, 0, 0, 0}, {1, 0, 0}, 1, "b.png", {{7, 7, 11}, {8, 8, 12}}};
  all.points[10] = {10, {1000, 0, 0}, {}, 0, {{1, 0}}};
  all.points[11] = {11, {0, 0, 5}, {}, 0, {{1, 1}, {2, 0}}};
  all.points[12] = {12, {1, 0, 5}, {}, 0, {{2, 1}}};
  const ColmapModel a = tile_colmap(all, {"a.png"});
  EXPECT_EQ(a.images.size(), 1u);
  EXPECT_EQ(a.cameras.size(), 1u);
  ASSERT_EQ(a.points.size(), 2u);
  EXPECT_EQ(a.points.at(10).xyz[0], 1000);
  EXPECT_EQ(a.points.at(11).track, (std::vector<std::pair<uint32_t, uint32_t>>{{1, 1}}));
  EXPECT_EQ(a.images.at(1).points2d[1].point3d_id, 11u);
  EXPECT_EQ(a.images.at(1).points2d[2].point3d_id, ColmapPoint2D{}.point3d_id);
  const ColmapModel b = tile_colmap(all, {"b.png"});
  EXPECT_EQ(b.points.count(10), 0u);
  EXPECT_EQ(b.points.at(11).track, (std::vector<std::pair<uint32_t, uint32_t>>{{2, 0}}));
  EXPECT_EQ(b.points.count(12), 1u);
  EXPECT_TRUE(tile_colmap(all, {"c.png"}).points.empty());
}

TilePlan two_tile_plan() {
  TilePlan plan;
  plan.scene = "/data/district";
  plan.city_model = "/data/city.json";
  plan.lod = 2;
  plan.max_images = 24;
  plan.min_share = 0.2;
  plan.unseen = {"c"};
  plan.tiles.push_back({"tile_000", {"a"}, {-TileCell::kInf, -TileCell::kInf, 10, TileCell::kInf}, {"0.png"}});
  plan.tiles.push_back({"tile_001", {"b"}, {10, -TileCell::kInf, TileCell::kInf, TileCell::kInf}, {"1.png"}});
  return plan;
}

// A published LoD2 tile stores multi-part buildings as Building -> BuildingPart: tiling cuts whole
// Buildings (the ids of the file's <bldg:Building> elements, read from its text), each box holding its
// parts' geometry, so no tile ever gets half a building.
TEST(TileScene, AMultiPartBuildingIsOneFootprintHoldingItsParts) {
  const std::string tile = std::string(CLS_TEST_DATA) + "/citygml/nrw/LoD2_32_329_5730_1_NW.gml";
  const std::string text = read_text_file(tile);
  std::set<std::string> building_ids;
  for (size_t at = text.find("<bldg:Building "); at != std::string::npos; at = text.find("<bldg:Building ", at + 1)) {
    const size_t id = text.find("gml:id=\"", at) + 8;
    building_ids.insert(text.substr(id, text.find('"', id) - id));
  }
  const SceneCityModel city = load_scene_city_model(tile, "", {}, "test");
  const std::vector<BuildingFootprint> footprints = building_footprints(city);
  std::set<std::string> footprint_ids;
  for (const BuildingFootprint& f : footprints) footprint_ids.insert(f.id);
  EXPECT_EQ(footprint_ids, building_ids);
  ASSERT_EQ(footprints.size(), building_ids.size());
  // Every vertex of every triangle lies in the box of the building its level-3 chain ends in.
  const std::vector<int32_t> building = building_of_triangles(city.mesh);
  size_t checked = 0;
  for (size_t t = 0; t < city.mesh.num_triangles(); ++t) {
    ASSERT_GE(building[t], 0) << t;
    const BuildingFootprint& f = footprints[building[t]];
    for (int k = 0; k < 3; ++k) {
      const Vec3f& v = city.vertices[city.mesh.triangles[t][k]];
      EXPECT_TRUE(v[0] >= f.x0 - 1e-3 && v[0] <= f.x1 + 1e-3 && v[1] >= f.y0 - 1e-3 && v[1] <= f.y1 + 1e-3) << f.id;
      ++checked;
    }
  }
  EXPECT_GT(checked, 0u);
}

TEST(TilePlanFile, RoundTripsWithUnboundedSidesAndRefusesBadNames) {
  TempDir dir;
  const TilePlan plan = two_tile_plan();
  write_tile_plan(dir.path / "tiles.json", plan);
  const TilePlan back = read_tiles_dir(dir.path);
  ASSERT_EQ(back.tiles.size(), 2u);
  EXPECT_TRUE(std::isinf(back.tiles[0].cell.x0) && back.tiles[0].cell.x0 < 0);
  EXPECT_EQ(back.tiles[0].cell.x1, 10);
  EXPECT_TRUE(std::isinf(back.tiles[0].cell.y1) && back.tiles[0].cell.y1 > 0);
  EXPECT_EQ(back.tiles[1].buildings, (std::vector<std::string>{"b"}));
  EXPECT_EQ(back.tiles[1].images, (std::vector<std::string>{"1.png"}));
  EXPECT_EQ(back.scene, plan.scene);
  EXPECT_EQ(back.unseen, plan.unseen);
  // The same plan with a tile named out of the folder.
  nlohmann::json j = nlohmann::json::parse(read_text_file(dir.path / "tiles.json"));
  j["tiles"][1]["name"] = "../elsewhere";
  write_text_atomic(dir.path / "tiles.json", j.dump());
  try {
    read_tiles_dir(dir.path);
    ADD_FAILURE() << "a tile named ../elsewhere was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("not a plain directory name"), std::string::npos) << e.what();
  }
  fs::remove(dir.path / "tiles.json");
  EXPECT_THROW(read_tiles_dir(dir.path), Error);
}

// Three tiles (the third a copy of the second under another name): enough for the task bookkeeping.
TilePlan three_tile_plan() {
  TilePlan plan = two_tile_plan();
  plan.tiles.push_back(plan.tiles.back());
  plan.tiles.back().name = "tile_002";
  return plan;
}

void mark_finished(const fs::path& tiles_dir, TilePhase phase, int index) {
  write_text_atomic(task_marker(tiles_dir, phase, index),
                    nlohmann::json({{"fingerprint", tasks_fingerprint(tiles_dir)}}).dump());
}

TEST(TileTasks, MarkersCountOnlyForThePlanAndSettingsTheyRanUnder) {
  TempDir dir;
  TilePlan plan = three_tile_plan();
  write_tile_plan(dir.path / "tiles.json", plan);
  RunTilesSettings s;
  EXPECT_TRUE(write_run_settings(dir.path, s));
  mark_finished(dir.path, TilePhase::Features, 1);
  write_text_atomic(task_marker(dir.path, TilePhase::Features, 2), "{\"fingerprint\": \"of another run\"}");
  EXPECT_EQ(pending_tasks(dir.path, plan, TilePhase::Features), (std::vector<int>{0, 2}));
  EXPECT_EQ(pending_tasks(dir.path, plan, TilePhase::Autoencoder), (std::vector<int>{0}));
  EXPECT_FALSE(write_run_settings(dir.path, s));  // the same settings keep what finished
  EXPECT_EQ(pending_tasks(dir.path, plan, TilePhase::Features).size(), 2u);
  s.pipeline.language_iterations = 7;
  EXPECT_TRUE(write_run_settings(dir.path, s));
  EXPECT_EQ(pending_tasks(dir.path, plan, TilePhase::Features).size(), 3u);
  EXPECT_EQ(read_run_settings(dir.path).pipeline.language_iterations, 7);
  mark_finished(dir.path, TilePhase::Features, 0);
  plan.max_images = 12;  // a new plan: nothing it did not run counts
  write_tile_plan(dir.path / "tiles.json", plan);
  EXPECT_EQ(pending_tasks(dir.path, plan, TilePhase::Features).size(), 3u);
  EXPECT_EQ(parse_tile_phase("train"), TilePhase::Train);
  EXPECT_THROW(parse_tile_phase("merge"), UsageError);
}

// run-tiles carries `run`'s options to every tile, declared by the same bindings, but not those each
// scene has its own (the city model, the output, the shared autoencoder, where to stop).
TEST(TileTasks, RunTilesCarriesRunsOptionsButNotTheScenesOwn) {
  RunTilesSettings s;
  s.pipeline.alpha = 0.3;
  s.pipeline.features.models = "synthetic";
  s.pipeline.lambda_citygml = 0.25;
  s.pipeline.baselines = {};
  s.pipeline.scene_dir = "/district";
  s.pipeline.city = "/district/model.gml";
  s.pipeline.stop_after = "features";
  s.autoencoder_samples = 1234;
  const nlohmann::json j = s.to_json();
  for (const char* own : {"scene", "out", "city", "city_transform", "lod", "taxonomy", "rgb_model", "autoencoder",
                          "stop_after"})
    EXPECT_FALSE(j["pipeline"].contains(own)) << own;
  for (const auto& b : pipeline_options().bindings()) {
    if (b.per_scene) continue;
    EXPECT_TRUE(j["pipeline"].contains(option_key(b.name))) << b.name;
  }
  EXPECT_EQ(j["pipeline"]["alpha"], 0.3);
  EXPECT_EQ(j["pipeline"]["baseline"], nlohmann::json::array());
  const RunTilesSettings back = RunTilesSettings::from_json(j, "run-tiles.json");
  EXPECT_EQ(back.to_json(), j);
  EXPECT_EQ(back.pipeline.features.models, "synthetic");
  EXPECT_EQ(back.autoencoder_samples, 1234);
  nlohmann::json bad = j;
  bad["pipeline"]["models"] = "real";
  EXPECT_THROW(RunTilesSettings::from_json(bad, "run-tiles.json"), Error);
}

TEST(TaskScript, RetriesFailuresButNotInterruptionsAndQuotes) {
  TempDir dir;
  EXPECT_EQ(shell_quote("it's"), "'it'\\''s'");
  EXPECT_EQ(array_spec({0, 1, 2, 5, 7, 8}), "0-2,5,7-8");
  EXPECT_EQ(array_spec({3}), "3");
  // A stand-in binary (in a folder with a space and a quote) that records its task index and fails
  // with the status named in a file.
  const fs::path bin = dir.path / "it's here";
  fs::create_directories(bin);
  const fs::path fake = bin / "fake";
  write_text_atomic(fake, "#!/bin/sh\necho \"$5\" >> \"$(dirname \"$0\")/calls\"\nexit $(cat \"$(dirname \"$0\")/code\")\n");
  fs::permissions(fake, fs::perms::owner_all);
  const fs::path script = write_task_script(dir.path, TilePhase::Train, fake.string(), 2);
  auto run = [&](int code, std::vector<std::string> env) {
    write_text_atomic(bin / "code", std::to_string(code));
    fs::remove(bin / "calls");
    const pid_t pid = spawn_logged({"bash", script.string()}, dir.path / "log", env);
    int status = -1;
    pid_t ended = 0;
    while ((ended = wait_any_child(status, 5)) == 0) {
    }
    EXPECT_EQ(ended, pid);
    return std::pair{status, read_text_file(bin / "calls")};
  };
  EXPECT_EQ(run(0, {"SLURM_ARRAY_TASK_ID=1"}), (std::pair<int, std::string>{0, "1\n"}));
  EXPECT_EQ(run(1, {"SLURM_ARRAY_TASK_ID=1"}), (std::pair<int, std::string>{1, "1\n1\n1\n"}));  // 1 + 2 retries
  EXPECT_EQ(run(130, {"SLURM_ARRAY_TASK_ID=1"}), (std::pair<int, std::string>{130, "1\n"}));  // resumed later
  EXPECT_EQ(run(137, {"SLURM_ARRAY_TASK_ID=1"}), (std::pair<int, std::string>{137, "1\n"}));  // killed
  // A chunk of a phase larger than MaxArraySize: task = array index + offset.
  EXPECT_EQ(run(0, {"SLURM_ARRAY_TASK_ID=3", "CLS_TASK_OFFSET=1000"}), (std::pair<int, std::string>{0, "1003\n"}));
}

TEST(LocalExecutor, RunsThePhasesInOrderAndStopsAfterAFailure) {
  TempDir dir;
  TilePlan plan = three_tile_plan();
  write_tile_plan(dir.path / "tiles.json", plan);
  write_run_settings(dir.path, RunTilesSettings{});
  mark_finished(dir.path, TilePhase::Features, 1);  // finished before: not run again
  // A stand-in binary that logs "phase index OMP_NUM_THREADS" and fails where a file says so.
  const fs::path fake = dir.path / "fake";
  write_text_atomic(fake, "#!/bin/sh\necho \"$4 $5 $OMP_NUM_THREADS\" >> \"$(dirname \"$0\")/calls\"\n"
                          "[ -e \"$(dirname \"$0\")/fail_$4_$5\" ] && exit 3\nexit 0\n");
  fs::permissions(fake, fs::perms::owner_all);
  LocalExecutorOptions o;
  o.binary = fake.string();
  o.jobs = 2;
  o.retries = 0;
  // The executor divides the process's threads (--threads N exports OMP_NUM_THREADS) among its jobs.
  const char* env = std::getenv("OMP_NUM_THREADS");
  const std::string saved = env ? env : "";
  ::setenv("OMP_NUM_THREADS", "6", 1);
  EXPECT_EQ(run_tiles_locally(dir.path, plan, o), 0);
  if (env) ::setenv("OMP_NUM_THREADS", saved.c_str(), 1);
  else ::unsetenv("OMP_NUM_THREADS");
  std::string calls = read_text_file(dir.path / "calls");
  const std::string threads = "3";
  auto lines = [](std::string text) {
    std::vector<std::string> out;
    for (size_t p; (p = text.find('\n')) != std::string::npos; text.erase(0, p + 1)) out.push_back(text.substr(0, p));
    return out;
  };
  std::vector<std::string> got = lines(calls);
  ASSERT_EQ(got.size(), 6u) << calls;  // features 0, 2; autoencoder 0; train 0, 1, 2
  std::sort(got.begin(), got.begin() + 2);
  std::sort(got.begin() + 3, got.end());
  EXPECT_EQ(got, (std::vector<std::string>{"features 0 " + threads, "features 2 " + threads, "autoencoder 0 " + threads,
                                           "train 0 " + threads, "train 1 " + threads, "train 2 " + threads}));
  // A failing feature task: its status comes back, and no later phase starts.
  fs::remove(dir.path / "calls");
  write_text_atomic(dir.path / "fail_features_2", "");
  EXPECT_EQ(run_tiles_locally(dir.path, plan, o), 3);
  got = lines(read_text_file(dir.path / "calls"));
  EXPECT_EQ(got.size(), 2u);
  for (const std::string& line : got) EXPECT_EQ(line.rfind("features", 0), 0u) << line;
  EXPECT_TRUE(fs::exists(task_log(dir.path, TilePhase::Features, "2")));
}

// A tile's language model: Gaussians at the given x positions (y = 0), latents x + level.
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

TEST(TileMerge, KeepsEachTilesOwnCellAndRefusesWhatIsNotShared) {
  TempDir dir;
  const TilePlan plan = two_tile_plan();
  write_tile_plan(dir.path / "tiles.json", plan);
  write_run_settings(dir.path, RunTilesSettings{});
  const fs::path model0 = tile_run_dir(dir.path, plan.tiles[0]) / "language" / "citylangsplat";
  const fs::path model1 = tile_run_dir(dir.path, plan.tiles[1]) / "language" / "citylangsplat";
  // Both tiles trained Gaussians across the seam at x = 10.
  write_tile_model(model0, {1, 9.5, 10, 12}, 1);
  write_tile_model(model1, {8, 10, 11}, 1);
  fs::copy_file(model0 / "autoencoder.safetensors", shared_autoencoder(dir.path));
  mark_finished(dir.path, TilePhase::Train, 0);
  EXPECT_THROW(merge_tiles(dir.path, dir.path / "merged"), Error);  // tile 1 has not finished
  mark_finished(dir.path, TilePhase::Train, 1);

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

  write_tile_model(model1, {8, 10, 11}, 2);  // trained with another autoencoder
  EXPECT_THROW(merge_tiles(dir.path, dir.path / "merged2"), Error);
}

// A tile's sparse language model: Gaussians at the given x positions, K = 2 weights over a tile's own
// codebook of 3 random bases per level.
LanguageModel write_sparse_tile_model(const fs::path& dir, const std::vector<float>& xs, uint64_t seed) {
  const int64_t n = static_cast<int64_t>(xs.size());
  LanguageModel m{make_gaussians(n, 0), {}, std::nullopt, {{"method", "citylangsplat"}}, {}, {}};
  m.gaussians.means.select(1, 0).copy_(at::tensor(xs));
  at::manual_seed(seed);
  for (int l = 0; l < 3; ++l)
    m.sparse[l] = {at::randint(0, 3, {n, 2}, at::kInt), at::rand({n, 2}), at::randn({3, 8})};
  save_language_model(dir.string(), m);
  return m;
}

// Sparse tiles merge with their codebooks side by side: every kept Gaussian answers a text as it did in its
// tile (the same feature cosines), whichever tile's bases it uses.
TEST(TileMerge, SparseTilesKeepEveryGaussiansFeature) {
  TempDir dir;
  const TilePlan plan = two_tile_plan();
  write_tile_plan(dir.path / "tiles.json", plan);
  RunTilesSettings settings;
  settings.pipeline.field = "sparse";
  write_run_settings(dir.path, settings);
  const fs::path model0 = tile_run_dir(dir.path, plan.tiles[0]) / "language" / "citylangsplat";
  const fs::path model1 = tile_run_dir(dir.path, plan.tiles[1]) / "language" / "citylangsplat";
  const LanguageModel a = write_sparse_tile_model(model0, {1, 9.5, 10, 12}, 1);
  const LanguageModel b = write_sparse_tile_model(model1, {8, 10, 11}, 2);
  mark_finished(dir.path, TilePhase::Train, 0);
  mark_finished(dir.path, TilePhase::Train, 1);
  merge_tiles(dir.path, dir.path / "merged");
  const LanguageModel merged = load_language_model((dir.path / "merged" / "language" / "citylangsplat").string());
  ASSERT_TRUE(merged.is_sparse());
  const at::Tensor texts = at::randn({5, 8});
  for (int l = 1; l <= 3; ++l) {
    EXPECT_EQ(merged.sparse[l - 1].codebook.size(0), 6) << "both tiles' bases";
    const at::Tensor got = gaussian_cosines(merged, l, texts);
    // kept: 1, 9.5 of tile 0 (rows 0, 1), 10, 11 of tile 1 (rows 1, 2)
    const at::Tensor want = at::cat({gaussian_cosines(a, l, texts).slice(0, 0, 2), gaussian_cosines(b, l, texts).slice(0, 1, 3)});
    EXPECT_LT((got - want).abs().max().item<float>(), 1e-6) << "level " << l;
  }
  // A dense tile among sparse ones is refused.
  write_tile_model(model1, {8, 10, 11}, 2);
  EXPECT_THROW(merge_tiles(dir.path, dir.path / "merged2"), Error);
}

}  // namespace
}  // namespace cls
