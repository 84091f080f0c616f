#include "language/language_loss.h"

#include <torch/torch.h>

#include <array>
#include <cmath>
#include <string>

#include "core/error.h"
#include "language/seg_loss_pixel.h"

#ifdef CLS_WITH_CUDA
#include <c10/cuda/CUDAGuard.h>
#include <c10/cuda/CUDAStream.h>

#include "language/seg_loss_cuda.h"
#include "splat/cuda_check.h"
#endif

namespace cls {

LatentTarget gather_latent_target(const int32_t* ids, int height, int width, const at::Tensor& table,
                                  const char* what) {
  if (table.dim() != 2) throw Error(std::string(what) + ": latent table must be K x L");
  const int64_t k = table.size(0);
  const int64_t n = int64_t(height) * width;
  at::Tensor index = at::empty({n}, at::kLong);
  at::Tensor valid = at::empty({n}, at::kFloat);
  int64_t* ip = index.data_ptr<int64_t>();
  float* vp = valid.data_ptr<float>();
  for (int64_t i = 0; i < n; ++i) {
    const int32_t id = ids[i];
    if (id < -1 || id >= k)
      throw Error(std::string(what) + ": segment id " + std::to_string(id) + " outside [-1, " + std::to_string(k) + ")");
    // Invalid pixels gather row 0 (or a zero row when the table is empty) and are zeroed below.
    ip[i] = id < 0 ? 0 : id;
    vp[i] = id < 0 ? 0.f : 1.f;
  }
  const at::Tensor src = table.to(at::kFloat);
  LatentTarget t;
  if (k == 0) {
    t.latents = at::zeros({height, width, table.size(1)}, src.options());
  } else {
    t.latents = src.index_select(0, index.to(src.device())).mul_(valid.to(src.device()).unsqueeze(1))
                    .view({height, width, table.size(1)});
  }
  t.valid = valid.to(src.device()).view({height, width});
  return t;
}

namespace {

// sum_v w(v) |a(v) - b(v)|_1 / (H W L)
at::Tensor masked_l1(const at::Tensor& a, const at::Tensor& b, const at::Tensor& w) {
  return ((a - b).abs() * w.unsqueeze(-1)).sum() / double(a.numel());
}

void check_map(const at::Tensor& t, const at::Tensor& rendered, const char* name, bool channels) {
  const bool ok = t.defined() && t.dim() == (channels ? 3 : 2) && t.size(0) == rendered.size(0) &&
                  t.size(1) == rendered.size(1) && (!channels || t.size(2) == rendered.size(2));
  if (!ok) throw Error(std::string("language loss: ") + name + " does not match the rendered H x W x L map");
}

}  // namespace

LanguageLoss language_loss(const LanguageLossInputs& in, const LanguageLossWeights& w) {
  if (!in.rendered.defined() || in.rendered.dim() != 3)
    throw Error("language loss: rendered latents must be H x W x L");
  check_map(in.sam.latents, in.rendered, "SAM target", true);
  check_map(in.sam.valid, in.rendered, "SAM validity", false);
  check_map(in.coverage, in.rendered, "coverage", false);
  const at::Tensor& z = in.rendered;
  const at::Tensor m = in.coverage.to(z.scalar_type());
  const at::Tensor sam_valid = in.sam.valid.to(z.scalar_type());
  const at::Tensor sam_abs = (z - in.sam.latents.to(z.scalar_type())).abs();
  LanguageLoss out;
  const double denom = double(z.numel());
  out.sam = (sam_abs * (sam_valid * (1 - m)).unsqueeze(-1)).sum() / denom;
  out.sam_gml = (sam_abs * (sam_valid * m).unsqueeze(-1)).sum() / denom;
  if (w.baseline) {
    out.citygml = at::zeros({}, z.options().requires_grad(false));
    out.total = out.sam + out.sam_gml;
    return out;
  }
  check_map(in.gml.latents, in.rendered, "CityGML target", true);
  check_map(in.gml.valid, in.rendered, "CityGML validity", false);
  out.citygml = masked_l1(z, in.gml.latents.to(z.scalar_type()), m * in.gml.valid.to(z.scalar_type()));
  out.total = out.sam + w.lambda_sam * out.sam_gml + w.lambda_citygml * out.citygml;
  return out;
}

namespace {

using torch::autograd::AutogradContext;
using torch::autograd::variable_list;

// The seg map's ids and its table as float32 on `device`, contiguous (undefined where there is no map).
std::pair<at::Tensor, at::Tensor> on_device(const SegMapTarget& t, const at::Device& device) {
  if (!t.ids.defined()) return {};
  return {t.ids.to(device).contiguous(), t.table.to(device, at::kFloat).contiguous()};
}

// The tensors of one pass and the SegLossArgs that point into them (on their device).
struct SegLossTensors {
  at::Tensor z, coverage, sam_ids, sam_table, gml_ids, gml_table, grad;
  SegLossArgs args(const SegLossWeights& weights) {
    SegLossArgs a;
    a.rendered = z.data_ptr<float>();
    a.sam_ids = sam_ids.defined() ? sam_ids.data_ptr<int32_t>() : nullptr;
    a.sam_table = a.sam_ids ? sam_table.data_ptr<float>() : nullptr;
    a.ks = a.sam_ids ? sam_table.size(0) : 0;
    a.gml_ids = gml_ids.defined() ? gml_ids.data_ptr<int32_t>() : nullptr;
    a.gml_table = a.gml_ids ? gml_table.data_ptr<float>() : nullptr;
    a.kg = a.gml_ids ? gml_table.size(0) : 0;
    a.coverage = coverage.data_ptr<float>();
    a.n = z.size(0) * z.size(1);
    a.l = int(z.size(2));
    a.weights = weights;
    a.grad = grad.data_ptr<float>();
    return a;
  }
};

// The CPU pass: dL/dZ^ into a.grad, the sums returned; false where an id lies outside its table.
bool seg_loss_cpu(const SegLossArgs& a, SegLossSums& total) {
  const int64_t l = a.l;
  double sum_sam = 0, sum_sam_gml = 0, sum_citygml = 0;
  bool bad_id = false;
#pragma omp parallel for reduction(+ : sum_sam, sum_sam_gml, sum_citygml) reduction(|| : bad_id) schedule(static)
  for (int64_t p = 0; p < a.n; ++p) {
    const float* zv = a.rendered + p * l;
    float* gv = a.grad + p * l;
    const int32_t s = a.sam_ids ? a.sam_ids[p] : -1;
    const int32_t g = a.gml_ids ? a.gml_ids[p] : -1;
    if (!ids_in_tables(s, g, a.ks, a.kg)) {
      bad_id = true;
      continue;
    }
    const float mv = a.coverage[p];
    const float ws = sam_weight(a.weights, s, mv), wg = citygml_weight(a.weights, g, mv);
    float abs_s = 0, abs_g = 0;
    const float* ts = s >= 0 ? a.sam_table + int64_t(s) * l : nullptr;
    const float* tg = g >= 0 ? a.gml_table + int64_t(g) * l : nullptr;
    // Branch-free inner loops per case, so that they vectorise.
    if (ts && tg) {
#pragma omp simd reduction(+ : abs_s, abs_g)
      for (int64_t c = 0; c < l; ++c) gv[c] = l1_channel(zv[c], ts[c], ws, abs_s) + l1_channel(zv[c], tg[c], wg, abs_g);
    } else if (ts || tg) {
      const float* t = ts ? ts : tg;
      const float wt = ts ? ws : wg;
      float a_sum = 0;
#pragma omp simd reduction(+ : a_sum)
      for (int64_t c = 0; c < l; ++c) gv[c] = l1_channel(zv[c], t[c], wt, a_sum);
      (ts ? abs_s : abs_g) = a_sum;
    } else {
      for (int64_t c = 0; c < l; ++c) gv[c] = 0.f;
    }
    SegLossSums pixel;
    add_pixel(pixel, mv, abs_s, abs_g);
    sum_sam += pixel.sam, sum_sam_gml += pixel.sam_gml, sum_citygml += pixel.citygml;
  }
  total = {sum_sam, sum_sam_gml, sum_citygml};
  return !bad_id;
}

#ifdef CLS_WITH_CUDA
// The CUDA pass (seg_loss_cuda.h), the same contract as seg_loss_cpu. Waits for the device: the sums
// come back to the host.
bool seg_loss_gpu(const SegLossArgs& a, const at::Device& device, SegLossSums& total) {
  const c10::cuda::CUDAGuard guard(device);
  const at::Tensor sums = at::empty({4}, at::TensorOptions(device).dtype(at::kDouble));
  check_cuda(seg_loss_cuda(a, sums.data_ptr<double>(), c10::cuda::getCurrentCUDAStream().stream()), "language loss");
  const at::Tensor host = sums.cpu();
  const double* h = host.data_ptr<double>();
  total = {h[0], h[1], h[2]};
  return h[3] == 0;
}
#endif

// Forward: the three terms (into *terms) and dL/dZ^ (saved); backward: grad_output x dL/dZ^.
class SegLossFunction : public torch::autograd::Function<SegLossFunction> {
 public:
  static at::Tensor forward(AutogradContext* ctx, const at::Tensor& rendered, const SegMapTarget* sam,
                            const SegMapTarget* gml, const at::Tensor& coverage, LanguageLossWeights weights,
                            std::array<double, 3>* terms) {
    SegLossTensors t;
    t.z = rendered.detach().contiguous();
    t.coverage = coverage.to(t.z.device(), at::kFloat).contiguous();
    t.grad = at::empty_like(t.z);
    std::tie(t.sam_ids, t.sam_table) = on_device(*sam, t.z.device());
    if (!weights.baseline) std::tie(t.gml_ids, t.gml_table) = on_device(*gml, t.z.device());
    const SegLossWeights w{weights.lambda_sam, weights.lambda_citygml, weights.baseline, 1.0 / double(t.z.numel())};
    const SegLossArgs a = t.args(w);
    SegLossSums sums;
#ifdef CLS_WITH_CUDA
    const bool ok = t.z.is_cuda() ? seg_loss_gpu(a, t.z.device(), sums) : seg_loss_cpu(a, sums);
#else
    const bool ok = seg_loss_cpu(a, sums);
#endif
    if (!ok) {
      check_seg_ids(*sam, "SAM");
      if (!weights.baseline) check_seg_ids(*gml, "CityGML");
      throw Error("language loss: a seg map holds an id outside its latent table");
    }
    (*terms)[0] = sums.sam * w.inv, (*terms)[1] = sums.sam_gml * w.inv, (*terms)[2] = sums.citygml * w.inv;
    ctx->save_for_backward({t.grad});
    const double total = weights.baseline
                             ? (*terms)[0] + (*terms)[1]
                             : (*terms)[0] + weights.lambda_sam * (*terms)[1] + weights.lambda_citygml * (*terms)[2];
    return at::scalar_tensor(total, t.z.options());
  }

