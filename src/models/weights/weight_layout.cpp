#include "models/weights/weight_layout.h"

#include <ATen/ATen.h>

#include <set>
#include <sstream>

#include "core/error.h"

namespace cls {
namespace {

bool is_floating(at::ScalarType t) {
  return t == at::kFloat || t == at::kHalf || t == at::kBFloat16 || t == at::kDouble;
}

// The shape a recipe produces from its sources, or an empty optional-like flag when they disagree.
bool derived_shape(const TensorRecipe& r, const std::vector<std::vector<int64_t>>& shapes,
                   std::vector<int64_t>* out) {
  switch (r.op) {
    case TensorRecipe::Op::Same:
      *out = shapes[0];
      return true;
    case TensorRecipe::Op::Transpose:
      if (shapes[0].size() != 2) return false;
      *out = {shapes[0][1], shapes[0][0]};
      return true;
    case TensorRecipe::Op::Concat0: {
      std::vector<int64_t> s = shapes[0];
      if (s.empty()) return false;
      for (size_t i = 1; i < shapes.size(); ++i) {
        if (shapes[i].size() != s.size() || !std::equal(s.begin() + 1, s.end(), shapes[i].begin() + 1)) return false;
        s[0] += shapes[i][0];
      }
      *out = s;
      return true;
    }
  }
  return false;
}

std::string join_names(const std::vector<std::string>& names) {
  std::string s;
  for (const auto& n : names) s += (s.empty() ? "" : " + ") + n;
  return s;
}

MappedWeights map_with(const WeightFile& stored, const std::vector<ExpectedTensor>& expected,
                       const KeyLayout& layout, const std::string& prefix) {
  MappedWeights m{WeightFile(stored.source()), {}};
  m.report.layout = layout.name;
  m.report.prefix = prefix;
  std::set<std::string> used;
  for (const ExpectedTensor& e : expected) {
    const TensorRecipe recipe = layout.recipe(e.name);
    std::vector<std::string> sources;
    std::vector<std::string> absent;
    auto look_up = [&](const std::vector<std::string>& names) {
      sources.clear();
      absent.clear();
      for (const auto& f : names) {
        sources.push_back(prefix + f);
        if (!stored.contains(prefix + f)) absent.push_back(prefix + f);
      }
    };
    look_up(recipe.from);
    if (!absent.empty() && !recipe.fallback.empty()) {
      look_up(recipe.fallback);
      if (!absent.empty()) {
        look_up(recipe.from);
      }
    }
    for (const auto& s : sources)
      if (stored.contains(s)) used.insert(s);
    if (!absent.empty()) {
      m.report.missing.push_back(e.name + (sources.size() == 1 && sources[0] == e.name
                                               ? std::string()
                                               : " (looked for " + join_names(absent) + ")"));
      continue;
    }
    std::vector<std::vector<int64_t>> shapes;
    bool floating = true;
    at::ScalarType dtype = stored.info(sources[0]).dtype;
    for (const auto& s : sources) {
      shapes.push_back(stored.info(s).shape);
      if (!is_floating(stored.info(s).dtype)) {
        floating = false;
        m.report.bad_dtype.push_back(s + ": " + c10::toString(stored.info(s).dtype) + ", expected a float type");
      } else if (stored.info(s).dtype != dtype) {
        floating = false;
        m.report.bad_dtype.push_back(s + ": " + c10::toString(stored.info(s).dtype) + " differs from " +
                                     sources[0] + "'s " + c10::toString(dtype));
      }
    }
    std::vector<int64_t> shape;
    if (!derived_shape(recipe, shapes, &shape) || shape != e.shape) {
      std::string got;
      for (size_t i = 0; i < sources.size(); ++i) got += (i ? ", " : "") + sources[i] + " " + shape_string(shapes[i]);
      m.report.misshaped.push_back(e.name + ": expected " + shape_string(e.shape) + ", stored " + got);
      continue;
    }
    if (!floating) continue;
    // Loaders are copied (they keep the mapping alive), so the result outlives `stored`.
    std::vector<WeightFile::Loader> parts;
    for (const auto& src : sources) parts.push_back(stored.loader(src));
    WeightFile::Loader load;
    switch (recipe.op) {
      case TensorRecipe::Op::Same:
        load = parts[0];
        break;
      case TensorRecipe::Op::Transpose:
        load = [parts] { return parts[0]().t().contiguous(); };
        break;
      case TensorRecipe::Op::Concat0:
        load = [parts] {
          std::vector<at::Tensor> tensors;
          for (const auto& p : parts) tensors.push_back(p());
          return at::cat(tensors, 0);
        };
        break;
    }
    m.weights.add(e.name, TensorInfo{dtype, shape}, std::move(load));
  }
  for (const auto& name : stored.names()) {
    if (used.count(name)) continue;
    const bool inside = name.rfind(prefix, 0) == 0;
    const std::string local = inside ? name.substr(prefix.size()) : name;
    if (inside && layout.ignorable && layout.ignorable(local)) continue;
    m.report.unexpected.push_back(name);
  }
  return m;
}

}  // namespace

std::string LayoutReport::describe() const {
  std::ostringstream s;
  auto section = [&](const char* title, const std::vector<std::string>& items) {
    if (items.empty()) return;
    s << "\n  " << items.size() << ' ' << title << ':';
    for (const auto& i : items) s << "\n    " << i;
  };
  section("missing", missing);
  section("unexpected", unexpected);
  section("mis-shaped", misshaped);
  section("with a wrong dtype", bad_dtype);
  return s.str();
}

MappedWeights map_weights(const WeightFile& stored, const std::vector<ExpectedTensor>& expected,
                          const std::vector<KeyLayout>& layouts) {
  if (layouts.empty()) throw Error("map_weights: no layouts");
  MappedWeights best;
  bool have = false;
  for (const KeyLayout& layout : layouts) {
    for (const std::string prefix : {"", "module.", "model.", "state_dict.", "model.module."}) {
      MappedWeights m = map_with(stored, expected, layout, prefix);
      const auto score = [](const MappedWeights& x) {
        return std::make_pair(x.report.missing.size(), x.report.unexpected.size());
      };
      if (!have || score(m) < score(best)) {
        best = std::move(m);
        have = true;
      }
      if (best.report.ok()) return best;
    }
  }
  return best;
}

WeightFile map_weights_strict(const WeightFile& stored, const std::vector<ExpectedTensor>& expected,
                              const std::vector<KeyLayout>& layouts, const std::string& model) {
  MappedWeights m = map_weights(stored, expected, layouts);
  if (!m.report.ok())
    fail(stored.source(), "weights do not match " + model + " (closest layout: " + m.report.layout +
                              (m.report.prefix.empty() ? "" : ", prefix '" + m.report.prefix + "'") + "):" +
                              m.report.describe());
  return std::move(m.weights);
}

}  // namespace cls
