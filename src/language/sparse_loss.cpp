#include "language/sparse_loss.h"

#include <ATen/ATen.h>
#include <ATen/Dispatch.h>
#include <omp.h>
#include <torch/csrc/autograd/custom_function.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "core/blas_threads.h"
#include "core/error.h"

namespace cls {
namespace {

void check_inputs(const at::Tensor& weight_map, const at::Tensor& codebook, const SegMapTarget& sam,
                  const SegMapTarget& gml, const at::Tensor& coverage, const LanguageLossWeights& weights) {
  if (!weight_map.defined() || weight_map.dim() != 3 || weight_map.numel() == 0)
    throw Error("sparse cosine loss: the weight map must be a non-empty H x W x L tensor");
  if (!codebook.defined() || codebook.dim() != 2 || codebook.size(0) != weight_map.size(2))
    throw Error("sparse cosine loss: the codebook must be L x D with L = " + std::to_string(weight_map.size(2)) +
                ", the weight map's channels");
  if (!coverage.defined() || coverage.dim() != 2 || coverage.size(0) != weight_map.size(0) ||
      coverage.size(1) != weight_map.size(1))
    throw Error("sparse cosine loss: the coverage must be H x W as the weight map");
  check_seg_target(sam, weight_map, codebook.size(1), "sparse cosine loss", "SAM");
  check_seg_ids(sam, "SAM");
  if (!weights.baseline) {  // the baseline reads no CityGML map
    check_seg_target(gml, weight_map, codebook.size(1), "sparse cosine loss", "CityGML");
    check_seg_ids(gml, "CityGML");
  }
}

// One seg map of the CPU pass: its ids, B t per row of its table (rows x L) and |t|^2 per row; where it has no
// ids (none given, an empty table, the baseline's CityGML map) `ids` is null.
template <class T>
struct CosineTargets {
  const int32_t* ids = nullptr;  // n
  const T* projected = nullptr;  // rows x L
  const T* norm2 = nullptr;      // rows
  int64_t rows = 0;
};

// The unweighted sums of 1 - cos: L_SAM, L_SAM-GML, L_CityGML times H W.
struct CosineSums {
  double sam = 0, sam_gml = 0, citygml = 0;
};

// Pixels at a time: a chunk's W (B B^T) and its beta W^T W are one-thread GEMMs on rows still in cache.
constexpr int64_t kChunkRows = 1024;

// The pass over the pixels of W (n x L), in chunks: per pixel the cosines with its targets, 1 - cos summed
// into `sums`, and with the terms' weights w_t at the pixel (dL/d(1 - cos): SAM ((1 - M) + lambda_sam M) / n,
// the baseline's 1 / n, CityGML lambda_citygml M / n):
//   dL/dW      = sum_t -w_t (B t / d - [d not floored] cos W G / |F|^2)      (into grad, n x L)
//   dL/d(B t)  = sum over the pixels of the target of -w_t W / d              (into grad_projected per map)
//   dL/dG      = sum over the pixels of beta W W^T, beta = sum_t [d not floored] w_t cos / (2 |F|^2)
//                                                                             (into grad_gram, L x L)
// with G = B B^T, |F|^2 = W^T G W and d = max(|F| |t|, 1e-8). Per-thread sums, added in thread order
// afterwards (the same sums on every run with the same threads). The GEMMs run on the pass's threads, each
// with OpenBLAS held to it (the caller's ScopedBlasThreads).
template <class T>
void cosine_pass(const at::Tensor& w, const at::Tensor& gram, const float* coverage, const CosineTargets<T> (&maps)[2],
                 const LanguageLossWeights& lw, T* grad, at::Tensor& grad_gram, std::vector<T> (&grad_projected)[2],
                 CosineSums& sums) {
  const int64_t n = w.size(0), l = w.size(1);
  const T* const wd = w.data_ptr<T>();
  const T inv = T(1) / T(n);
  const int threads = omp_get_max_threads();
  std::vector<std::vector<T>> local(static_cast<size_t>(threads) * 2);
  std::vector<CosineSums> partial(static_cast<size_t>(threads));
  std::vector<at::Tensor> outer(static_cast<size_t>(threads));
#pragma omp parallel num_threads(threads)
  {
    const int me = omp_get_thread_num();
    std::vector<T>* mine = &local[static_cast<size_t>(me) * 2];
    for (int k = 0; k < 2; ++k) mine[k].assign(static_cast<size_t>(maps[k].rows * l), T(0));
    at::Tensor& my_outer = outer[static_cast<size_t>(me)] = at::zeros({l, l}, w.options());
    const at::Tensor wg_rows = at::empty({kChunkRows, l}, w.options()), wb_rows = at::empty({kChunkRows, l}, w.options());
    CosineSums part;
#pragma omp for schedule(static)
    for (int64_t p0 = 0; p0 < n; p0 += kChunkRows) {
      const int64_t rows = std::min(kChunkRows, n - p0);
      const at::Tensor w_chunk = w.slice(0, p0, p0 + rows);
      at::Tensor wg = wg_rows.slice(0, 0, rows), wb = wb_rows.slice(0, 0, rows);
      at::mm_out(wg, w_chunk, gram);
      const T* const wgd = wg.data_ptr<T>();
      T* const wbd = wb.data_ptr<T>();
      for (int64_t r = 0; r < rows; ++r) {
        const int64_t p = p0 + r;
        const T* wp = wd + p * l;
        const T* gp = wgd + r * l;
        T* out = grad + p * l;
        T f2 = 0;
#pragma omp simd reduction(+ : f2)
        for (int64_t c = 0; c < l; ++c) f2 += wp[c] * gp[c];
        for (int64_t c = 0; c < l; ++c) out[c] = T(0);
        const T m = coverage[p];
        const T weights[2] = {(lw.baseline ? T(1) : (1 - m) + T(lw.lambda_sam) * m) * inv, T(lw.lambda_citygml) * m * inv};
        T b = 0, distance[2] = {0, 0};
        for (int k = 0; k < 2; ++k) {
          const int id = maps[k].ids ? maps[k].ids[p] : -1;
          if (id < 0) continue;
          const T* a = maps[k].projected + id * l;
          T dot = 0;
#pragma omp simd reduction(+ : dot)
          for (int64_t c = 0; c < l; ++c) dot += wp[c] * a[c];
          const T product = f2 * maps[k].norm2[id];
          const bool floored = !(product >= T(1e-16));  // clamp_min's gradient: none below the floor
          const T d = floored ? T(1e-8) : std::sqrt(product);
          const T cos = dot / d;
          distance[k] = 1 - cos;
          const T along_target = -weights[k] / d, along_norm = floored ? T(0) : weights[k] * cos / f2;
#pragma omp simd
          for (int64_t c = 0; c < l; ++c) out[c] += along_target * a[c] + along_norm * gp[c];
          T* ga = mine[k].data() + id * l;
#pragma omp simd
          for (int64_t c = 0; c < l; ++c) ga[c] += along_target * wp[c];
          b += along_norm / 2;
        }
        T* bw = wbd + r * l;
#pragma omp simd
        for (int64_t c = 0; c < l; ++c) bw[c] = b * wp[c];
        part.sam += double((1 - m) * distance[0]), part.sam_gml += double(m * distance[0]);
        part.citygml += double(m * distance[1]);
      }
      my_outer.addmm_(wb.t(), w_chunk);
    }
    partial[static_cast<size_t>(me)] = part;
  }
  for (int k = 0; k < 2; ++k) grad_projected[k].assign(static_cast<size_t>(maps[k].rows * l), T(0));
  grad_gram = at::zeros({l, l}, w.options());
  for (int t = 0; t < threads; ++t) {
    sums.sam += partial[size_t(t)].sam, sums.sam_gml += partial[size_t(t)].sam_gml,
        sums.citygml += partial[size_t(t)].citygml;
    grad_gram += outer[size_t(t)];
    for (int k = 0; k < 2; ++k) {
      const std::vector<T>& from = local[static_cast<size_t>(t) * 2 + k];
      for (size_t i = 0; i < from.size(); ++i) grad_projected[k][i] += from[i];
    }
  }
}

// Forward: the terms (into *terms) and the gradients of `total` (saved); backward: grad_output times them.
class SparseCosineLossFunction : public torch::autograd::Function<SparseCosineLossFunction> {
 public:
  static at::Tensor forward(torch::autograd::AutogradContext* ctx, const at::Tensor& flat_weights,
                            const at::Tensor& codebook, const SegMapTarget* sam, const SegMapTarget* gml,
                            const at::Tensor& coverage, LanguageLossWeights weights, std::array<double, 3>* terms) {
    // OpenBLAS held to the calling thread (core/blas_threads.h): its pool and the OpenMP one took turns
    // spinning, 40 % of a 2-core loss went to their spins and yields; the large GEMMs are split over the
    // pass's threads, the others are small.
    const ScopedBlasThreads blas(1);
    const at::Tensor w = flat_weights.detach().contiguous(), book = codebook.detach().contiguous();
    const int64_t n = w.size(0), l = w.size(1);
    const at::Tensor gram = book.matmul(book.t());
    const at::Tensor m = coverage.reshape({n}).to(at::kFloat).contiguous();
    // per seg map: the table in the weights' dtype, B t per row and |t|^2 (the baseline reads no CityGML map)
    at::Tensor ids[2], tables[2], projected[2], norm2[2];
    const SegMapTarget* targets[2] = {sam, weights.baseline ? nullptr : gml};
    for (int k = 0; k < 2; ++k) {
      if (!targets[k] || !targets[k]->ids.defined() || targets[k]->table.size(0) == 0) continue;
      ids[k] = targets[k]->ids.reshape({n}).to(at::kCPU).contiguous();
      tables[k] = targets[k]->table.to(at::kCPU, w.scalar_type()).contiguous();
      projected[k] = tables[k].matmul(book.t()).contiguous();
      norm2[k] = tables[k].pow(2).sum(1).contiguous();
    }
    at::Tensor grad_w = at::empty_like(w), grad_gram, grad_book;
    CosineSums sums;
    AT_DISPATCH_FLOATING_TYPES(w.scalar_type(), "sparse_cosine_loss", [&] {
      using T = scalar_t;
      CosineTargets<T> maps[2];
      for (int k = 0; k < 2; ++k)
        if (ids[k].defined())
          maps[k] = {ids[k].data_ptr<int32_t>(), projected[k].data_ptr<T>(), norm2[k].data_ptr<T>(), tables[k].size(0)};
      std::vector<T> grad_projected[2];
      cosine_pass<T>(w, gram, m.data_ptr<float>(), maps, weights, grad_w.data_ptr<T>(), grad_gram, grad_projected, sums);
      // dL/dB: through B t (dL/d(B t) times t, per map) and through G = B B^T (2 dL/dG B)
      grad_book = 2 * grad_gram.matmul(book);
      for (int k = 0; k < 2; ++k)
        if (ids[k].defined())
          grad_book += at::from_blob(grad_projected[k].data(), {maps[k].rows, l}, w.options()).t().matmul(tables[k]);
    });
    (*terms)[0] = sums.sam / double(n), (*terms)[1] = sums.sam_gml / double(n), (*terms)[2] = sums.citygml / double(n);
    ctx->save_for_backward({grad_w, grad_book});
    const double total = weights.baseline
                             ? (*terms)[0] + (*terms)[1]
                             : (*terms)[0] + weights.lambda_sam * (*terms)[1] + weights.lambda_citygml * (*terms)[2];
    return at::scalar_tensor(total, w.options());
  }

