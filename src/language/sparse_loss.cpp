// The sparse cosine loss (sparse_loss.h). -Wpsabi: see splat/blend_lanes.h (row_products.h's register vectors
// never cross a call: its functions are inlined into the per-build kernels).
#pragma GCC diagnostic ignored "-Wpsabi"
#include "language/sparse_loss.h"

#include <ATen/ATen.h>
#include <ATen/Dispatch.h>
#include <omp.h>
#include <torch/csrc/autograd/custom_function.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/blas_threads.h"
#include "core/error.h"
#include "language/row_products.h"
#include "splat/rasterize.h"
#include "splat/rasterize_cpu.h"

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

// Pixels at a time: a chunk's W (B B^T) and its beta W^T W are products on rows still in cache.
constexpr int64_t kChunkRows = 1024;

// One call's rows of the pass (CosinePass::rows): W (rows x L), G (L x L), their pixels, the calling thread's
// buffers and where the gradients and sums go.
template <class T>
struct CosineRows {
  const T* w;
  const T* gram;
  T* wg;  // W G (rows x L)
  T* wb;  // beta W (rows x L)
  T* outer;  // out: += beta W^T W (L x L)
  const int64_t* pixels;
  int64_t rows, l;
  T* grad;  // out: dL/dW
  const float* coverage;
  const CosineTargets<T>* maps;  // 2
  const LanguageLossWeights* lw;
  T inv;  // 1 / the image's pixels
  T* grad_projected[2];
  CosineSums* sums;
};

// W G, then per pixel the cosines with its targets, 1 - cos into the sums, dL/dW, dL/d(B t) and beta W, then
// beta W^T W (CosinePass).
template <int kBytes, class T>
[[gnu::always_inline]] inline void cosine_rows(const CosineRows<T>& a) {
  const int64_t l = a.l;
  rows_times_matrix<kBytes>(a.w, a.rows, l, a.gram, a.wg);
  CosineSums sums;  // added to the thread's once (through a pointer, a store per pixel)
  for (int64_t r = 0; r < a.rows; ++r) {
    const int64_t p = a.pixels[r];
    const T* wp = a.w + r * l;
    const T* gp = a.wg + r * l;
    T* out = a.grad + r * l;
    T f2 = 0;
#pragma omp simd reduction(+ : f2)
    for (int64_t c = 0; c < l; ++c) f2 += wp[c] * gp[c];
    for (int64_t c = 0; c < l; ++c) out[c] = T(0);
    const T m = a.coverage[p];
    const T weights[2] = {(a.lw->baseline ? T(1) : (1 - m) + T(a.lw->lambda_sam) * m) * a.inv,
                          T(a.lw->lambda_citygml) * m * a.inv};
    T b = 0, distance[2] = {0, 0};
    for (int k = 0; k < 2; ++k) {
      const int id = a.maps[k].ids ? a.maps[k].ids[p] : -1;
      if (id < 0) continue;
      const T* t = a.maps[k].projected + id * l;
      T dot = 0;
#pragma omp simd reduction(+ : dot)
      for (int64_t c = 0; c < l; ++c) dot += wp[c] * t[c];
      const T product = f2 * a.maps[k].norm2[id];
      const bool floored = !(product >= T(1e-16));  // clamp_min's gradient: none below the floor
      const T d = floored ? T(1e-8) : std::sqrt(product);
      const T cos = dot / d;
      distance[k] = 1 - cos;
      const T along_target = -weights[k] / d, along_norm = floored ? T(0) : weights[k] * cos / f2;
#pragma omp simd
      for (int64_t c = 0; c < l; ++c) out[c] += along_target * t[c] + along_norm * gp[c];
      T* gt = a.grad_projected[k] + id * l;
#pragma omp simd
      for (int64_t c = 0; c < l; ++c) gt[c] += along_target * wp[c];
      b += along_norm / 2;
    }
    T* bw = a.wb + r * l;
#pragma omp simd
    for (int64_t c = 0; c < l; ++c) bw[c] = b * wp[c];
    sums.sam += double((1 - m) * distance[0]), sums.sam_gml += double(m * distance[0]);
    sums.citygml += double(m * distance[1]);
  }
  a.sums->sam += sums.sam, a.sums->sam_gml += sums.sam_gml, a.sums->citygml += sums.citygml;
  add_transposed_product<kBytes>(a.wb, a.w, a.rows, l, a.outer);
}

