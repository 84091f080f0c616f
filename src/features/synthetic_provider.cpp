#include "features/synthetic_provider.h"

#include <ATen/ATen.h>
#include <opencv2/imgproc.hpp>

#include <cmath>
#include <set>

#include "core/error.h"
#include "core/hash.h"

namespace cls {
namespace {

uint64_t splitmix64(uint64_t& state) {
  uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

double uniform01(uint64_t& state) {  // (0, 1]
  return (static_cast<double>(splitmix64(state) >> 11) + 1.0) * (1.0 / 9007199254740992.0);
}

// A key for an identity: the seed and a description, hashed.
uint64_t key_of(uint64_t seed, const std::string& what) { return fnv1a64(what, fnv1a64(std::to_string(seed))); }

void add_scaled(std::vector<float>& a, const std::vector<float>& b, double s) {
  for (size_t i = 0; i < a.size(); ++i) a[i] += static_cast<float>(s * b[i]);
}

void normalise(std::vector<float>& v) {
  double n = 0;
  for (const float x : v) n += double(x) * x;
  n = std::sqrt(n);
  if (n > 0)
    for (float& x : v) x = static_cast<float>(x / n);
}

at::Tensor to_rows(const std::vector<std::vector<float>>& rows, int dim) {
  at::Tensor t = at::zeros({static_cast<int64_t>(rows.size()), dim}, at::kFloat);
  float* p = t.data_ptr<float>();
  for (size_t r = 0; r < rows.size(); ++r) std::copy(rows[r].begin(), rows[r].end(), p + r * dim);
  return t;
}

}  // namespace

std::vector<float> hashed_unit_vector(uint64_t key, int dim) {
  uint64_t state = key;
  std::vector<float> v(static_cast<size_t>(dim));
  for (int i = 0; i < dim; i += 2) {  // Box-Muller: two normals per pair of uniforms
    const double r = std::sqrt(-2.0 * std::log(uniform01(state)));
    const double phi = 2.0 * M_PI * uniform01(state);
    v[i] = static_cast<float>(r * std::cos(phi));
    if (i + 1 < dim) v[i + 1] = static_cast<float>(r * std::sin(phi));
  }
  normalise(v);
  return v;
}

std::vector<float> noisy_unit_vector(std::vector<float> direction, uint64_t seed, const std::string& who, double noise) {
  add_scaled(direction, hashed_unit_vector(key_of(seed, who), static_cast<int>(direction.size())), noise);
  normalise(direction);
  return direction;
}

SamSegments pack_sam_levels(const std::array<std::vector<int32_t>, 3>& ids,
                            const std::array<std::vector<std::vector<float>>, 3>& features, size_t hw, int dim) {
  SamSegments out;
  out.seg.assign(4 * hw, -1);
  std::vector<std::vector<float>> rows;
  const std::array<int, 4> source = {0, 0, 1, 2};
  for (int k = 0; k < 4; ++k) {
    const int32_t offset = static_cast<int32_t>(rows.size());
    const auto& src = ids[source[k]];
    for (size_t i = 0; i < hw; ++i)
      if (src[i] >= 0) out.seg[k * hw + i] = src[i] + offset;
    rows.insert(rows.end(), features[source[k]].begin(), features[source[k]].end());
  }
  out.features = to_rows(rows, dim);
  return out;
}

SyntheticFeatureProvider::SyntheticFeatureProvider(const SyntheticProviderParams& params, const Taxonomy& taxonomy)
    : params_(params), taxonomy_(taxonomy) {
  if (params_.dim < 2) throw Error("synthetic provider: dim must be at least 2");
  if (params_.tile < 1) throw Error("synthetic provider: tile must be at least 1 px");
  if (params_.sam_confusion < 0 || params_.sam_confusion > 1)
    throw Error("synthetic provider: sam_confusion must be in [0, 1]");
  if (params_.sam_noise < 0 || params_.gml_noise < 0 || params_.text_noise < 0)
    throw Error("synthetic provider: noise levels must be >= 0");
  for (size_t c = 0; c < taxonomy_.classes.size(); ++c)
    for (const std::string& p : taxonomy_.classes[c].prompts) prompt_class_.emplace(p, static_cast<int>(c));
  // Class names count as prompts of their class too ("ground" as well as its listed prompts).
  for (size_t c = 0; c < taxonomy_.classes.size(); ++c) prompt_class_.emplace(taxonomy_.classes[c].name, static_cast<int>(c));
}

SyntheticProviderParams SyntheticFeatureProvider::params_from_spec(const nlohmann::json& spec) {
  SyntheticProviderParams p;
  static const std::set<std::string> known = {"provider", "note", "seed", "dim", "sam_noise",
                                              "sam_confusion", "gml_noise", "text_noise", "tile"};
  for (const auto& [k, v] : spec.items()) {
    (void)v;
    if (!known.count(k)) throw Error("synthetic provider spec: unknown key '" + k + "'");
  }
  try {
    p.seed = spec.value("seed", p.seed);
    p.dim = spec.value("dim", p.dim);
    p.sam_noise = spec.value("sam_noise", p.sam_noise);
    p.sam_confusion = spec.value("sam_confusion", p.sam_confusion);
    p.gml_noise = spec.value("gml_noise", p.gml_noise);
    p.text_noise = spec.value("text_noise", p.text_noise);
    p.tile = spec.value("tile", p.tile);
  } catch (const nlohmann::json::exception& e) {
    throw Error(std::string("synthetic provider spec: ") + e.what());
  }
  return p;
}

nlohmann::json SyntheticFeatureProvider::spec() const {
  return {{"provider", "synthetic"},
          {"seed", params_.seed},
          {"dim", params_.dim},
          {"sam_noise", params_.sam_noise},
          {"sam_confusion", params_.sam_confusion},
          {"gml_noise", params_.gml_noise},
          {"text_noise", params_.text_noise},
          {"tile", params_.tile},
          {"note", "synthetic stand-in for CLIP/SAM (mechanics tests only, not a model of CLIP)"}};
}

std::vector<float> SyntheticFeatureProvider::class_vector(int class_id) const {
  return hashed_unit_vector(key_of(params_.seed, class_id < 0 ? "background" : "class " + std::to_string(class_id)),
                            params_.dim);
}

SamSegments SyntheticFeatureProvider::sam_segments(const FeatureView& view) {
  const int h = view.coverage.rows, w = view.coverage.cols;
  if (h == 0 || w == 0) throw Error(view.name + ": empty coverage mask");
  for (const cv::Mat& l : view.labels)
    if (l.rows != h || l.cols != w || l.type() != CV_16UC1)
      throw Error(view.name + ": label maps must be CV_16UC1 of the coverage mask's size");
  const size_t hw = size_t(h) * w;
  const int num_classes = static_cast<int>(taxonomy_.classes.size());

  // Per level s/m/l: segment ids (-1 = none) and each segment's feature.
  std::array<std::vector<int32_t>, 3> ids;
  std::array<std::vector<std::vector<float>>, 3> feats;
  for (int level = 1; level <= 3; ++level) {
    std::vector<int32_t>& id = ids[level - 1];
    std::vector<std::vector<float>>& f = feats[level - 1];
    id.assign(hw, -1);
    const cv::Mat& labels = view.labels[level - 1];
    // Covered segments: connected components per class.
    std::set<int> present;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        if (view.coverage.at<uint8_t>(y, x) && labels.at<uint16_t>(y, x)) present.insert(labels.at<uint16_t>(y, x));
    for (const int label : present) {
      cv::Mat mask(h, w, CV_8UC1);
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
          mask.at<uint8_t>(y, x) = view.coverage.at<uint8_t>(y, x) && labels.at<uint16_t>(y, x) == label;
      cv::Mat comp;
      const int n = cv::connectedComponents(mask, comp, 8, CV_32S);
      const int first = static_cast<int>(f.size());
      for (int k = 1; k < n; ++k) {
        const std::string who = view.name + "|" + std::to_string(level) + "|" + std::to_string(label) + "|" + std::to_string(k);
        uint64_t state = key_of(params_.seed, "confusion " + who);
        int cls_id = label - 1;
        if (num_classes > 1 && uniform01(state) <= params_.sam_confusion) {
          const int other = static_cast<int>(splitmix64(state) % uint64_t(num_classes - 1));
          cls_id = other >= cls_id ? other + 1 : other;  // any class but the true one
        }
        f.push_back(noisy_unit_vector(class_vector(cls_id), params_.seed, "segment " + who, params_.sam_noise));
      }
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
          if (const int k = comp.at<int32_t>(y, x); k > 0) id[size_t(y) * w + x] = first + k - 1;
    }
    // Uncovered pixels: grid tiles with background features.
    const int tiles_x = (w + params_.tile - 1) / params_.tile;
    std::map<int, int32_t> tile_id;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        if (view.coverage.at<uint8_t>(y, x)) continue;
        const int t = (y / params_.tile) * tiles_x + x / params_.tile;
        auto it = tile_id.find(t);
        if (it == tile_id.end()) {
          const std::string who = view.name + "|" + std::to_string(level) + "|tile " + std::to_string(t);
          it = tile_id.emplace(t, static_cast<int32_t>(f.size())).first;
          f.push_back(noisy_unit_vector(class_vector(-1), params_.seed, "segment " + who, params_.sam_noise));
        }
        id[size_t(y) * w + x] = it->second;
      }
  }

