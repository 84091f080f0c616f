// synth --drop-openings: the edited city model keeps every polygon (same triangles, same area) and
// labels the dropped windows and doors as the surface they sit in; checked on the real LoD3 files in
// all three encodings against the unedited model read by the same reader.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <set>

#include "citymodel/city_model.h"
#include "citymodel/mesh_stats.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "synth/drop_openings.h"

namespace fs = std::filesystem;
using namespace cls;

namespace {

const std::string kData = CLS_TEST_DATA "/citygml/";
const std::string kFiles[] = {"fzk-haus/fzk_haus_lod3_v2.gml", "fzk-haus/FZK-Haus-LoD3-KIT-IAI-KHH-B36-V1__v3.gml",
                              "citygml4j/lod3_building_v2.gml", "cityjson/texture4.city.json"};

SemanticMesh load_text(const std::string& text, const std::string& name) {
  const fs::path p = fs::temp_directory_path() / ("cls_drop_" + std::to_string(::getpid()) + "_" + name);
  write_text_atomic(p, text);
  SemanticMesh mesh = load_city_model(p.string(), Taxonomy::builtin(), 3);
  fs::remove(p);
  return mesh;
}

std::map<std::string, ClassStats> by_class(const SemanticMesh& mesh) {
  std::map<std::string, ClassStats> out;
  for (const ClassStats& c : compute_mesh_stats(mesh, Taxonomy::builtin()).classes) out[c.name] = c;
  return out;
}

// Openings with faces: the level-1 entities of triangles whose own class is window or door.
size_t openings_with_faces(const SemanticMesh& mesh) {
  const Taxonomy tax = Taxonomy::builtin();
  const int window = tax.find("window"), door = tax.find("door");
  std::set<int> entities;
  for (size_t t = 0; t < mesh.num_triangles(); ++t)
    if (mesh.tri_class[t] == window || mesh.tri_class[t] == door) entities.insert(mesh.tri_entity[t][0]);
  return entities.size();
}

double area_of(const std::map<std::string, ClassStats>& stats, const std::string& name) {
  const auto it = stats.find(name);
  return it == stats.end() ? 0.0 : it->second.area;
}

}  // namespace

TEST(DropOpenings, AllDroppedTheWallsTakeTheirAreaInEveryEncoding) {
  for (const std::string& file : kFiles) {
    SCOPED_TRACE(file);
    const std::string text = read_text_file(kData + file);
    const SemanticMesh before = load_city_model(kData + file, Taxonomy::builtin(), 3);
    const synth::DroppedOpenings d = synth::drop_openings(file, text, 1.0, 1);
    ASSERT_GT(openings_with_faces(before), 0u);
    EXPECT_EQ(d.total, static_cast<int>(openings_with_faces(before)));
    EXPECT_EQ(d.dropped, d.total);
    const SemanticMesh after = load_text(d.text, fs::path(file).filename().string());
    EXPECT_EQ(openings_with_faces(after), 0u);
    EXPECT_EQ(after.num_triangles(), before.num_triangles());
    const auto sb = by_class(before), sa = by_class(after);
    double total_before = 0, total_after = 0;
    for (const auto& [name, c] : sb) total_before += c.area;
    for (const auto& [name, c] : sa) total_after += c.area;
    EXPECT_NEAR(total_after, total_before, 1e-6 * total_before);
    // Every opening here sits in a wall or a roof: those gain exactly the openings' area.
    const double openings = area_of(sb, "window") + area_of(sb, "door");
    EXPECT_GT(openings, 0);
    EXPECT_NEAR(area_of(sa, "wall") + area_of(sa, "roof"), area_of(sb, "wall") + area_of(sb, "roof") + openings,
                1e-6 * total_before);
    // The level-2 label of every face is unchanged (a window already carried its wall's class there).
    std::multiset<int> l2_before, l2_after;
    for (const auto& c : before.tri_level_class) l2_before.insert(c[1]);
    for (const auto& c : after.tri_level_class) l2_after.insert(c[1]);
    EXPECT_TRUE(l2_before == l2_after);
  }
}

TEST(DropOpenings, AFractionIsASeededChoiceOfThatMany) {
  for (const std::string& file : kFiles) {
    SCOPED_TRACE(file);
    const std::string text = read_text_file(kData + file);
    const synth::DroppedOpenings a = synth::drop_openings(file, text, 0.3, 1), b = synth::drop_openings(file, text, 0.3, 1);
    EXPECT_EQ(a.text, b.text);
    EXPECT_EQ(a.dropped, static_cast<int>(std::lround(0.3 * a.total)));
    const SemanticMesh after = load_text(a.text, fs::path(file).filename().string());
    EXPECT_EQ(static_cast<int>(openings_with_faces(after)), a.total - a.dropped);
    // Another seed drops another set (one of a few seeds does, whatever the file's count).
    bool differs = false;
    for (uint64_t seed = 2; seed < 6 && !differs; ++seed) differs = synth::drop_openings(file, text, 0.3, seed).text != a.text;
    EXPECT_TRUE(differs);
    // Nothing dropped: the same model (the writer may reformat, the reader must not see a difference).
    const synth::DroppedOpenings none = synth::drop_openings(file, text, 0, 1);
    EXPECT_EQ(none.dropped, 0);
    EXPECT_EQ(openings_with_faces(load_text(none.text, fs::path(file).filename().string())), static_cast<size_t>(a.total));
  }
}

TEST(DropOpenings, BadInputsAreRefused) {
  const std::string gml = read_text_file(kData + kFiles[0]);
  EXPECT_THROW(synth::drop_openings("x.gml", gml, 1.5, 1), UsageError);
  EXPECT_THROW(synth::drop_openings("x.gml", gml, -0.1, 1), UsageError);
  try {
    synth::drop_openings("broken.gml", gml.substr(0, gml.size() / 2), 0.3, 1);
    FAIL() << "a truncated file was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("broken.gml"), std::string::npos) << e.what();
  }
  EXPECT_THROW(synth::drop_openings("x.json", "{\"type\":\"CityJSON\"", 0.3, 1), Error);
  EXPECT_THROW(synth::drop_openings("x.jsonl", "{\"type\":\"CityJSON\"}\n{\"type\":\"CityJSONFeature\"}\n", 0.3, 1), UsageError);
}
