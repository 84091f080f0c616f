// The sparse field's pieces (language/sparse_field.h) against hand cases: the top-K softmax and its
// gradient, the k-means codebook on separated clusters, and the validation of a level.
#include <ATen/ATen.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/error.h"
#include "language/sparse_field.h"

namespace cls {
namespace {

TEST(SparseField, TopKSoftmaxKeepsTheLargestLogitsAndOnlyTheyLearn) {
  const at::Tensor logits = at::tensor({0.5f, 2.0f, -1.0f, 1.0f, 0.0f, 3.0f, 3.5f, -2.0f}).reshape({2, 4}).requires_grad_(true);
  const SparseWeights w = top_k_softmax(logits, 2);
  EXPECT_TRUE(at::equal(w.indices, at::tensor({1, 3, 2, 1}, at::kInt).reshape({2, 2})));
  // softmax over the kept pair: e^2 / (e^2 + e^1), ...
  const double a = std::exp(2.0) / (std::exp(2.0) + std::exp(1.0)), b = std::exp(3.5) / (std::exp(3.5) + std::exp(3.0));
  EXPECT_NEAR(w.weights[0][0].item<double>(), a, 1e-6);
  EXPECT_NEAR(w.weights[0][1].item<double>(), 1 - a, 1e-6);
  EXPECT_NEAR(w.weights[1][0].item<double>(), b, 1e-6);
  (w.weights * at::tensor({1.0f, -3.0f, 2.0f, 0.5f}).reshape({2, 2})).sum().backward();
  const at::Tensor g = logits.grad();
  for (const auto& [row, col] : {std::pair{0, 0}, std::pair{0, 2}, std::pair{1, 0}, std::pair{1, 3}})
    EXPECT_EQ(g[row][col].item<float>(), 0.0f) << "a logit outside the top K got a gradient";
  EXPECT_NE(g[0][1].item<float>(), 0.0f);
  EXPECT_THROW(top_k_softmax(logits, 5), Error);
}

// The one-pass CPU form against at::topk and at::softmax (the reference), weights and the logits' gradient,
// for K from one to all bases, in float and double; and of equal logits the first kept.
TEST(SparseField, TopKSoftmaxEqualsTheReference) {
  at::manual_seed(11);
  for (const at::ScalarType dtype : {at::kFloat, at::kDouble})
    for (const int k : {1, 4, 7, 64}) {
      const at::Tensor base = at::randn({257, 64}, at::TensorOptions().dtype(dtype));
      const at::Tensor upstream = at::randn({257, k}, at::TensorOptions().dtype(dtype));
      const at::Tensor fast_logits = base.clone().requires_grad_(true), ref_logits = base.clone().requires_grad_(true);
      const SparseWeights fast = top_k_softmax(fast_logits, k), ref = top_k_softmax_reference(ref_logits, k);
      EXPECT_TRUE(at::equal(fast.indices, ref.indices)) << "k " << k;
      EXPECT_TRUE(at::allclose(fast.weights, ref.weights, 1e-6, 1e-7)) << "k " << k;
      (fast.weights * upstream).sum().backward();
      (ref.weights * upstream).sum().backward();
      EXPECT_TRUE(at::allclose(fast_logits.grad(), ref_logits.grad(), 1e-5, 1e-7)) << "k " << k;
    }
  const SparseWeights tied = top_k_softmax(at::tensor({1.0f, 2.0f, 2.0f, 2.0f}).reshape({1, 4}), 2);
  EXPECT_TRUE(at::equal(tied.indices, at::tensor({1, 2}, at::kInt).reshape({1, 2})));
  EXPECT_NEAR(tied.weights[0][0].item<double>(), 0.5, 1e-7);
}

TEST(SparseField, KMeansFindsSeparatedClusters) {
  at::manual_seed(3);
  const at::Tensor centres = at::tensor({10.0f, 0.0f, 0.0f, 0.0f, -10.0f, 0.0f, 0.0f, 0.0f, 10.0f}).reshape({3, 3});
  std::vector<at::Tensor> parts;
  for (int c = 0; c < 3; ++c) parts.push_back(centres[c] + 0.1f * at::randn({20 + 5 * c, 3}));
  const at::Tensor rows = at::cat(parts, 0);
  const at::Tensor book = kmeans_codebook(rows, 3, 7);
  ASSERT_EQ(book.sizes(), at::IntArrayRef({3, 3}));
  for (int c = 0; c < 3; ++c) {
    const at::Tensor mean = parts[size_t(c)].mean(0);
    const double nearest = (book - mean).norm(2, {1}).min().item<double>();
    EXPECT_LT(nearest, 1e-4) << "cluster " << c << " has no basis at its mean";
  }
  // Fewer rows than bases: the rows, then near copies.
  const at::Tensor few = kmeans_codebook(rows.slice(0, 0, 2), 4, 1);
  EXPECT_TRUE(at::equal(few.slice(0, 0, 2), rows.slice(0, 0, 2)));
  for (int r = 2; r < 4; ++r)
    EXPECT_LT((rows.slice(0, 0, 2) - few[r]).norm(2, {1}).min().item<double>(), 0.01) << "basis " << r;
  EXPECT_THROW(kmeans_codebook(at::zeros({0, 3}), 2, 1), Error);
}

TEST(SparseField, ValidateNamesWhatIsWrong) {
  SparseLevel s{at::zeros({5, 2}, at::kInt), at::ones({5, 2}), at::ones({4, 3})};
  EXPECT_NO_THROW(s.validate("f", 5, 3));
  EXPECT_THROW(s.validate("f", 6, 3), Error) << "rows of another model";
  EXPECT_THROW(s.validate("f", 5, 4), Error) << "bases of another width";
  s.indices[2][1] = 4;
  EXPECT_THROW(s.validate("f", 5, 3), Error) << "an index past the codebook";
  s.indices[2][1] = 0;
  s.weights[1][0] = std::nanf("");
  EXPECT_THROW(s.validate("f", 5, 3), Error) << "a NaN weight";
}

}  // namespace
}  // namespace cls