// Instruction-set builds of cosine_rows, as the rasterizer's tile kernels (rasterize_cpu.h): its products and
// L-long loops vectorise per build.
#define CLS_COSINE_ROWS(NAME, ATTRIBUTE, REGISTER_BYTES) \
  template <class T>                                     \
  ATTRIBUTE void cosine_rows_##NAME(const CosineRows<T>& a) { cosine_rows<REGISTER_BYTES>(a); }
CLS_COSINE_ROWS(baseline, , 16)
#if CLS_X86_KERNELS
CLS_COSINE_ROWS(v3, [[gnu::target("arch=x86-64-v3")]], 32)
CLS_COSINE_ROWS(v4, [[gnu::target("arch=x86-64-v4,prefer-vector-width=512")]], 64)
#endif
#undef CLS_COSINE_ROWS

template <class T>
void (*cosine_rows_kernel())(const CosineRows<T>&) {
#if CLS_X86_KERNELS
  const CpuKernels k = cpu_kernels();
  if (k == CpuKernels::X86_64_V4) return &cosine_rows_v4<T>;
  if (k == CpuKernels::X86_64_V3) return &cosine_rows_v3<T>;
#endif
  return &cosine_rows_baseline<T>;
}

// The pass over the pixels of W (n x L), some rows at a time from several threads: per pixel the cosines with its
// targets, 1 - cos summed, and with the terms' weights w_t at the pixel (dL/d(1 - cos): SAM
// ((1 - M) + lambda_sam M) / n, the baseline's 1 / n, CityGML lambda_citygml M / n):
//   dL/dW      = sum_t -w_t (B t / d - [d not floored] cos W G / |F|^2)      (the rows' gradient)
//   dL/d(B t)  = sum over the pixels of the target of -w_t W / d              (grad_projected per map)
//   dL/dG      = sum over the pixels of beta W W^T, beta = sum_t [d not floored] w_t cos / (2 |F|^2)
//                                                                             (grad_gram, L x L)
// with G = B B^T, |F|^2 = W^T G W and d = max(|F| |t|, 1e-8). Per-thread sums (omp_get_thread_num()), added in
// thread order by finish.
template <class T>
class CosinePass {
 public:
  CosinePass(const at::Tensor& gram, const float* coverage, const CosineTargets<T> (&maps)[2],
             const LanguageLossWeights& lw, int64_t pixels)
      : gram_(gram), coverage_(coverage), maps_(maps), lw_(lw), inv_(T(1) / T(pixels)),
        threads_(static_cast<size_t>(omp_get_max_threads())), kernel_(cosine_rows_kernel<T>()) {
    // every thread's buffers here, on the calling thread: nothing is allocated inside the parallel regions
    const int64_t l = gram_.size(0);
    for (Thread& t : threads_) {
      for (int k = 0; k < 2; ++k) t.grad_projected[k].assign(static_cast<size_t>(maps_[k].rows * l), T(0));
      t.outer.assign(static_cast<size_t>(l * l), T(0));
      t.wg.resize(static_cast<size_t>(kChunkRows * l));
      t.wb.resize(static_cast<size_t>(kChunkRows * l));
    }
  }

  // `rows` rows of W (rows x L, at most kChunkRows) at the image's pixels `pixels`: their gradient into grad.
  void rows(const T* w, const int64_t* pixels, int64_t rows, T* grad) {
    const int64_t l = gram_.size(0);
    Thread& me = threads_[static_cast<size_t>(omp_get_thread_num())];
    kernel_({w, gram_.data_ptr<T>(), me.wg.data(), me.wb.data(), me.outer.data(), pixels, rows, l, grad, coverage_,
             maps_, &lw_, inv_, {me.grad_projected[0].data(), me.grad_projected[1].data()}, &me.sums});
  }

