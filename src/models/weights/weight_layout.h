#pragma once
// Key layouts: one canonical name/shape list per model (generated from its config) and, per
// checkpoint flavour, a recipe saying which stored tensors make each canonical tensor (renamed,
// transposed, or q/k/v concatenated). map_weights() applies the recipe lazily and reports every
// missing, unexpected, mis-shaped or non-float tensor by name before any compute.
#include <functional>
#include <string>
#include <vector>

#include "models/weights/weight_file.h"

namespace cls {

struct ExpectedTensor {
  std::string name;            // canonical name
  std::vector<int64_t> shape;
};

// How a canonical tensor is made from stored ones.
struct TensorRecipe {
  enum class Op { Same, Transpose, Concat0 };
  TensorRecipe() = default;
  TensorRecipe(std::vector<std::string> from_, Op op_ = Op::Same, std::vector<std::string> fallback_ = {})
      : from(std::move(from_)), op(op_), fallback(std::move(fallback_)) {}
  std::vector<std::string> from;  // stored names (without the file's common prefix)
  Op op = Op::Same;
  std::vector<std::string> fallback;  // used instead of `from` when some of `from` is absent
};

struct KeyLayout {
  std::string name;  // "openai", "huggingface", ...
  // The recipe for a canonical name.
  std::function<TensorRecipe(const std::string& canonical)> recipe;
  // Stored names this layout knows but does not use (buffers, bookkeeping), so they are not
  // reported as unexpected.
  std::function<bool(const std::string& stored)> ignorable;
};

struct LayoutReport {
  std::string layout;  // the layout that matched best
  std::string prefix;  // stripped from every stored name ("module.", "model." ...), usually ""
  std::vector<std::string> missing;     // canonical names (with the stored names looked for)
  std::vector<std::string> unexpected;  // stored names nothing uses
  std::vector<std::string> misshaped;   // "name: stored [..] expected [..]"
  std::vector<std::string> bad_dtype;   // non-floating tensors where weights are expected
  bool ok() const { return missing.empty() && unexpected.empty() && misshaped.empty() && bad_dtype.empty(); }
  std::string describe() const;  // every problem, one per line
};

struct MappedWeights {
  WeightFile weights;  // canonical names -> lazily derived tensors (only those that could be made)
  LayoutReport report;
};

// Tries every layout (and the prefixes "", "module.", "model.", "state_dict.") and keeps the one
// that makes the most canonical tensors.
MappedWeights map_weights(const WeightFile& stored, const std::vector<ExpectedTensor>& expected,
                          const std::vector<KeyLayout>& layouts);

// map_weights + a cls::Error "<file>: weights do not match <model> (<layout> layout): ..." listing
// every problem, when there is any.
WeightFile map_weights_strict(const WeightFile& stored, const std::vector<ExpectedTensor>& expected,
                              const std::vector<KeyLayout>& layouts, const std::string& model);

}  // namespace cls