  static torch::autograd::variable_list backward(torch::autograd::AutogradContext* ctx,
                                                 torch::autograd::variable_list grad_output) {
    const auto saved = ctx->get_saved_variables();
    const bool one = grad_output[0].numel() == 1 && grad_output[0].item<double>() == 1.0;  // the graph's root
    const auto scaled = [&](const at::Tensor& g) { return one ? g : g * grad_output[0]; };
    return {scaled(saved[0]), scaled(saved[1]), at::Tensor(), at::Tensor(), at::Tensor(), at::Tensor(), at::Tensor()};
  }
};

}  // namespace

LanguageLoss sparse_cosine_loss(const at::Tensor& weight_map, const at::Tensor& codebook, const SegMapTarget& sam,
                                const SegMapTarget& gml, const at::Tensor& coverage, const LanguageLossWeights& weights) {
  if (!weight_map.defined() || !weight_map.device().is_cpu())
    return sparse_cosine_loss_reference(weight_map, codebook, sam, gml, coverage, weights);
  check_inputs(weight_map, codebook, sam, gml, coverage, weights);
  const at::Tensor book = codebook.to(at::kCPU, weight_map.scalar_type());
  std::array<double, 3> terms{0, 0, 0};
  LanguageLoss out;
  out.total = SparseCosineLossFunction::apply(weight_map.reshape({-1, weight_map.size(2)}), book, &sam, &gml,
                                              coverage, weights, &terms);
  const auto opts = weight_map.options().requires_grad(false);
  out.sam = at::scalar_tensor(terms[0], opts);
  out.sam_gml = at::scalar_tensor(terms[1], opts);
  out.citygml = at::scalar_tensor(weights.baseline ? 0.0 : terms[2], opts);
  return out;
}

LanguageLoss sparse_cosine_loss_reference(const at::Tensor& weight_map, const at::Tensor& codebook,
                                          const SegMapTarget& sam, const SegMapTarget& gml, const at::Tensor& coverage,
                                          const LanguageLossWeights& weights) {
  check_inputs(weight_map, codebook, sam, gml, coverage, weights);
  const int64_t n = weight_map.size(0) * weight_map.size(1);
  const at::TensorOptions opts = weight_map.options().requires_grad(false);
  const at::Tensor flat = weight_map.reshape({n, weight_map.size(2)});
  const at::Tensor book = codebook.to(weight_map.device(), weight_map.scalar_type());
  // |F(v)|^2 = W(v)^T (B B^T) W(v): the L x L Gram matrix instead of the D-d features.
  const at::Tensor norm2 = (at::matmul(flat, at::matmul(book, book.t())) * flat).sum(1);
  // 1 - cos(F(v), t(v)) where the map has a target, else 0. A pixel no Gaussian reaches (W = 0) has cosine 0
  // and a gradient of (B t) / 1e-8 that no weight receives: nothing is blended there.
  const auto distance = [&](const SegMapTarget& t) {
    if (!t.ids.defined() || t.table.size(0) == 0) return at::zeros({n}, opts);
    const at::Tensor ids = t.ids.reshape({n}).to(weight_map.device(), at::kLong);
    const at::Tensor valid = ids.ge(0).to(weight_map.scalar_type());
    const at::Tensor index = ids.clamp_min(0);
    const at::Tensor table = t.table.to(weight_map.device(), weight_map.scalar_type());
    const at::Tensor projected = at::matmul(table, book.t()).index_select(0, index);  // B t(v): n x L
    const at::Tensor target2 = table.pow(2).sum(1).index_select(0, index);
    const at::Tensor cosine = (flat * projected).sum(1) / (norm2 * target2).clamp_min(1e-16).sqrt();
    return (1 - cosine) * valid;
  };
  const at::Tensor m = coverage.reshape({n}).to(weight_map.device(), weight_map.scalar_type());
  const at::Tensor d_sam = distance(sam);
  LanguageLoss out;
  out.sam = (d_sam * (1 - m)).sum() / double(n);
  out.sam_gml = (d_sam * m).sum() / double(n);
  if (weights.baseline) {
    out.citygml = at::zeros({}, opts);
    out.total = out.sam + out.sam_gml;
    return out;
  }
  out.citygml = (distance(gml) * m).sum() / double(n);
  out.total = out.sam + weights.lambda_sam * out.sam_gml + weights.lambda_citygml * out.citygml;
  return out;
}

}  // namespace cls