  // The threads' sums, in thread order: the same on every run where each thread gets the same rows (cosine_pass's
  // static shares; the tile pass hands tiles out as threads come free, so with more than one thread its sums may
  // differ by rounding from run to run).
  void finish(at::Tensor& grad_gram, std::vector<T> (&grad_projected)[2], CosineSums& sums) const {
    const int64_t l = gram_.size(0);
    for (int k = 0; k < 2; ++k) grad_projected[k].assign(static_cast<size_t>(maps_[k].rows * l), T(0));
    grad_gram = at::zeros({l, l}, gram_.options());
    T* const gg = grad_gram.data_ptr<T>();
    for (const Thread& t : threads_) {
      sums.sam += t.sums.sam, sums.sam_gml += t.sums.sam_gml, sums.citygml += t.sums.citygml;
      for (size_t i = 0; i < t.outer.size(); ++i) gg[i] += t.outer[i];
      for (int k = 0; k < 2; ++k)
        for (size_t i = 0; i < t.grad_projected[k].size(); ++i) grad_projected[k][i] += t.grad_projected[k][i];
    }
  }

 private:
  struct Thread {
    std::vector<T> grad_projected[2];
    std::vector<T> outer, wg, wb;  // beta W^T W; W G and beta W of the rows
    CosineSums sums;
  };
  const at::Tensor gram_;
  const float* coverage_;
  const CosineTargets<T> (&maps_)[2];
  const LanguageLossWeights& lw_;
  const T inv_;
  std::vector<Thread> threads_;
  void (*kernel_)(const CosineRows<T>&);
};

// The whole map W (n x L) in chunks of pixels, static over the threads (nothing allocated inside the region: an
// exception may not leave it).
template <class T>
void cosine_pass(const at::Tensor& w, CosinePass<T>& pass, T* grad) {
  const int64_t n = w.size(0), l = w.size(1);
  const T* const wd = w.data_ptr<T>();
  std::vector<int64_t> pixels(static_cast<size_t>(omp_get_max_threads() * kChunkRows));
#pragma omp parallel for schedule(static)
  for (int64_t p0 = 0; p0 < n; p0 += kChunkRows) {
    const int64_t rows = std::min(kChunkRows, n - p0);
    int64_t* const mine = pixels.data() + omp_get_thread_num() * kChunkRows;
    std::iota(mine, mine + rows, p0);
    pass.rows(wd + p0 * l, mine, rows, grad + p0 * l);
  }
}

// The splatted weights a recorded pass renders the map from (sparse_cosine_loss_recorded).
struct RecordedMap {
  const at::Tensor &means, &scales, &quats, &opacities, &indices;
  const RasterizeSettings& settings;
};

// TileLoss of the pass: each tile's rows through CosinePass::rows.
template <class T>
class CosineTileLoss : public TileLoss<T> {
 public:
  explicit CosineTileLoss(CosinePass<T>& pass) : pass_(pass) {}
  void tile(const int64_t* pixels, int rows, const T* image, T* dL_dimage) override {
    pass_.rows(image, pixels, rows, dL_dimage);
  }

 private:
  CosinePass<T>& pass_;
};

