#include "splat/rasterize.h"

#include <torch/torch.h>

#include <array>
#include <type_traits>

#include "core/error.h"
#include "splat/rasterize_cpu.h"
#include "splat/rasterize_cuda.h"

#ifdef CLS_WITH_CUDA
#include <c10/cuda/CUDACachingAllocator.h>
#include <c10/cuda/CUDAGuard.h>
#include <c10/cuda/CUDAStream.h>

#include "splat/cuda_check.h"
#endif

namespace cls {

struct BlendCache {
  std::unique_ptr<BlendWeights<float>> weights_float;
  std::unique_ptr<BlendWeights<double>> weights_double;
  // The geometry recorded (means, scales, quats, opacities), held so that its memory cannot pass to other
  // tensors while the cache lives, and each tensor's version then.
  std::array<at::Tensor, 4> geometry;
  std::array<int64_t, 4> version{};

  template <class T>
  std::unique_ptr<BlendWeights<T>>& weights() {
    if constexpr (std::is_same_v<T, float>)
      return weights_float;
    else
      return weights_double;
  }
};

std::shared_ptr<BlendCache> make_blend_cache() { return std::make_shared<BlendCache>(); }

size_t blend_cache_bytes(const BlendCache& cache) {
  return (cache.weights_float ? cache.weights_float->bytes() : 0) + (cache.weights_double ? cache.weights_double->bytes() : 0);
}

namespace {

using torch::autograd::AutogradContext;
using torch::autograd::variable_list;

template <class T>
SplatInputs<T> make_inputs(const at::Tensor& means, const at::Tensor& scales, const at::Tensor& quats,
                           const at::Tensor& opacities, const at::Tensor& values, int sh_degree,
                           const at::Tensor& background, const at::Tensor& index, int channels) {
  SplatInputs<T> in;
  in.n = static_cast<int>(means.size(0));
  in.means = means.data_ptr<T>();
  in.scales = scales.data_ptr<T>();
  in.quats = quats.data_ptr<T>();
  in.opacities = opacities.data_ptr<T>();
  if (sh_degree >= 0) {
    in.sh = values.data_ptr<T>();
    in.sh_degree = sh_degree;
    in.channels = 3;
  } else {
    in.features = values.data_ptr<T>();
    in.channels = channels;
    if (index.numel() > 0) in.feature_index = index.data_ptr<int32_t>(), in.nnz = static_cast<int>(values.size(1));
  }
  in.background = background.defined() ? background.data_ptr<T>() : nullptr;
  return in;
}

using Geometry = std::array<at::Tensor, 4>;  // means, scales, quats, opacities

std::array<int64_t, 4> geometry_version(const Geometry& g) {
  return {g[0]._version(), g[1]._version(), g[2]._version(), g[3]._version()};
}
bool same_memory(const Geometry& a, const Geometry& b) {
  for (int i = 0; i < 4; ++i)
    if (a[i].data_ptr() != b[i].data_ptr() || a[i].sizes() != b[i].sizes()) return false;
  return true;
}

template <class T>
bool same_camera(const SplatCamera<T>& a, const SplatCamera<T>& b) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (a.R.m[i][j] != b.R.m[i][j]) return false;
  return a.t[0] == b.t[0] && a.t[1] == b.t[1] && a.t[2] == b.t[2] && a.fx == b.fx && a.fy == b.fy && a.cx == b.cx &&
         a.cy == b.cy && a.width == b.width && a.height == b.height;
}

// The cache's weights, checked to be of this geometry, camera and dtype, or null when nothing was recorded.
template <class T>
const BlendWeights<T>* checked_weights(BlendCache& cache, const Geometry& geometry, const SplatCamera<T>& cam) {
  if (!cache.weights_float && !cache.weights_double) return nullptr;
  const BlendWeights<T>* bw = cache.weights<T>().get();
  if (!bw) throw Error("rasterize: the blend cache was recorded for another dtype");
  if (!same_memory(cache.geometry, geometry))
    throw Error("rasterize: the blend cache was recorded for other Gaussians (keep one cache per view and geometry)");
  if (cache.version != geometry_version(geometry))
    throw Error("rasterize: the Gaussians changed since the blend cache was recorded (it is for frozen geometry)");
  if (!same_camera(bw->cam, cam))
    throw Error("rasterize: the blend cache was recorded for another camera (keep one per view)");
  return bw;
}

// The forward of `in` through the cache: from its recorded weights (checked_weights), or, when it is empty,
// the walk, recording them. Returns the weights, for the backward and the radii.
template <class T>
const BlendWeights<T>& forward_through_cache(BlendCache& cache, const Geometry& geometry, const SplatCamera<T>& cam,
                                             const SplatInputs<T>& in, T* image, T* alpha, T* depth) {
  if (const BlendWeights<T>* bw = checked_weights(cache, geometry, cam)) {
    rasterize_forward_recorded_cpu(*bw, in, image, alpha, depth);
    return *bw;
  }
  auto recorded = std::make_unique<BlendWeights<T>>();
  SplatForwardState<T> state;
  rasterize_forward_cpu(cam, in, image, alpha, depth, state, recorded.get());
  cache.geometry = geometry;
  cache.version = geometry_version(geometry);
  return *(cache.weights<T>() = std::move(recorded));
}

#ifdef CLS_WITH_CUDA
// What a CUDA forward keeps for its backward.
struct CudaSavedState {
  CudaForwardStatePtr state;
  SplatCamera<float> cam;
};

// LibTorch's caching allocator for the rasterizer's buffers (rasterize_cuda.h, CudaAllocator).
void* torch_cuda_alloc(size_t bytes, void* stream) {
  try {
    return c10::cuda::CUDACachingAllocator::raw_alloc_with_stream(bytes, static_cast<cudaStream_t>(stream));
  } catch (const c10::Error&) {
    return nullptr;  // out of memory: the rasterizer reports cudaErrorMemoryAllocation
  }
}

void torch_cuda_free(void* p) { c10::cuda::CUDACachingAllocator::raw_delete(p); }

CudaSplatArgs cuda_args(const SplatCamera<float>& cam, const at::Tensor& means, const at::Tensor& scales,
                        const at::Tensor& quats, const at::Tensor& opacities, const at::Tensor& values, int sh_degree,
                        const at::Tensor& background, const at::Tensor& index, int channels) {
  CudaSplatArgs a;
  a.cam = cam;
  a.n = static_cast<int>(means.size(0));
  a.means = means.data_ptr<float>(), a.scales = scales.data_ptr<float>(), a.quats = quats.data_ptr<float>();
  a.opacities = opacities.data_ptr<float>();
  if (sh_degree >= 0) {
    a.sh = values.data_ptr<float>(), a.sh_degree = sh_degree, a.channels = 3;
  } else {
    a.features = values.data_ptr<float>(), a.channels = channels;
    if (index.numel() > 0) a.feature_index = index.data_ptr<int32_t>(), a.nnz = static_cast<int>(values.size(1));
  }
  a.background = background.defined() ? background.data_ptr<float>() : nullptr;
  a.allocator.alloc = torch_cuda_alloc;
  a.allocator.free = torch_cuda_free;
  return a;
}

#endif

class RasterizeFunction : public torch::autograd::Function<RasterizeFunction> {
 public:
  // values: SH N x (degree+1)^2 x 3 when sh_degree >= 0, else features N x C, or with a non-empty `index`
  // (int32 N x K) sparse features N x K at those channels of C. All contiguous, one dtype.
  static variable_list forward(AutogradContext* ctx, at::Tensor means, at::Tensor scales, at::Tensor quats,
                               at::Tensor opacities, at::Tensor values, at::Tensor means2d, at::Tensor index,
                               int64_t sh_degree, int64_t channels, const RasterizeSettings* settings) {
    (void)means2d;
    const auto& cam = settings->camera;
    const int C = static_cast<int>(channels);
    const auto opts = means.options();
    at::Tensor image = torch::empty({cam.height, cam.width, C}, opts);
    at::Tensor alpha = torch::empty({cam.height, cam.width}, opts);
    at::Tensor depth = torch::empty({cam.height, cam.width}, opts);
    at::Tensor radii = torch::zeros({means.size(0)}, opts.dtype(torch::kInt32));
    at::Tensor bg = settings->background.defined() ? settings->background.to(opts).contiguous() : at::Tensor();
    at::Tensor holder;
    if (means.is_cuda()) {
#ifdef CLS_WITH_CUDA
      const c10::cuda::CUDAGuard guard(means.device());  // the stream and the buffers of the tensors' GPU
      auto* saved = new CudaSavedState();
      holder = torch::from_blob(saved, {1}, [](void* p) { delete static_cast<CudaSavedState*>(p); },
                                torch::TensorOptions().dtype(torch::kUInt8));
      saved->cam = make_splat_camera<float>(cam, settings->pose);
      CudaSplatArgs a = cuda_args(saved->cam, means, scales, quats, opacities, values, int(sh_degree), bg, index, C);
      a.image = image.data_ptr<float>(), a.alpha = alpha.data_ptr<float>(), a.depth = depth.data_ptr<float>();
      void* stream = c10::cuda::getCurrentCUDAStream().stream();
      check_cuda(rasterize_forward_cuda(a, saved->state, stream), "rasterize: forward");
      check_cuda(cuda_forward_radii(*saved->state, radii.data_ptr<int32_t>(), stream), "rasterize: radii");
#endif
    } else {
    AT_DISPATCH_FLOATING_TYPES(means.scalar_type(), "rasterize_forward", [&] {
      using T = scalar_t;
      const SplatInputs<T> in = make_inputs<T>(means, scales, quats, opacities, values, int(sh_degree), bg, index, C);
      const SplatCamera<T> splat_cam = make_splat_camera<T>(cam, settings->pose);
      if (settings->blend_cache) {  // recorded weights, or this call records them; the backward reads them
        const BlendWeights<T>& bw =
            forward_through_cache(*settings->blend_cache, {means, scales, quats, opacities}, splat_cam, in,
                                  image.data_ptr<T>(), alpha.data_ptr<T>(), depth.data_ptr<T>());
        std::copy(bw.radii.begin(), bw.radii.end(), radii.data_ptr<int32_t>());
        auto* keep = new std::shared_ptr<BlendCache>(settings->blend_cache);
        holder = torch::from_blob(keep, {1}, [](void* p) { delete static_cast<std::shared_ptr<BlendCache>*>(p); },
                                  torch::TensorOptions().dtype(torch::kUInt8));
        return;
      }
      auto* state = new SplatForwardState<T>();
      // The forward state is plain C++; a byte tensor whose deleter frees it carries it to backward.
      holder = torch::from_blob(state, {1}, [](void* p) { delete static_cast<SplatForwardState<T>*>(p); },
                                torch::TensorOptions().dtype(torch::kUInt8));
      rasterize_forward_cpu(splat_cam, in, image.data_ptr<T>(), alpha.data_ptr<T>(), depth.data_ptr<T>(), *state);
      screen_radii(*state, radii.data_ptr<int32_t>());
    });
    }
    ctx->save_for_backward({means, scales, quats, opacities, values, index});
    ctx->saved_data["channels"] = channels;
    ctx->saved_data["state"] = holder;
    ctx->saved_data["recorded"] = settings->blend_cache != nullptr;
    ctx->saved_data["sh_degree"] = sh_degree;
    ctx->saved_data["background"] = bg;
    ctx->saved_data["abs_grad"] = settings->mean2d_abs_grad;
    ctx->saved_data["has_means2d"] = means2d.numel() > 0;
    ctx->mark_non_differentiable({radii});
    return {image, alpha, depth, radii};
  }

