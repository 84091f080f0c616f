#pragma once
// A sparse language field (issue 36, after LangSplatV2): per Gaussian and level K weights over a
// codebook of L bases in the features' own space (CLIP's 512-d), so no decoder. A Gaussian's feature is
// f_i = sum_k w_ik b_{j_ik}; a pixel's is the blend of those, i.e. its rendered L-vector of weights times
// the codebook. Rendering splats K values per Gaussian (rasterize_sparse_features); a cosine with a
// direction q needs only B q (L values) and the Gram matrix B B^T, never the D-d features.
#include <ATen/core/Tensor.h>

#include <cstdint>
#include <random>
#include <string>

namespace cls {

struct SparseLevel {
  at::Tensor indices;   // N x K int32: the bases of each Gaussian's weights, in [0, L)
  at::Tensor weights;   // N x K float32
  at::Tensor codebook;  // L x D float32: the bases
  bool defined() const { return codebook.defined(); }
  int64_t size() const { return weights.size(0); }
  // cls::Error naming `what` unless the shapes, dtypes and indices agree (n Gaussians, D-d bases).
  void validate(const std::string& what, int64_t n, int64_t d) const;
};

// The top-K entries of each row of `logits` (N x L) and their softmax, LangSplatV2's sparse coefficients:
// indices int32 N x K, weights N x K differentiable with respect to the logits (the others get no gradient).
struct SparseWeights {
  at::Tensor indices, weights;
};
// On the CPU one pass over the rows (forward and backward); elsewhere top_k_softmax_reference. Of equal
// logits the first is kept.
SparseWeights top_k_softmax(const at::Tensor& logits, int k);
// The same with at::topk and at::softmax (what a GPU runs; the reference the tests compare with).
SparseWeights top_k_softmax_reference(const at::Tensor& logits, int k);

// A codebook of k bases for `rows` (M x D float32): k-means (k-means++ seeding from `seed`, then Lloyd
// iterations until no assignment changes or `iterations` ran), as LangSplatV2 starts its codebook. With M <= k
// the rows themselves, then copies of them with a 1e-3 jitter. Deterministic for a seed on one machine.
at::Tensor kmeans_codebook(const at::Tensor& rows, int k, uint64_t seed, int iterations = 30);

// Cosine of every Gaussian's feature with each direction: directions P x D -> N x P float32 (0 where a
// feature or a direction is zero). A pass over the Gaussians with K dot products and K^2 Gram entries
// each: what per-Gaussian scores, selections and 3D labels cost.
at::Tensor sparse_cosines(const SparseLevel& level, const at::Tensor& directions);

// Every Gaussian's weights scattered into N x L (zero at the bases it does not use; repeats add).
at::Tensor scattered_weights(const SparseLevel& level);
// The reference: every Gaussian's D-d feature formed (scattered_weights times the codebook).
at::Tensor sparse_features(const SparseLevel& level);

// rows x cols float32 of N(0, sigma^2), drawn in order from `rng` (the seeded starts of training).
at::Tensor normal_noise(int64_t rows, int64_t cols, float sigma, std::mt19937_64& rng);

}  // namespace cls
