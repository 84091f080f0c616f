#include "language/sparse_field.h"

#include <ATen/ATen.h>
#include <ATen/Dispatch.h>
#include <torch/csrc/autograd/custom_function.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/log.h"
#include "splat/rasterize.h"

namespace cls {

void SparseLevel::validate(const std::string& what, int64_t n, int64_t d) const {
  if (!codebook.defined() || codebook.dim() != 2 || codebook.size(0) < 1 || codebook.size(1) != d)
    fail(what, cat("the codebook must be L x ", d, ", got ", codebook.defined() ? c10::str(codebook.sizes()) : "none"));
  if (!weights.defined() || weights.dim() != 2 || weights.size(0) != n || weights.size(1) < 1 ||
      !indices.defined() || indices.sizes() != weights.sizes())
    fail(what, cat("weights and indices must both be ", n, " x K (one row per Gaussian)"));
  if (indices.scalar_type() != at::kInt || weights.scalar_type() != at::kFloat || codebook.scalar_type() != at::kFloat)
    fail(what, "indices must be int32, weights and codebook float32");
  if (indices.numel() > 0 && (indices.min().item<int32_t>() < 0 || indices.max().item<int32_t>() >= codebook.size(0)))
    fail(what, cat("an index lies outside the codebook's ", codebook.size(0), " bases"));
  if (!at::isfinite(weights).all().item<bool>() || !at::isfinite(codebook).all().item<bool>())
    fail(what, "weights or codebook hold a NaN or infinity");
}

namespace {

void check_top_k(const at::Tensor& logits, int k) {
  if (logits.dim() != 2 || k < 1 || k > logits.size(1))
    throw Error(cat("top_k_softmax: K must lie in [1, ", logits.dim() == 2 ? logits.size(1) : 0, "], got ", k));
}

// One row's top k (largest first; of equal logits the first) and their softmax: k passes of a vectorised
// maximum over the logits not yet taken, then the first position holding it (an insertion per new
// candidate mispredicted its branch about 17 times a row for k 4 of 64, 9 ms for 50k rows on 2 cores).
// Where only -inf or NaN logits are left, the first positions not taken.
template <class T>
void top_k_row(const T* x, int64_t l, int k, int32_t* index, T* weight, std::vector<T>& rest) {
  rest.assign(x, x + l);
  const T taken = -std::numeric_limits<T>::infinity();
  for (int j = 0; j < k; ++j) {
    T m = taken;
#pragma omp simd reduction(max : m)
    for (int64_t c = 0; c < l; ++c) m = std::max(m, rest[size_t(c)]);
    int64_t at_max = 0;
    if (m > taken)
      while (rest[size_t(at_max)] != m) ++at_max;
    else  // only -inf or NaN left: the first position not taken
      while (std::find(index, index + j, int32_t(at_max)) != index + j) ++at_max;
    index[j] = int32_t(at_max);
    rest[size_t(at_max)] = taken;
  }
  const T top = x[index[0]];
  T sum = 0;
  for (int j = 0; j < k; ++j) sum += weight[j] = std::exp(x[index[j]] - top);
  for (int j = 0; j < k; ++j) weight[j] /= sum;
}

template <class T>
void top_k_rows(const T* x, int64_t n, int64_t l, int k, int32_t* index, T* weight) {
#pragma omp parallel
  {
    std::vector<T> rest;
#pragma omp for schedule(static)
    for (int64_t i = 0; i < n; ++i) top_k_row(x + i * l, l, k, index + i * k, weight + i * k, rest);
  }
}

// d logit_{i,j_m} = w_m (g_m - sum_k w_k g_k) at the kept bases (softmax's Jacobian) into `out` (n x l, zeros).
template <class T>
void top_k_rows_backward(const int32_t* index, const T* w, const T* g, int64_t n, int64_t l, int64_t k, T* out) {
#pragma omp parallel for schedule(static)
  for (int64_t i = 0; i < n; ++i) {
    const T *wi = w + i * k, *gi = g + i * k;
    T dot = 0;
    for (int64_t j = 0; j < k; ++j) dot += wi[j] * gi[j];
    for (int64_t j = 0; j < k; ++j) out[i * l + index[i * k + j]] += wi[j] * (gi[j] - dot);
  }
}

// top_k_softmax on the CPU in one pass over the rows, forward and backward: at::topk and at::softmax took
// 20 ms of a 200 ms sparse training iteration (50k Gaussians, L 64), their backward an N x L scatter besides.
class TopKSoftmaxFunction : public torch::autograd::Function<TopKSoftmaxFunction> {
 public:
  static torch::autograd::variable_list forward(torch::autograd::AutogradContext* ctx, const at::Tensor& logits,
                                                int64_t k) {
    const at::Tensor x = logits.detach().contiguous();
    const int64_t n = x.size(0), l = x.size(1);
    at::Tensor indices = at::empty({n, k}, x.options().dtype(at::kInt));
    at::Tensor weights = at::empty({n, k}, x.options());
    AT_DISPATCH_FLOATING_TYPES(x.scalar_type(), "top_k_softmax", [&] {
      top_k_rows(x.data_ptr<scalar_t>(), n, l, int(k), indices.data_ptr<int32_t>(), weights.data_ptr<scalar_t>());
    });
    ctx->mark_non_differentiable({indices});
    ctx->save_for_backward({indices, weights});
    ctx->saved_data["l"] = l;
    return {weights, indices};
  }