  static variable_list backward(AutogradContext* ctx, variable_list grad_out) {
    const auto saved = ctx->get_saved_variables();
    const at::Tensor &means = saved[0], &scales = saved[1], &quats = saved[2], &opacities = saved[3], &values = saved[4],
                     &index = saved[5];
    const int channels = static_cast<int>(ctx->saved_data["channels"].toInt());
    const int sh_degree = static_cast<int>(ctx->saved_data["sh_degree"].toInt());
    const at::Tensor bg = ctx->saved_data["background"].toTensor();
    at::Tensor abs_grad = ctx->saved_data["abs_grad"].toTensor();
    void* state_ptr = ctx->saved_data["state"].toTensor().data_ptr();
    auto contiguous_or_undef = [](const at::Tensor& t) { return t.defined() ? t.contiguous() : t; };
    const at::Tensor g_image = contiguous_or_undef(grad_out[0]), g_alpha = contiguous_or_undef(grad_out[1]),
                     g_depth = contiguous_or_undef(grad_out[2]);
    at::Tensor d_means = torch::zeros_like(means), d_scales = torch::zeros_like(scales),
               d_quats = torch::zeros_like(quats), d_opac = torch::zeros_like(opacities),
               d_values = torch::zeros_like(values), d_mean2d = torch::zeros({means.size(0), 2}, means.options()),
               d_abs = torch::zeros({means.size(0), 2}, means.options());
    const bool has_means2d = ctx->saved_data["has_means2d"].toBool();
    // Only the gradients autograd asks for: without geometry gradients (a language field on frozen
    // Gaussians) the backward skips the per-pixel alpha gradient. g: SplatGradients<T> or CudaSplatGrads.
    auto fill = [&](auto& g, auto scalar) {
      using T = decltype(scalar);
      auto wanted = [&](size_t input, at::Tensor& t) { return ctx->needs_input_grad(input) ? t.data_ptr<T>() : nullptr; };
      g.means = wanted(0, d_means), g.scales = wanted(1, d_scales), g.quats = wanted(2, d_quats);
      g.opacities = wanted(3, d_opac);
      (sh_degree >= 0 ? g.sh : g.features) = wanted(4, d_values);
      g.mean2d = has_means2d ? wanted(5, d_mean2d) : nullptr;
      g.mean2d_abs = abs_grad.defined() ? d_abs.data_ptr<T>() : nullptr;
    };
    if (means.is_cuda()) {
#ifdef CLS_WITH_CUDA
      const c10::cuda::CUDAGuard guard(means.device());
      const auto& saved_state = *static_cast<const CudaSavedState*>(state_ptr);
      const CudaSplatArgs a =
          cuda_args(saved_state.cam, means, scales, quats, opacities, values, sh_degree, bg, index, channels);
      CudaSplatGrads g;
      fill(g, float{});
      auto ptr = [](const at::Tensor& t) -> const float* { return t.defined() ? t.data_ptr<float>() : nullptr; };
      check_cuda(rasterize_backward_cuda(a, *saved_state.state, ptr(g_image), ptr(g_alpha), ptr(g_depth), g,
                                         c10::cuda::getCurrentCUDAStream().stream()),
                 "rasterize: backward");
#endif
    } else {
    AT_DISPATCH_FLOATING_TYPES(means.scalar_type(), "rasterize_backward", [&] {
      using T = scalar_t;
      const SplatInputs<T> in = make_inputs<T>(means, scales, quats, opacities, values, sh_degree, bg, index, channels);
      if (ctx->saved_data["recorded"].toBool()) {  // frozen geometry: the features' gradient only
        BlendCache& cache = **static_cast<const std::shared_ptr<BlendCache>*>(state_ptr);
        if (ctx->needs_input_grad(4) && g_image.defined())
          rasterize_backward_recorded_cpu(*cache.weights<T>(), in, g_image.data_ptr<T>(), d_values.data_ptr<T>());
        return;
      }
      const auto& state = *static_cast<const SplatForwardState<T>*>(state_ptr);
      SplatGradients<T> g;
      fill(g, T{});
      auto ptr = [](const at::Tensor& t) -> const T* { return t.defined() ? t.data_ptr<T>() : nullptr; };
      rasterize_backward_cpu(in, state, ptr(g_image), ptr(g_alpha), ptr(g_depth), g);
    });
    }
    if (abs_grad.defined()) abs_grad.add_(d_abs.to(abs_grad.scalar_type()));
    if (!has_means2d) d_mean2d = at::Tensor();
    return {d_means, d_scales, d_quats, d_opac, d_values, d_mean2d, at::Tensor(), at::Tensor(), at::Tensor(), at::Tensor()};
  }
};

void check_inputs(const at::Tensor& means, const at::Tensor& scales, const at::Tensor& quats,
                  const at::Tensor& opacities, const RasterizeSettings& s) {
  const int64_t n = means.size(0);
  auto need = [&](const at::Tensor& t, const char* name, std::vector<int64_t> shape) {
    if (!t.defined() || t.sizes() != at::IntArrayRef(shape))
      throw Error(std::string("rasterize: ") + name + " must have shape " + c10::str(shape) +
                  (t.defined() ? ", got " + c10::str(t.sizes()) : ", got undefined"));
    if (t.scalar_type() != means.scalar_type() || t.device() != means.device())
      throw Error(std::string("rasterize: ") + name + " must have the means' dtype and device");
  };
  if (means.dim() != 2) throw Error("rasterize: means must be N x 3");
  if (means.scalar_type() != torch::kFloat32 && means.scalar_type() != torch::kFloat64)
    throw Error("rasterize: tensors must be float32 or float64");
#ifdef CLS_WITH_CUDA
  if (means.is_cuda() && means.scalar_type() != torch::kFloat32) throw Error("rasterize: CUDA tensors must be float32");
#else
  if (!means.device().is_cpu()) throw Error("rasterize: this build has no CUDA backend; use CPU tensors");
#endif
  need(means, "means", {n, 3});
  need(scales, "scales", {n, 3});
  need(quats, "quats", {n, 4});
  need(opacities, "opacities", {n});
  if (s.camera.width <= 0 || s.camera.height <= 0 || !(s.camera.fx > 0) || !(s.camera.fy > 0))
    throw Error("rasterize: camera needs a positive size and focal lengths");
}

// What any call with a blend cache needs.
void check_cache_inputs(const at::Tensor& means, const at::Tensor& scales, const at::Tensor& quats,
                        const at::Tensor& opacities) {
  if (!means.device().is_cpu()) throw Error("rasterize: a blend cache is for CPU tensors");
  if (!means.is_contiguous() || !scales.is_contiguous() || !quats.is_contiguous() || !opacities.is_contiguous())
    throw Error("rasterize: a blend cache needs contiguous geometry tensors (it knows them by their memory)");
}

// Whether autograd will ask for a gradient of the geometry (or the densification statistic).
bool geometry_grad(const at::Tensor& means, const at::Tensor& scales, const at::Tensor& quats,
                   const at::Tensor& opacities, const at::Tensor& means2d, const RasterizeSettings& s) {
  return s.mean2d_abs_grad.defined() ||
         (torch::GradMode::is_enabled() && (means.requires_grad() || scales.requires_grad() || quats.requires_grad() ||
                                            opacities.requires_grad() || (means2d.defined() && means2d.requires_grad())));
}

// index: int32 N x K for sparse features (values N x K at channels of C), undefined otherwise.
RasterizeOutput run(const at::Tensor& means, const at::Tensor& scales, const at::Tensor& quats,
                    const at::Tensor& opacities, const at::Tensor& values, int sh_degree, const at::Tensor& means2d,
                    const RasterizeSettings& s, const at::Tensor& index = {}, int channels = 0) {
  const int C = sh_degree >= 0 ? 3 : index.defined() ? channels : static_cast<int>(values.size(1));
  if (s.background.defined() && s.background.numel() != C)
    throw Error("rasterize: background must have " + std::to_string(C) + " values");
  if (s.mean2d_abs_grad.defined() && s.mean2d_abs_grad.sizes() != at::IntArrayRef({means.size(0), 2}))
    throw Error("rasterize: mean2d_abs_grad must be N x 2");
  if (s.blend_cache) {
    if (sh_degree >= 0) throw Error("rasterize: a blend cache is for features, not SH colours");
    if (geometry_grad(means, scales, quats, opacities, means2d, s))
      throw Error("rasterize: a blend cache is for frozen Gaussians; a gradient to the geometry was asked for");
    check_cache_inputs(means, scales, quats, opacities);
  }
  // An undefined means2d still needs a tensor slot in apply(); a zero-size one gets no gradient.
  const at::Tensor m2d = means2d.defined() ? means2d : torch::zeros({0}, means.options());
  const at::Tensor idx = index.defined() ? index.contiguous() : torch::zeros({0}, means.options().dtype(torch::kInt32));
  auto out = RasterizeFunction::apply(means.contiguous(), scales.contiguous(), quats.contiguous(),
                                      opacities.contiguous(), values.contiguous(), m2d, idx, int64_t(sh_degree),
                                      int64_t(C), &s);
  return {out[0], out[1], out[2], out[3]};
}

}  // namespace

