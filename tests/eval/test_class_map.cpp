// Ground truth as users have it: a labelled LAS cloud (tests/hand_las.h, written from the spec's tables)
// whose classification or extra-bytes label a class map turns into the taxonomy's classes; the shipped
// ZAHA map against the taxonomy; errors that name the file and the label.
#include <gtest/gtest.h>

#include <filesystem>
#include <set>

#include "core/atomic_file.h"
#include "error_of.h"
#include "eval/class_map.h"
#include "eval/labelled_points.h"
#include "hand_las.h"
#include "models/temp_dir.h"

namespace fs = std::filesystem;
using namespace cls;

namespace {

const Taxonomy& taxonomy() {
  static const Taxonomy t = Taxonomy::builtin();
  return t;
}

fs::path write_map(const fs::path& dir, const std::string& text) {
  const fs::path p = dir / "map.json";
  write_text_atomic(p, text);
  return p;
}

}  // namespace

TEST(ClassMap, LabelsMapToTaxonomyIdsAndNullToUnlabelled) {
  test::TempDir dir("class_map");
  const ClassMap m = read_class_map(write_map(dir.path, R"({"name": "x", "classes": {"0": "wall", "7": "window",
                                                          "-3": null}})").string(), taxonomy());
  EXPECT_EQ(m.name, "x");
  ASSERT_EQ(m.classes.size(), 3u);
  EXPECT_EQ(m.classes.at(0), taxonomy().find("wall"));
  EXPECT_EQ(m.classes.at(7), taxonomy().find("window"));
  EXPECT_EQ(m.classes.at(-3), -1);
  EXPECT_EQ(map_labels(m, {7, 0, -3, 7}, "cloud.las", "classification"),
            (std::vector<int32_t>{taxonomy().find("window"), taxonomy().find("wall"), -1, taxonomy().find("window")}));
  // A label the map does not list names the cloud, the field, the value and the map.
  const std::string message = test::error_of([&] { map_labels(m, {0, 5}, "cloud.las", "classification"); });
  for (const std::string& part : {std::string("cloud.las"), std::string("classification value 5"), m.file})
    EXPECT_NE(message.find(part), std::string::npos) << part << ": " << message;
  EXPECT_NE(test::error_of([&] { map_labels(m, {0.5}, "cloud.las", "label"); }).find("not an integer"), std::string::npos);
}

TEST(ClassMap, BadMapsAreRefusedNamingTheFileAndTheLabel) {
  test::TempDir dir("class_map_bad");
  const std::vector<std::pair<std::string, std::string>> cases = {
      {R"({"classes": {"1": "spire"}})", "label 1 maps to 'spire'"},
      {R"({"classes": {"one": "wall"}})", "'one' is not an integer"},
      {R"({"classes": {"1": 4}})", "not a class name or null"},
      {R"({"classes": {}})", "needs \"classes\""},
      {R"({"classes": )", "not JSON"},
  };
  for (const auto& [text, needle] : cases) {
    const fs::path p = write_map(dir.path, text);
    const std::string message = test::error_of([&] { read_class_map(p.string(), taxonomy()); });
    EXPECT_NE(message.find(p.string()), std::string::npos) << message;
    EXPECT_NE(message.find(needle), std::string::npos) << needle << ": " << message;
  }
}

// Every class the shipped ZAHA map names is in the built-in taxonomy, and it covers the paper's Table 3
// classes (wall, window, door, molding, deco, roof, interior).
TEST(ClassMap, TheShippedZahaMapCoversThePapersTable3Classes) {
  const ClassMap m = read_class_map(CLS_TEST_DATA "/class-maps/zaha-lofg3.json", taxonomy());
  std::set<int32_t> targets;
  for (const auto& [label, id] : m.classes) targets.insert(id);
  for (const char* name : {"wall", "window", "door", "molding", "deco", "roof", "interior"})
    EXPECT_TRUE(targets.count(taxonomy().find(name))) << name;
}

// A LAS cloud read through a class map: its classification, or an extra-bytes field; without a map a
// LAS cloud is refused (its codes are not taxonomy ids), and a code the map lacks names the file.
TEST(ClassMap, ALasCloudIsReadThroughTheMap) {
  test::TempDir dir("class_map_las");
  std::vector<test::HandLasPoint> points(6);
  for (size_t i = 0; i < points.size(); ++i) {
    points[i].x = int32_t(100 * i);
    points[i].classification = uint8_t(i % 3);  // 0 wall, 1 window, 2 unlabelled
    points[i].label = uint16_t(i % 3 == 0 ? 1 : 0);   // 1 window, 0 wall
  }
  const fs::path las = dir.path / "gt.las";
  write_text_atomic(las, test::hand_las(7, points, {0.01, 0.01, 0.01}, {1000, 2000, 3000}, true));
  const ClassMap m = read_class_map(
      write_map(dir.path, R"({"classes": {"0": "wall", "1": "window", "2": null}})").string(), taxonomy());
  const int wall = taxonomy().find("wall"), window = taxonomy().find("window");
  const LabelledPoints by_class = read_labelled_points(las.string(), "", &m);
  ASSERT_EQ(by_class.size(), points.size());
  for (size_t i = 0; i < points.size(); ++i) {
    EXPECT_EQ(by_class.labels[i], i % 3 == 0 ? wall : i % 3 == 1 ? window : -1) << i;
    EXPECT_EQ(by_class.positions[i].x, 1000 + points[i].x * 0.01);
    EXPECT_EQ(by_class.positions[i].z, 3000.0);
  }
  const LabelledPoints by_field = read_labelled_points(las.string(), "label", &m);
  for (size_t i = 0; i < points.size(); ++i) EXPECT_EQ(by_field.labels[i], i % 3 == 0 ? window : wall) << i;

  const std::string no_map = test::error_of([&] { read_labelled_points(las.string()); });
  EXPECT_NE(no_map.find(las.string()), std::string::npos) << no_map;
  EXPECT_NE(no_map.find("--class-map"), std::string::npos) << no_map;
  const ClassMap partial = read_class_map(write_map(dir.path, R"({"classes": {"0": "wall"}})").string(), taxonomy());
  const std::string unmapped = test::error_of([&] { read_labelled_points(las.string(), "", &partial); });
  EXPECT_NE(unmapped.find(las.string()), std::string::npos) << unmapped;
  EXPECT_NE(unmapped.find("classification value 1"), std::string::npos) << unmapped;
  const std::string missing = test::error_of([&] { read_labelled_points(las.string(), "zaha", &m); });
  EXPECT_NE(missing.find("no extra-bytes field 'zaha'"), std::string::npos) << missing;
}
