#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "citymodel/taxonomy.h"
#include "core/error.h"

namespace fs = std::filesystem;
using namespace cls;

namespace {

std::string write_temp(const std::string& name, const std::string& text) {
  const fs::path dir = fs::temp_directory_path() / "cls_test_taxonomy";
  fs::create_directories(dir);
  const fs::path p = dir / name;
  std::ofstream(p) << text;
  return p.string();
}

// The error message of loading `text` from a file; "" if it loads.
std::string load_error(const std::string& name, const std::string& text) {
  const std::string path = write_temp(name, text);
  try {
    Taxonomy::load(path);
  } catch (const Error& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find(path), std::string::npos) << msg;
    return msg;
  }
  return "";
}

}  // namespace

TEST(Taxonomy, BuiltinMatchesShippedFile) {
  const Taxonomy tax = Taxonomy::builtin();
  const Taxonomy file = Taxonomy::load(std::string(CLS_TEST_DATA) + "/taxonomy.json");
  ASSERT_EQ(tax.classes.size(), file.classes.size());
  // The paper's Table 3 facade classes that no city model carries: evaluated and queried, never raycast.
  for (const char* name : {"molding", "deco"}) {
    ASSERT_GE(tax.find(name), 0) << name;
    EXPECT_EQ(tax.classes[size_t(tax.find(name))].level, 1) << name;
    EXPECT_TRUE(tax.classes[size_t(tax.find(name))].source_types.empty()) << name;
  }
  EXPECT_EQ(tax.classes[tax.find("window")].level, 1);
  EXPECT_EQ(tax.classes[tax.find("wall")].level, 2);
  EXPECT_EQ(tax.classes[tax.find("building")].level, 3);
  EXPECT_EQ(tax.classes[tax.find("window")].prompts[0], "a window on a building facade");
  EXPECT_EQ(tax.class_of_type("WindowSurface"), tax.find("window"));
  EXPECT_EQ(tax.class_of_type("Window"), tax.find("window"));
  EXPECT_EQ(tax.class_of_type("BuildingPart"), tax.find("building"));
  EXPECT_EQ(tax.class_of_type("FloorSurface"), tax.find("interior"));
  EXPECT_FALSE(tax.class_of_type("Bridge").has_value());
  EXPECT_EQ(tax.find("no such class"), -1);
  const std::array<unsigned char, 3> roof_color{200, 40, 40};
  EXPECT_EQ(tax.classes[tax.find("roof")].color, roof_color);
}

TEST(Taxonomy, LegendJsonListsClassesById) {
  const Taxonomy tax = Taxonomy::builtin();
  const auto legend = nlohmann::json::parse(tax.legend_json());
  ASSERT_EQ(legend.size(), tax.classes.size());
  for (size_t k = 0; k < legend.size(); ++k) {
    EXPECT_EQ(legend[k]["id"], k);
    EXPECT_EQ(legend[k]["name"], tax.classes[k].name);
    EXPECT_EQ(legend[k]["level"], tax.classes[k].level);
    EXPECT_EQ(legend[k]["color"][0], tax.classes[k].color[0]);
    EXPECT_EQ(legend[k]["prompts"], tax.classes[k].prompts);
  }
}

TEST(Taxonomy, FromLegendRestoresWhatTheLegendRecords) {
  const Taxonomy tax = Taxonomy::builtin();
  const Taxonomy back = Taxonomy::from_legend(tax.legend_json(), "legend.json");
  ASSERT_EQ(back.classes.size(), tax.classes.size());
  for (size_t k = 0; k < tax.classes.size(); ++k) {
    EXPECT_EQ(back.classes[k].name, tax.classes[k].name);
    EXPECT_EQ(back.classes[k].level, tax.classes[k].level);
    EXPECT_EQ(back.classes[k].prompts, tax.classes[k].prompts);
    EXPECT_EQ(back.classes[k].color, tax.classes[k].color);
    EXPECT_TRUE(back.classes[k].source_types.empty());
  }
  // Errors name the file: ids out of order, a class without a name, not JSON, not an array.
  for (const char* bad : {R"([{"id":1,"name":"a"}])", R"([{"id":0}])", "[{", R"({"name":"a"})"}) {
    try {
      Taxonomy::from_legend(bad, "model.json");
      ADD_FAILURE() << "accepted: " << bad;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("model.json"), std::string::npos) << e.what();
    }
  }
}

TEST(Taxonomy, UserFileWithOptionalFieldsOmitted) {
  const std::string path = write_temp("minimal.json", R"({"classes":[
      {"name":"facade","level":2,"source_types":["WallSurface","RoofSurface"]},
      {"name":"house","level":3}]})");
  const Taxonomy tax = Taxonomy::load(path);
  ASSERT_EQ(tax.classes.size(), 2u);
  EXPECT_EQ(tax.class_of_type("RoofSurface"), 0);
  EXPECT_EQ(tax.classes[1].prompts, std::vector<std::string>{"house"});  // name as the default prompt
}

TEST(Taxonomy, InvalidFilesGiveErrorsNamingFileAndProblem) {
  EXPECT_NE(load_error("malformed.json", R"({"classes":[{"name":"a","level":2})").find("malformed JSON"),
            std::string::npos);
  EXPECT_NE(load_error("noclasses.json", R"({"klasses":[]})").find("classes"), std::string::npos);
  EXPECT_NE(load_error("noname.json", R"({"classes":[{"level":2}]})").find("name"), std::string::npos);
  EXPECT_NE(load_error("nolevel.json", R"({"classes":[{"name":"a"}]})").find("level"), std::string::npos);
  EXPECT_NE(load_error("level4.json", R"({"classes":[{"name":"a","level":4}]})").find("level 4"),
            std::string::npos);
  EXPECT_NE(load_error("level0.json", R"({"classes":[{"name":"a","level":0}]})").find("level 0"),
            std::string::npos);
  EXPECT_NE(load_error("dupname.json", R"({"classes":[{"name":"a","level":1},{"name":"a","level":2}]})")
                .find("duplicate class name"),
            std::string::npos);
  EXPECT_NE(load_error("duptype.json", R"({"classes":[{"name":"a","level":1,"source_types":["Window"]},
                                                      {"name":"b","level":1,"source_types":["Window"]}]})")
                .find("\"Window\""),
            std::string::npos);
  EXPECT_NE(load_error("badcolor.json", R"({"classes":[{"name":"a","level":1,"color":[1,2,300]}]})").find("color"),
            std::string::npos);
  EXPECT_NE(load_error("badtypes.json", R"({"classes":[{"name":"a","level":1,"source_types":"Window"}]})")
                .find("source_types"),
            std::string::npos);
  EXPECT_THROW(Taxonomy::load("/nonexistent/taxonomy.json"), Error);
}