  return pack_sam_levels(ids, feats, hw, params_.dim);
}

at::Tensor SyntheticFeatureProvider::region_features(const FeatureView& view, const std::vector<RegionMask>& regions) {
  std::vector<std::vector<float>> rows;
  for (size_t r = 0; r < regions.size(); ++r) {
    const RegionMask& m = regions[r];
    if (m.class_id < 0 || m.class_id >= static_cast<int>(taxonomy_.classes.size()))
      throw Error(view.name + ": region " + std::to_string(r) + " has no taxonomy class (the synthetic provider needs one)");
    const std::string who = view.name + "|" + std::to_string(m.level) + "|" + std::to_string(m.class_id) + "|" +
                            std::to_string(r) + "|" + std::to_string(cv::countNonZero(m.mask));
    rows.push_back(noisy_unit_vector(class_vector(m.class_id), params_.seed, "region " + who, params_.gml_noise));
  }
  return to_rows(rows, params_.dim);
}

at::Tensor SyntheticFeatureProvider::text_features(const std::vector<std::string>& texts) {
  std::vector<std::vector<float>> rows;
  for (const std::string& t : texts) {
    const auto it = prompt_class_.find(t);
    std::vector<float> v;
    if (it != prompt_class_.end()) {
      v = noisy_unit_vector(class_vector(it->second), params_.seed, "phrase " + t, params_.text_noise);
    } else {
      v = hashed_unit_vector(key_of(params_.seed, "text " + t), params_.dim);
    }
    rows.push_back(std::move(v));
  }
  return to_rows(rows, params_.dim);
}

}  // namespace cls