RasterizeOutput rasterize_sh(const at::Tensor& means, const at::Tensor& scales, const at::Tensor& quats,
                             const at::Tensor& opacities, const at::Tensor& sh, int sh_degree,
                             const at::Tensor& means2d, const RasterizeSettings& settings) {
  check_inputs(means, scales, quats, opacities, settings);
  const int64_t K = (sh_degree + 1) * (sh_degree + 1);
  if (sh_degree < 0 || sh_degree > 3 || sh.dim() != 3 || sh.size(0) != means.size(0) || sh.size(1) < K ||
      sh.size(2) != 3)
    throw Error("rasterize_sh: sh must be N x K x 3 with K >= (degree+1)^2 and degree 0-3, got " + c10::str(sh.sizes()) +
                " for degree " + std::to_string(sh_degree));
  if (sh.scalar_type() != means.scalar_type()) throw Error("rasterize_sh: sh must have the means' dtype");
  return run(means, scales, quats, opacities, sh.slice(1, 0, K), sh_degree, means2d, settings);
}

RasterizeOutput rasterize_features(const at::Tensor& means, const at::Tensor& scales, const at::Tensor& quats,
                                   const at::Tensor& opacities, const at::Tensor& features,
                                   const at::Tensor& means2d, const RasterizeSettings& settings) {
  check_inputs(means, scales, quats, opacities, settings);
  if (features.dim() != 2 || features.size(0) != means.size(0) || features.size(1) < 1)
    throw Error("rasterize_features: features must be N x C, got " + c10::str(features.sizes()));
  if (features.scalar_type() != means.scalar_type()) throw Error("rasterize_features: features must have the means' dtype");
  return run(means, scales, quats, opacities, features, -1, means2d, settings);
}

