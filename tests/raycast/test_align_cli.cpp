// `citylangsplat align` end to end: a synthetic FZK-Haus scene (terrain, clutter, 1 cm point noise)
// given a city transform 1 m, 2 deg and 1% off; the truth is the transform synth keeps aside.
#include <gtest/gtest.h>

#include "cli_runner.h"

#include <filesystem>
#include <nlohmann/json.hpp>

#include "citymodel/city_model.h"
#include "citymodel/city_transform.h"
#include "raycast/alignment.h"

namespace cls {
namespace {
namespace fs = std::filesystem;

const std::string kFzk = CLS_TEST_DATA "/citygml/fzk-haus/fzk_haus_lod3_v2.gml";

TEST(AlignCli, RecoversTheCityErrorOfASyntheticScene) {
  const fs::path dir = fs::temp_directory_path() / ("cls_align_cli_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  const fs::path scene = dir / "scene";
  test::CliResult r = test::run_cli("-q synth --city " + kFzk + " --out " + scene.string() +
                                    " --views 8 --width 96 --height 72 --gt-density 10 --city-error t=1,r=2,s=0.01");
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string city = " --scene " + scene.string() + " --city " + (scene / "city/fzk_haus_lod3_v2.gml").string() +
                           " --city-transform " + (scene / "city/transform.json").string();
  const fs::path out = dir / "refined.json";
  r = test::run_cli("align" + city + " --out " + out.string() + " --truth " +
                    (scene / "city/transform_true.json").string() + " --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_NEAR(j["error_to_truth"]["before"]["centre"].get<double>(), 1, 1e-6);
  // Most points are terrain and clutter (the median distance stays large); the share on the model grows.
  EXPECT_GT(j["after"]["fraction_within"].get<double>(), j["before"]["fraction_within"].get<double>() + 0.1);

  // The written transform, compared with the truth here rather than trusting the printed figures.
  const SemanticMesh mesh = load_city_model(kFzk, Taxonomy::builtin(), 3);
  const TransformDifference d = transform_difference(read_city_transform(out.string()),
                                                     read_city_transform((scene / "city/transform_true.json").string()), mesh);
  EXPECT_LT(d.max_displacement, 0.03) << r.out;
  EXPECT_LT(d.rotation_deg, 0.05) << r.out;
  EXPECT_NEAR(j["error_to_truth"]["after"]["max_displacement"].get<double>(), d.max_displacement, 1e-9);

  // --rigid keeps the given scale, so the 1% stays.
  r = test::run_cli("align" + city + " --out " + (dir / "rigid.json").string() + " --rigid --json");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NEAR(read_city_transform((dir / "rigid.json").string()).scale(),
              read_city_transform((scene / "city/transform.json").string()).scale(), 1e-12);

  // Bad command lines and a start beyond the capture distance.
  EXPECT_EQ(test::run_cli("align" + city).status, 2);  // no --out
  EXPECT_EQ(test::run_cli("align" + city + " --out " + out.string() + " --capture 0.1 --finest 0.2").status, 2);
  r = test::run_cli("align" + city + " --out " + (dir / "far.json").string() + " --capture 0.001 --finest 0.001");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("raise the capture distance"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "far.json"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace cls
