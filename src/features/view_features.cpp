#include "features/view_features.h"

#include <ATen/ATen.h>

#include <cmath>
#include <string>

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/npy.h"
#include "models/weights/npy_tensor.h"

namespace cls {
namespace fs = std::filesystem;

namespace {

constexpr int kSamLevels = 4;  // default, s, m, l
constexpr int kGmlLevels = 3;  // subpart, part, whole
constexpr int64_t kMaxExactId = int64_t(1) << 24;  // float32 holds every integer up to 2^24

fs::path file_of(const fs::path& dir, const std::string& stem, const std::string& suffix) {
  return dir / (stem + suffix);
}

// Rows of a feature matrix, -1 if it is not a defined 2-D tensor.
int64_t rows_of(const at::Tensor& t) { return t.defined() && t.dim() == 2 ? t.size(0) : -1; }

void check_features(const at::Tensor& t, const std::string& what, const std::string& name) {
  if (!t.defined()) throw Error(what + ": " + name + " is missing");
  if (t.dim() != 2) throw Error(what + ": " + name + " must be N x D, got " + std::to_string(t.dim()) + " dimensions");
  if (t.scalar_type() != at::kFloat) throw Error(what + ": " + name + " must be float32");
}

void check_seg(const std::vector<int32_t>& seg, int levels, int64_t hw, int64_t rows, const std::string& what,
               const std::string& name) {
  if (static_cast<int64_t>(seg.size()) != levels * hw)
    throw Error(what + ": " + name + " has " + std::to_string(seg.size()) + " values, expected " +
                std::to_string(levels) + " x H x W = " + std::to_string(levels * hw));
  for (const int32_t v : seg)
    if (v < -1 || v >= rows)
      throw Error(what + ": " + name + " holds id " + std::to_string(v) + " but there are " + std::to_string(rows) +
                  " feature rows");
}

// Seg map ids as LangSplat stores them: float32.
NpyArray seg_to_npy(const std::vector<int32_t>& seg, int levels, int h, int w, const fs::path& path) {
  std::vector<float> values(seg.size());
  for (size_t i = 0; i < seg.size(); ++i) {
    if (seg[i] >= kMaxExactId) fail(path.string(), "segment id " + std::to_string(seg[i]) + " is not exact in float32");
    values[i] = static_cast<float>(seg[i]);
  }
  return make_npy<float>({levels, h, w}, values);
}

NpyArray features_to_npy(const at::Tensor& t) { return to_npy(t.detach().to(at::kCPU, at::kFloat).contiguous()); }

// A seg map file: `levels` x H x W integer ids in float32 (LangSplat) or int32/int64.
std::vector<int32_t> read_seg(const fs::path& path, int levels, int* h, int* w) {
  const NpyArray a = read_npy(path);
  if (a.shape.size() != 3 || a.shape[0] != levels)
    fail(path.string(), "expected a " + std::to_string(levels) + " x H x W seg map, got shape " +
                            [&] {
                              std::string s = "(";
                              for (size_t i = 0; i < a.shape.size(); ++i) s += (i ? ", " : "") + std::to_string(a.shape[i]);
                              return s + ")";
                            }());
  if (a.dtype != "<f4" && a.dtype != "<i4" && a.dtype != "<i8")
    fail(path.string(), "seg map dtype '" + a.dtype + "' (expected float32 '<f4', or '<i4' / '<i8')");
  *h = static_cast<int>(a.shape[1]);
  *w = static_cast<int>(a.shape[2]);
  const std::vector<double> v = a.to_double();
  std::vector<int32_t> seg(v.size());
  for (size_t i = 0; i < v.size(); ++i) {
    if (!(v[i] == std::floor(v[i])) || v[i] < -1 || v[i] >= static_cast<double>(kMaxExactId))
      fail(path.string(), "seg map value " + std::to_string(v[i]) + " at index " + std::to_string(i) +
                              " is not an id (an integer >= -1)");
    seg[i] = static_cast<int32_t>(v[i]);
  }
  return seg;
}

at::Tensor read_features(const fs::path& path) {
  const NpyArray a = read_npy(path);
  if (a.shape.size() != 2) fail(path.string(), "expected an N x D feature matrix, got " + std::to_string(a.shape.size()) + " dimensions");
  if (a.dtype != "<f4" && a.dtype != "<f2" && a.dtype != "<f8")
    fail(path.string(), "feature dtype '" + a.dtype + "' is not floating point");
  return to_tensor(a).to(at::kFloat);
}

}  // namespace

void ViewFeatures::validate(const std::string& what) const {
  if (height <= 0 || width <= 0)
    throw Error(what + ": image size " + std::to_string(width) + " x " + std::to_string(height) + " is not positive");
  check_features(sam_features, what, "SAM features");
  check_features(gml_features, what, "CityGML features");
  const int64_t hw = int64_t(height) * width;
  check_seg(sam_seg, kSamLevels, hw, sam_features.size(0), what, "SAM seg map");
  check_seg(gml_seg, kGmlLevels, hw, gml_features.size(0), what, "CityGML seg map");
  if (sam_features.size(1) != gml_features.size(1))
    throw Error(what + ": SAM features have " + std::to_string(sam_features.size(1)) + " dimensions, CityGML features " +
                std::to_string(gml_features.size(1)));
  if (static_cast<int64_t>(regions.size()) != gml_features.size(0))
    throw Error(what + ": " + std::to_string(regions.size()) + " regions but " + std::to_string(gml_features.size(0)) +
                " CityGML feature rows");
  for (const CityRegion& r : regions)
    if (r.level < 1 || r.level > 3) throw Error(what + ": region level " + std::to_string(r.level) + " is not 1, 2 or 3");
}

void write_view_features(const fs::path& dir, const std::string& stem, const ViewFeatures& f) {
  const fs::path json_path = file_of(dir, stem, "_gml.json");
  f.validate(json_path.string());
  fs::create_directories(dir);
  // The json marks a complete view: remove a stale one first, write it last.
  fs::remove(json_path);
  const fs::path s = file_of(dir, stem, "_s.npy"), g = file_of(dir, stem, "_gml_s.npy");
  write_npy(s, seg_to_npy(f.sam_seg, kSamLevels, f.height, f.width, s));
  write_npy(file_of(dir, stem, "_f.npy"), features_to_npy(f.sam_features));
  write_npy(g, seg_to_npy(f.gml_seg, kGmlLevels, f.height, f.width, g));
  write_npy(file_of(dir, stem, "_gml_f.npy"), features_to_npy(f.gml_features));

  nlohmann::json regions = nlohmann::json::array();
  for (const CityRegion& r : f.regions)
    regions.push_back({{"level", r.level},
                       {"class", r.class_id},
                       {"class_name", r.class_name},
                       {"instance", r.instance},
                       {"building", r.building},
                       {"pixels", r.pixels}});
  nlohmann::json j = {{"height", f.height},
                      {"width", f.width},
                      {"dim", f.sam_features.size(1)},
                      {"stamp", f.stamp.is_null() ? nlohmann::json::object() : f.stamp},
                      {"regions", regions}};
  write_text_atomic(json_path, j.dump(1) + "\n");
}

ViewFeatures read_view_features(const fs::path& dir, const std::string& stem) {
  const fs::path json_path = file_of(dir, stem, "_gml.json");
  ViewFeatures f;
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(read_text_file(json_path));
    f.height = j.at("height").get<int>();
    f.width = j.at("width").get<int>();
    if (j.contains("stamp")) f.stamp = j.at("stamp");
    for (const auto& r : j.at("regions")) {
      CityRegion c;
      c.level = r.at("level").get<int>();
      c.class_id = r.at("class").get<int>();
      c.class_name = r.at("class_name").get<std::string>();
      c.instance = r.at("instance").get<int64_t>();
      c.building = r.value("building", int64_t(-1));
      c.pixels = r.at("pixels").get<int64_t>();
      f.regions.push_back(std::move(c));
    }
  } catch (const nlohmann::json::exception& e) {
    fail(json_path.string(), std::string("malformed: ") + e.what());
  }

