// `citylangsplat citymodel stats|export` as a user runs it: stdout, stderr, exit status, files.
#include <gtest/gtest.h>

#include "cli_runner.h"
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "core/atomic_file.h"

namespace fs = std::filesystem;

namespace {

const std::string kData = CLS_TEST_DATA;
const std::string kBroken = std::string(CLS_TEST_FIXTURES) + "/broken";


class CityModelCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("cls_cli_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

}  // namespace

TEST_F(CityModelCli, StatsJsonIsExactlyOneObject) {
  const cls::test::CliResult r = cls::test::run_cli("citymodel stats '" + kData + "/citygml/cityjson/texture4.city.json' --json");
  ASSERT_EQ(r.status, 0) << r.err;
  ASSERT_FALSE(r.out.empty());
  EXPECT_EQ(r.out.back(), '\n');
  EXPECT_EQ(r.out.find('\n'), r.out.size() - 1);  // one line
  const auto j = nlohmann::json::parse(r.out);    // throws if anything but one JSON value
  EXPECT_EQ(j["format"], "CityJSON");
  EXPECT_EQ(j["version"], "2.0");
  EXPECT_EQ(j["crs"], "http://www.opengis.net/def/crs/EPSG/0/3068");
  EXPECT_EQ(j["buildings"], 1);
  EXPECT_EQ(j["origin"].size(), 3u);
  EXPECT_EQ(j["classes"]["window"]["objects"], 15);
  EXPECT_EQ(j["classes"]["door"]["objects"], 6);
  EXPECT_EQ(j["classes"]["wall"]["objects"], 9);
  EXPECT_EQ(j["classes"]["roof"]["objects"], 3);
  EXPECT_EQ(j["classes"]["ground"]["objects"], 1);
  size_t triangles = 0;
  for (const auto& [name, c] : j["classes"].items()) triangles += c["triangles"].get<size_t>();
  EXPECT_EQ(j["triangles"].get<size_t>(), triangles);
}

TEST_F(CityModelCli, StatsTableAndLodOption) {
  const cls::test::CliResult r = cls::test::run_cli("citymodel stats '" + kData + "/citygml/cityjson/multi_lod.json' --lod 1");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("LoD 1"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("surface"), std::string::npos) << r.out;
  const cls::test::CliResult bad = cls::test::run_cli("citymodel stats '" + kData + "/citygml/cityjson/multi_lod.json' --lod 5");
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.err.find("--lod"), std::string::npos) << bad.err;
  const cls::test::CliResult help = cls::test::run_cli("citymodel export --help");
  EXPECT_EQ(help.status, 0);
  EXPECT_NE(help.out.find("(default: highest)"), std::string::npos) << help.out;
}

TEST_F(CityModelCli, ExportWritesAPly) {
  const fs::path out = dir_ / "station.ply";
  const cls::test::CliResult r = cls::test::run_cli("citymodel export '" + kData + "/citygml/cityjson/texture4.city.json' --out '" +
                            out.string() + "'");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(r.out.empty());  // diagnostics go to stderr
  const std::string ply = cls::read_text_file(out);
  EXPECT_EQ(ply.rfind("ply\nformat binary_little_endian 1.0\n", 0), 0u);
  EXPECT_NE(ply.find("element face 678\n"), std::string::npos);
}

// Each broken input: exit status 1, "error: <file>: ..." as the last line of stderr, no output file
// left behind.
TEST_F(CityModelCli, BrokenInputsFailCleanly) {
  const fs::path out = dir_ / "out.ply";
  const std::string good = kData + "/citygml/cityjson/texture4.city.json";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {kBroken + "/cityjson_truncated.json", ""},
      {kBroken + "/cityjson_bad_transform.json", ""},
      {kBroken + "/cityjson_nan_coordinate.json", ""},
      {kBroken + "/cityjson_null_coordinate.json", ""},
      {kBroken + "/cityjson_vertex_out_of_range.json", ""},
      {kBroken + "/cityjsonseq_truncated.jsonl", ""},
      {kBroken + "/unknown_format.stl", ""},
      {kBroken + "/does_not_exist.json", ""},
      {kData + "/citygml/citygml4j/invalid_building_v3.gml", ""},
      {good, kBroken + "/city_transform_not_similarity.json"},
  };
  for (const auto& [input, transform] : cases) {
    std::string args = "citymodel export '" + input + "' --out '" + out.string() + "'";
    if (!transform.empty()) args += " --city-transform '" + transform + "'";
    const cls::test::CliResult r = cls::test::run_cli(args);
    const std::string named = transform.empty() ? input : transform;
    EXPECT_EQ(r.status, 1) << args << "\n" << r.err;
    // The last line of stderr is the error (progress lines may come before it).
    const size_t last_line = r.err.rfind('\n', r.err.size() >= 2 ? r.err.size() - 2 : 0);
    const std::string last = r.err.substr(last_line == std::string::npos ? 0 : last_line + 1);
    EXPECT_EQ(last.rfind("error: " + named + ": ", 0), 0u) << r.err;
    EXPECT_FALSE(fs::exists(out)) << args;
    const cls::test::CliResult stats = cls::test::run_cli("citymodel stats '" + input + "' --json");
    if (transform.empty()) {
      EXPECT_EQ(stats.status, 1) << input;
      EXPECT_TRUE(stats.out.empty()) << stats.out;
    }
  }
  // No temporary files either.
  EXPECT_TRUE(fs::is_empty(dir_));
}