  static variable_list backward(AutogradContext* ctx, variable_list grad_output) {
    const at::Tensor grad = ctx->get_saved_variables()[0];
    // The loss is the graph's root almost always: skip the 88 MB multiply by 1.
    const at::Tensor g = grad_output[0].numel() == 1 && grad_output[0].item<double>() == 1.0 ? grad : grad * grad_output[0];
    return {g, at::Tensor(), at::Tensor(), at::Tensor(), at::Tensor(), at::Tensor()};
  }
};

}  // namespace

void check_seg_target(const SegMapTarget& t, const at::Tensor& map, int64_t columns, const char* what,
                      const char* name) {
  if (!t.ids.defined()) return;
  if (t.ids.dim() != 2 || t.ids.size(0) != map.size(0) || t.ids.size(1) != map.size(1) || t.ids.scalar_type() != at::kInt)
    throw Error(std::string(what) + ": the " + name + " seg map must be H x W int32 as the rendered map");
  if (!t.table.defined() || t.table.dim() != 2 || t.table.size(1) != columns || !t.table.is_floating_point())
    throw Error(std::string(what) + ": the " + name + " table must be K x " + std::to_string(columns) +
                " floating point");
}

void check_seg_ids(const SegMapTarget& t, const char* name) {
  if (!t.ids.defined()) return;
  const at::Tensor ids = t.ids.to(at::kCPU).contiguous();
  const int32_t* p = ids.data_ptr<int32_t>();
  const int64_t k = t.table.size(0), w = ids.size(1);
  for (int64_t i = 0; i < ids.numel(); ++i)
    if (p[i] < -1 || p[i] >= k)
      throw Error(std::string("language loss: the ") + name + " seg map holds id " + std::to_string(p[i]) +
                  " at pixel (" + std::to_string(i % w) + ", " + std::to_string(i / w) + "), outside [-1, " +
                  std::to_string(k) + ") of its latent table");
}

LanguageLoss language_loss_from_seg(const at::Tensor& rendered, const SegMapTarget& sam, const SegMapTarget& gml,
                                    const at::Tensor& coverage, const LanguageLossWeights& weights) {
  if (!rendered.defined() || rendered.dim() != 3 || rendered.scalar_type() != at::kFloat)
    throw Error("language loss: rendered latents must be an H x W x L float32 tensor");
#ifdef CLS_WITH_CUDA
  if (!rendered.device().is_cpu() && !rendered.is_cuda())
#else
  if (!rendered.device().is_cpu())
#endif
    throw Error("language loss: rendered latents on " + rendered.device().str() + ": the one-pass loss runs on " +
                "the CPU or a CUDA device");
  if (rendered.numel() == 0) throw Error("language loss: the rendered map is empty (" + c10::str(rendered.sizes()) + ")");
  check_map(coverage, rendered, "coverage", false);
  check_seg_target(sam, rendered, rendered.size(2), "language loss", "SAM");
  if (!weights.baseline) check_seg_target(gml, rendered, rendered.size(2), "language loss", "CityGML");
  std::array<double, 3> terms{0, 0, 0};
  LanguageLoss out;
  out.total = SegLossFunction::apply(rendered, &sam, &gml, coverage, weights, &terms);
  const auto opts = at::TensorOptions().dtype(at::kFloat);
  out.sam = at::scalar_tensor(terms[0], opts);
  out.sam_gml = at::scalar_tensor(terms[1], opts);
  out.citygml = at::scalar_tensor(weights.baseline ? 0.0 : terms[2], opts);
  return out;
}

}  // namespace cls