  const auto seg = [&](const std::string& suffix, int levels) {
    const fs::path p = file_of(dir, stem, suffix);
    int h = 0, w = 0;
    std::vector<int32_t> s = read_seg(p, levels, &h, &w);
    if (h != f.height || w != f.width)
      fail(p.string(), "seg map is " + std::to_string(w) + " x " + std::to_string(h) + " but " +
                           json_path.filename().string() + " says " + std::to_string(f.width) + " x " +
                           std::to_string(f.height));
    return s;
  };
  f.sam_seg = seg("_s.npy", kSamLevels);
  f.gml_seg = seg("_gml_s.npy", kGmlLevels);
  const fs::path sf = file_of(dir, stem, "_f.npy"), gf = file_of(dir, stem, "_gml_f.npy");
  f.sam_features = read_features(sf);
  f.gml_features = read_features(gf);
  // Name the file that disagrees with the others.
  try {
    check_seg(f.sam_seg, kSamLevels, int64_t(f.height) * f.width, rows_of(f.sam_features), sf.string(), "SAM seg map");
  } catch (const Error& e) {
    fail(file_of(dir, stem, "_s.npy").string(), std::string("inconsistent with ") + sf.filename().string() + ": " + e.what());
  }
  try {
    check_seg(f.gml_seg, kGmlLevels, int64_t(f.height) * f.width, rows_of(f.gml_features), gf.string(), "CityGML seg map");
  } catch (const Error& e) {
    fail(file_of(dir, stem, "_gml_s.npy").string(), std::string("inconsistent with ") + gf.filename().string() + ": " + e.what());
  }
  if (static_cast<int64_t>(f.regions.size()) != rows_of(f.gml_features))
    fail(json_path.string(), "lists " + std::to_string(f.regions.size()) + " regions but " + gf.filename().string() +
                                 " has " + std::to_string(rows_of(f.gml_features)) + " rows");
  if (f.sam_features.size(1) != f.gml_features.size(1))
    fail(gf.string(), "has " + std::to_string(f.gml_features.size(1)) + " columns but " + sf.filename().string() +
                          " has " + std::to_string(f.sam_features.size(1)));
  f.validate(json_path.string());
  return f;
}

bool view_features_complete(const fs::path& dir, const std::string& stem) {
  for (const char* suffix : {"_s.npy", "_f.npy", "_gml_s.npy", "_gml_f.npy", "_gml.json"})
    if (!fs::is_regular_file(file_of(dir, stem, suffix))) return false;
  return true;
}

}  // namespace cls