// Forward: the terms (into *terms) and the gradients of `total` (saved); backward: grad_output times them. `x`:
// the flat weight map (n x L), or with `recorded` the splatted weights (N x K) it is rendered from.
class SparseCosineLossFunction : public torch::autograd::Function<SparseCosineLossFunction> {
 public:
  static at::Tensor forward(torch::autograd::AutogradContext* ctx, const at::Tensor& x, const at::Tensor& codebook,
                            const SegMapTarget* sam, const SegMapTarget* gml, const at::Tensor& coverage,
                            LanguageLossWeights weights, const RecordedMap* recorded, std::array<double, 3>* terms) {
    // OpenBLAS held to the calling thread (core/blas_threads.h): its pool and the OpenMP one took turns
    // spinning, 40 % of a 2-core loss went to their spins and yields; its products here are small (the pass's
    // own are row_products.h's, on the pass's threads).
    const ScopedBlasThreads blas(1);
    const at::Tensor xd = x.detach().contiguous(), book = codebook.detach().contiguous();
    const int64_t n = coverage.numel(), l = book.size(0);
    const at::Tensor gram = book.matmul(book.t());
    const at::Tensor m = coverage.reshape({n}).to(at::kFloat).contiguous();
    // per seg map: the table in the weights' dtype, B t per row and |t|^2 (the baseline reads no CityGML map)
    at::Tensor ids[2], tables[2], projected[2], norm2[2];
    const SegMapTarget* targets[2] = {sam, weights.baseline ? nullptr : gml};
    for (int k = 0; k < 2; ++k) {
      if (!targets[k] || !targets[k]->ids.defined() || targets[k]->table.size(0) == 0) continue;
      ids[k] = targets[k]->ids.reshape({n}).to(at::kCPU).contiguous();
      tables[k] = targets[k]->table.to(at::kCPU, xd.scalar_type()).contiguous();
      projected[k] = tables[k].matmul(book.t()).contiguous();
      norm2[k] = tables[k].pow(2).sum(1).contiguous();
    }
    at::Tensor grad_x = recorded ? at::zeros_like(xd) : at::empty_like(xd), grad_gram, grad_book;
    CosineSums sums;
    AT_DISPATCH_FLOATING_TYPES(xd.scalar_type(), "sparse_cosine_loss", [&] {
      using T = scalar_t;
      CosineTargets<T> maps[2];
      for (int k = 0; k < 2; ++k)
        if (ids[k].defined())
          maps[k] = {ids[k].data_ptr<int32_t>(), projected[k].data_ptr<T>(), norm2[k].data_ptr<T>(), tables[k].size(0)};
      CosinePass<T> pass(gram, m.data_ptr<float>(), maps, weights, n);
      if (recorded) {
        const RecordedMap& r = *recorded;
        const BlendWeights<T>* bw = recorded_blend_weights<T>(r.means, r.scales, r.quats, r.opacities, r.settings);
        if (!bw)
          throw Error(std::string("sparse_cosine_loss_recorded: ") +
                      (r.settings.blend_cache ? "the view's blend cache holds no weights yet (render it once with "
                                                "rasterize_sparse_features)"
                                              : "the settings hold no blend cache"));
        SplatInputs<T> in;
        in.n = static_cast<int>(xd.size(0));
        in.features = xd.data_ptr<T>(), in.channels = static_cast<int>(l);
        in.feature_index = r.indices.data_ptr<int32_t>(), in.nnz = static_cast<int>(xd.size(1));
        CosineTileLoss<T> tile_loss(pass);
        try {
          rasterize_recorded_loss_cpu(*bw, in, tile_loss, grad_x.data_ptr<T>());
        } catch (const std::invalid_argument& e) {
          throw Error(std::string("sparse_cosine_loss_recorded: ") + e.what());
        }
      } else {
        cosine_pass<T>(xd, pass, grad_x.data_ptr<T>());
      }
      std::vector<T> grad_projected[2];
      pass.finish(grad_gram, grad_projected, sums);
      // dL/dB: through B t (dL/d(B t) times t, per map) and through G = B B^T (2 dL/dG B)
      grad_book = 2 * grad_gram.matmul(book);
      for (int k = 0; k < 2; ++k)
        if (ids[k].defined())
          grad_book += at::from_blob(grad_projected[k].data(), {maps[k].rows, l}, xd.options()).t().matmul(tables[k]);
    });
    (*terms)[0] = sums.sam / double(n), (*terms)[1] = sums.sam_gml / double(n), (*terms)[2] = sums.citygml / double(n);
    ctx->save_for_backward({grad_x, grad_book});
    const double total = weights.baseline
                             ? (*terms)[0] + (*terms)[1]
                             : (*terms)[0] + weights.lambda_sam * (*terms)[1] + weights.lambda_citygml * (*terms)[2];
    return at::scalar_tensor(total, xd.options());
  }