  static torch::autograd::variable_list backward(torch::autograd::AutogradContext* ctx,
                                                 torch::autograd::variable_list grad_output) {
    const auto saved = ctx->get_saved_variables();
    const at::Tensor& indices = saved[0];
    const at::Tensor& weights = saved[1];
    if (!grad_output[0].defined()) return {at::Tensor(), at::Tensor()};  // the weights were not used
    const at::Tensor g = grad_output[0].to(weights.scalar_type()).contiguous();
    const int64_t n = weights.size(0), k = weights.size(1), l = ctx->saved_data["l"].toInt();
    at::Tensor out = at::zeros({n, l}, weights.options());
    AT_DISPATCH_FLOATING_TYPES(weights.scalar_type(), "top_k_softmax_backward", [&] {
      top_k_rows_backward(indices.data_ptr<int32_t>(), weights.data_ptr<scalar_t>(), g.data_ptr<scalar_t>(), n, l, k,
                          out.data_ptr<scalar_t>());
    });
    return {out, at::Tensor()};
  }
};

}  // namespace

SparseWeights top_k_softmax(const at::Tensor& logits, int k) {
  check_top_k(logits, k);
  if (!logits.device().is_cpu()) return top_k_softmax_reference(logits, k);
  const torch::autograd::variable_list out = TopKSoftmaxFunction::apply(logits, int64_t(k));
  return {out[1], out[0]};
}

SparseWeights top_k_softmax_reference(const at::Tensor& logits, int k) {
  check_top_k(logits, k);
  const auto [values, indices] = logits.topk(k, 1);
  return {indices.to(at::kInt).contiguous(), at::softmax(values, 1).contiguous()};
}

at::Tensor kmeans_codebook(const at::Tensor& rows, int k, uint64_t seed, int iterations) {
  if (rows.dim() != 2 || rows.size(0) == 0 || k < 1) throw Error("kmeans_codebook: rows must be M x D with M > 0, and k >= 1");
  const at::Tensor x = rows.to(at::kCPU, at::kFloat).contiguous();
  const int64_t M = x.size(0);
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  if (M <= k) {  // every row a basis, then jittered copies
    std::vector<int64_t> pick(static_cast<size_t>(k));
    for (int64_t i = 0; i < k; ++i) pick[size_t(i)] = i < M ? i : int64_t(rng() % uint64_t(M));
    at::Tensor book = x.index_select(0, at::tensor(pick, at::kLong)).clone();
    if (k > M) {
      book.slice(0, M).add_(normal_noise(k - M, x.size(1), 1e-3f, rng));
    }
    return book;
  }
  // k-means++: each next centre drawn with probability proportional to the squared distance to the nearest one.
  const at::Tensor sq = (x * x).sum(1);
  std::vector<int64_t> chosen{int64_t(rng() % uint64_t(M))};
  at::Tensor nearest = (sq - 2 * at::mv(x, x[chosen[0]]) + sq[chosen[0]]).clamp_min(0);
  while (int64_t(chosen.size()) < k) {
    const at::Tensor cumulative = nearest.to(at::kDouble).cumsum(0);
    const double total = cumulative[M - 1].item<double>();
    int64_t next = int64_t(rng() % uint64_t(M));
    if (total > 0) {
      const double u = uniform(rng) * total;
      next = std::min<int64_t>(M - 1, at::searchsorted(cumulative, at::scalar_tensor(u, at::kDouble)).item<int64_t>());
    }
    chosen.push_back(next);
    nearest = at::minimum(nearest, (sq - 2 * at::mv(x, x[next]) + sq[next]).clamp_min(0));
  }
  at::Tensor centres = x.index_select(0, at::tensor(chosen, at::kLong)).clone();
  at::Tensor assignment;
  for (int it = 0; it < iterations; ++it) {
    const at::Tensor distance = sq.unsqueeze(1) - 2 * at::matmul(x, centres.t()) + (centres * centres).sum(1).unsqueeze(0);
    const at::Tensor next = distance.argmin(1);
    if (assignment.defined() && at::equal(next, assignment)) break;
    assignment = next;
    const at::Tensor sums = at::zeros_like(centres).index_add_(0, assignment, x);
    const at::Tensor counts = at::zeros({k}, at::kFloat).index_add_(0, assignment, at::ones({M}, at::kFloat));
    const at::Tensor filled = counts > 0;  // an emptied cluster keeps its centre
    centres = at::where(filled.unsqueeze(1), sums / counts.clamp_min(1).unsqueeze(1), centres);
  }
  return centres;
}

at::Tensor sparse_cosines(const SparseLevel& level, const at::Tensor& directions) {
  const at::Tensor book = level.codebook.to(at::kCPU, at::kFloat);
  const at::Tensor dirs = directions.to(at::kCPU, at::kFloat);
  if (dirs.dim() != 2 || dirs.size(1) != book.size(1))
    throw Error(cat("sparse_cosines: directions must be P x ", book.size(1), ", got ", c10::str(dirs.sizes())));
  const at::Tensor unit = dirs / dirs.norm(2, {1}, true).clamp_min(1e-30);
  const at::Tensor proj = at::matmul(book, unit.t()).contiguous();  // L x P: <b_j, q_p / |q_p|>
  const at::Tensor gram = at::matmul(book, book.t()).contiguous();  // L x L
  const at::Tensor idx = level.indices.to(at::kCPU).contiguous(), w = level.weights.to(at::kCPU, at::kFloat).contiguous();
  const int64_t N = w.size(0), K = w.size(1), L = book.size(0), P = dirs.size(0);
  at::Tensor out = at::zeros({N, P}, at::kFloat);
  const int32_t* ip = idx.data_ptr<int32_t>();
  const float *wp = w.data_ptr<float>(), *pp = proj.data_ptr<float>(), *gp = gram.data_ptr<float>();
  float* op = out.data_ptr<float>();
#pragma omp parallel for schedule(static)
  for (int64_t i = 0; i < N; ++i) {
    const int32_t* j = ip + i * K;
    const float* wi = wp + i * K;
    double norm2 = 0;  // |f_i|^2 = w^T G w over the K bases
    for (int64_t a = 0; a < K; ++a)
      for (int64_t b = 0; b < K; ++b) norm2 += double(wi[a]) * wi[b] * gp[int64_t(j[a]) * L + j[b]];
    if (!(norm2 > 1e-30)) continue;
    const float inv = float(1.0 / std::sqrt(norm2));
    for (int64_t p = 0; p < P; ++p) {
      float dot = 0;
      for (int64_t a = 0; a < K; ++a) dot += wi[a] * pp[int64_t(j[a]) * P + p];
      op[i * P + p] = dot * inv;
    }
  }
  return out;
}

at::Tensor scattered_weights(const SparseLevel& level) {
  return scatter_sparse_features(level.weights, level.indices, int(level.codebook.size(0)));
}

at::Tensor sparse_features(const SparseLevel& level) { return at::matmul(scattered_weights(level), level.codebook); }

at::Tensor normal_noise(int64_t rows, int64_t cols, float sigma, std::mt19937_64& rng) {
  at::Tensor noise = at::empty({rows, cols}, at::kFloat);
  std::normal_distribution<float> normal(0.f, sigma);
  float* p = noise.data_ptr<float>();
  for (int64_t i = 0; i < noise.numel(); ++i) p[i] = normal(rng);
  return noise;
}

}  // namespace cls