at::Tensor lift_to_gaussians(const at::Tensor& means, const at::Tensor& scales, const at::Tensor& quats,
                             const at::Tensor& opacities, const at::Tensor& values, const RasterizeSettings& settings) {
  if (values.dim() != 3 || values.size(0) != settings.camera.height || values.size(1) != settings.camera.width ||
      values.size(2) < 1)
    throw Error("lift_to_gaussians: values must be H x W x C at the camera's size, got " + c10::str(values.sizes()));
  const torch::AutoGradMode grad_mode(true);
  RasterizeSettings s = settings;
  s.background = torch::Tensor();  // of another width than `values`, and no part of the transpose
  s.mean2d_abs_grad = torch::Tensor();
  const torch::Tensor x = torch::zeros({means.size(0), values.size(2)}, means.options()).requires_grad_(true);
  const RasterizeOutput o =
      rasterize_features(means.detach(), scales.detach(), quats.detach(), opacities.detach(), x, {}, s);
  return torch::autograd::grad({o.image}, {x}, {values.to(o.image.options())})[0];
}

}  // namespace cls

namespace cls {

at::Tensor scatter_sparse_features(const at::Tensor& weights, const at::Tensor& indices, int channels) {
  return torch::zeros({weights.size(0), channels}, weights.options()).scatter_add(1, indices.to(torch::kLong), weights);
}

void check_sparse_inputs(const char* what, const at::Tensor& means, const at::Tensor& weights, const at::Tensor& indices,
                         int channels) {
  const std::string name = what;
  if (!weights.defined() || !indices.defined()) throw Error(name + ": weights and indices must both be given");
  if (weights.dim() != 2 || weights.size(0) != means.size(0) || weights.size(1) < 1 || indices.sizes() != weights.sizes())
    throw Error(name + ": weights and indices must both be N x K, got " + c10::str(weights.sizes()) + " and " +
                c10::str(indices.sizes()));
  if (weights.scalar_type() != means.scalar_type()) throw Error(name + ": weights must have the means' dtype");
  if (indices.scalar_type() != torch::kInt32 || indices.device() != means.device())
    throw Error(name + ": indices must be int32 on the means' device");
  if (channels < 1) throw Error(name + ": channels must be positive");
  if (indices.numel() > 0 && (indices.min().item<int32_t>() < 0 || indices.max().item<int32_t>() >= channels))
    throw Error(name + ": an index lies outside [0, " + std::to_string(channels) + ")");
}


RasterizeOutput rasterize_sparse_features(const at::Tensor& means, const at::Tensor& scales, const at::Tensor& quats,
                                          const at::Tensor& opacities, const at::Tensor& weights,
                                          const at::Tensor& indices, int channels, const at::Tensor& means2d,
                                          const RasterizeSettings& settings) {
  check_inputs(means, scales, quats, opacities, settings);
  check_sparse_inputs("rasterize_sparse_features", means, weights, indices, channels);
  // The sparse CUDA kernels take up to kCudaSparseMaxNnz weights and give their gradient alone; with more, or
  // with geometry gradients, the weights scattered into N x C dense features (the same image and gradients).
  if (means.is_cuda() && (geometry_grad(means, scales, quats, opacities, means2d, settings) ||
                          weights.size(1) > kCudaSparseMaxNnz)) {
    return rasterize_features(means, scales, quats, opacities, scatter_sparse_features(weights, indices, channels),
                              means2d, settings);
  }
  return run(means, scales, quats, opacities, weights, -1, means2d, settings, indices, channels);
}

RasterizeOutput rasterize_sparse_cosines(const at::Tensor& means, const at::Tensor& scales, const at::Tensor& quats,
                                         const at::Tensor& opacities, const at::Tensor& weights,
                                         const at::Tensor& indices, int channels, const at::Tensor& directions,
                                         const at::Tensor& factor, const RasterizeSettings& settings) {
  const char* what = "rasterize_sparse_cosines";
  check_inputs(means, scales, quats, opacities, settings);
  check_sparse_inputs(what, means, weights, indices, channels);
  if (!means.device().is_cpu())
    throw Error(std::string(what) + ": CPU tensors only (on a GPU, render the weights with rasterize_sparse_features)");
  if (settings.background.defined()) throw Error(std::string(what) + ": the cosines are of a zero background's features");
  if (!directions.defined() || directions.dim() != 2 || directions.size(0) < 1 || directions.size(1) != channels ||
      !factor.defined() || factor.dim() != 2 || factor.size(0) < 1 || factor.size(0) > channels ||
      factor.size(1) != channels)
    throw Error(std::string(what) + ": directions P x C and factor k x C (1 <= k <= C) expected for C = " +
                std::to_string(channels) + ", got " + (directions.defined() ? c10::str(directions.sizes()) : "undefined") +
                " and " + (factor.defined() ? c10::str(factor.sizes()) : "undefined"));
  if (directions.scalar_type() != means.scalar_type() || factor.scalar_type() != means.scalar_type() ||
      !directions.device().is_cpu() || !factor.device().is_cpu())
    throw Error(std::string(what) + ": directions and factor must have the means' dtype and device");
  const torch::NoGradGuard no_grad;
  const auto& cam = settings.camera;
  const auto opts = means.options();
  RasterizeOutput out;
  out.image = torch::empty({cam.height, cam.width, directions.size(0)}, opts);
  out.alpha = torch::empty({cam.height, cam.width}, opts);
  out.depth = torch::empty({cam.height, cam.width}, opts);
  out.radii = torch::zeros({means.size(0)}, opts.dtype(torch::kInt32));
  const at::Tensor m = means.contiguous(), s = scales.contiguous(), q = quats.contiguous(), o = opacities.contiguous(),
                   w = weights.contiguous(), idx = indices.contiguous(), a = directions.contiguous(),
                   r = factor.contiguous();
  AT_DISPATCH_FLOATING_TYPES(means.scalar_type(), "rasterize_sparse_cosines", [&] {
    using T = scalar_t;
    SplatInputs<T> in = make_inputs<T>(m, s, q, o, w, -1, at::Tensor(), idx, channels);
    in.cosines = {a.data_ptr<T>(), r.data_ptr<T>(), static_cast<int>(a.size(0)), static_cast<int>(r.size(0))};
    const SplatCamera<T> splat_cam = make_splat_camera<T>(cam, settings.pose);
    if (settings.blend_cache) {
      check_cache_inputs(means, scales, quats, opacities);
      const BlendWeights<T>& bw = forward_through_cache(*settings.blend_cache, {m, s, q, o}, splat_cam, in,
                                                        out.image.data_ptr<T>(), out.alpha.data_ptr<T>(),
                                                        out.depth.data_ptr<T>());
      std::copy(bw.radii.begin(), bw.radii.end(), out.radii.data_ptr<int32_t>());
      return;
    }
    SplatForwardState<T> state;
    rasterize_forward_cpu(splat_cam, in, out.image.data_ptr<T>(), out.alpha.data_ptr<T>(), out.depth.data_ptr<T>(),
                          state);
    screen_radii(state, out.radii.data_ptr<int32_t>());
  });
  return out;
}

template <class T>
const BlendWeights<T>* recorded_blend_weights(const at::Tensor& means, const at::Tensor& scales,
                                              const at::Tensor& quats, const at::Tensor& opacities,
                                              const RasterizeSettings& settings) {
  if (!settings.blend_cache) return nullptr;
  check_inputs(means, scales, quats, opacities, settings);
  check_cache_inputs(means, scales, quats, opacities);
  if (geometry_grad(means, scales, quats, opacities, at::Tensor(), settings))
    throw Error("recorded_blend_weights: recorded weights are for frozen Gaussians; a gradient to the geometry "
                "was asked for");
  if (means.scalar_type() != c10::CppTypeToScalarType<T>::value)
    throw Error("recorded_blend_weights: the Gaussians' dtype is not the one asked for");
  return checked_weights<T>(*settings.blend_cache, {means, scales, quats, opacities},
                            make_splat_camera<T>(settings.camera, settings.pose));
}
template const BlendWeights<float>* recorded_blend_weights<float>(const at::Tensor&, const at::Tensor&,
                                                                  const at::Tensor&, const at::Tensor&,
                                                                  const RasterizeSettings&);
template const BlendWeights<double>* recorded_blend_weights<double>(const at::Tensor&, const at::Tensor&,
                                                                    const at::Tensor&, const at::Tensor&,
                                                                    const RasterizeSettings&);

}  // namespace cls