  static torch::autograd::variable_list backward(torch::autograd::AutogradContext* ctx,
                                                 torch::autograd::variable_list grad_output) {
    const auto saved = ctx->get_saved_variables();
    const bool one = grad_output[0].numel() == 1 && grad_output[0].item<double>() == 1.0;  // the graph's root
    const auto scaled = [&](const at::Tensor& g) { return one ? g : g * grad_output[0]; };
    return {scaled(saved[0]), scaled(saved[1]), at::Tensor(), at::Tensor(), at::Tensor(),
            at::Tensor(),     at::Tensor(),     at::Tensor()};
  }
};

// The loss of the function's total and its plain terms.
LanguageLoss apply_loss(const at::Tensor& x, const at::Tensor& book, const SegMapTarget& sam, const SegMapTarget& gml,
                        const at::Tensor& coverage, const LanguageLossWeights& weights, const RecordedMap* recorded) {
  std::array<double, 3> terms{0, 0, 0};
  LanguageLoss out;
  out.total = SparseCosineLossFunction::apply(x, book, &sam, &gml, coverage, weights, recorded, &terms);
  const auto opts = x.options().requires_grad(false);
  out.sam = at::scalar_tensor(terms[0], opts);
  out.sam_gml = at::scalar_tensor(terms[1], opts);
  out.citygml = at::scalar_tensor(weights.baseline ? 0.0 : terms[2], opts);
  return out;
}

}  // namespace

LanguageLoss sparse_cosine_loss(const at::Tensor& weight_map, const at::Tensor& codebook, const SegMapTarget& sam,
                                const SegMapTarget& gml, const at::Tensor& coverage, const LanguageLossWeights& weights) {
  if (!weight_map.defined() || !weight_map.device().is_cpu())
    return sparse_cosine_loss_reference(weight_map, codebook, sam, gml, coverage, weights);
  check_inputs(weight_map, codebook, sam, gml, coverage, weights);
  const at::Tensor book = codebook.to(at::kCPU, weight_map.scalar_type());
  return apply_loss(weight_map.reshape({-1, weight_map.size(2)}), book, sam, gml, coverage, weights, nullptr);
}

LanguageLoss sparse_cosine_loss_recorded(const at::Tensor& means, const at::Tensor& scales, const at::Tensor& quats,
                                         const at::Tensor& opacities, const at::Tensor& weights_nk,
                                         const at::Tensor& indices, const RasterizeSettings& settings,
                                         const at::Tensor& codebook, const SegMapTarget& sam, const SegMapTarget& gml,
                                         const at::Tensor& coverage, const LanguageLossWeights& weights) {
  const char* what = "sparse_cosine_loss_recorded";
  if (!means.defined() || !means.device().is_cpu() || !weights_nk.defined() || !weights_nk.device().is_cpu())
    throw Error(std::string(what) + ": CPU tensors only (a GPU renders the map and takes sparse_cosine_loss)");
  if (settings.background.defined())
    throw Error(std::string(what) + ": the map is of a zero background (settings.background must be undefined)");
  if (!codebook.defined() || codebook.dim() != 2 || codebook.size(0) < 1)
    throw Error(std::string(what) + ": the codebook must be L x D");
  const int64_t l = codebook.size(0);
  check_sparse_inputs(what, means, weights_nk, indices, static_cast<int>(l));  // the rasterizer's own checks
  // the map's shape without the map: a broadcast scalar (no memory) for the shape checks
  const at::Tensor shape = at::zeros({1, 1, 1}, weights_nk.options().requires_grad(false))
                               .expand({settings.camera.height, settings.camera.width, l});
  check_inputs(shape, codebook, sam, gml, coverage, weights);
  // the cache's checks here, where grad mode is the caller's (an autograd function's forward runs without it)
  AT_DISPATCH_FLOATING_TYPES(means.scalar_type(), "sparse_cosine_loss_recorded", [&] {
    recorded_blend_weights<scalar_t>(means, scales, quats, opacities, settings);
  });
  const at::Tensor book = codebook.to(at::kCPU, weights_nk.scalar_type());
  const at::Tensor idx = indices.contiguous();
  const RecordedMap recorded{means, scales, quats, opacities, idx, settings};
  return apply_loss(weights_nk, book, sam, gml, coverage, weights, &recorded);
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
