#pragma once
// The paper's coverage-aware objective (3.3) for the sparse field with the cosine distance in CLIP space:
//   L_SAM     = sum_v (1 - M(v)) d(F(v), t_SAM(v))
//   L_SAM-GML = sum_v      M(v)  d(F(v), t_SAM(v))
//   L_CityGML = sum_v      M(v)  d(F(v), t_GML(v)),   d(F, t) = 1 - cos(F, t),
// weighted and masked as language_loss.h's L1 terms (SAM terms where a segment exists, CityGML where C^l is
// valid; the baseline: L_SAM + L_SAM-GML, no CityGML term), each divided by H W.
//
// Why a cosine: CLIP features are compared by their direction (the paper's own reason for the autoencoder's
// cosine term, 3.2), LangSplatV2 trains its sparse field with this loss alone, and it is exact in the L-d
// weight space: with F(v) = W(v) B (W: the rendered L-vector of weights, B: the L x D codebook),
//   F . t^ = W . (B t^)   and   |F|^2 = W^T (B B^T) W,
// so a view costs H W L^2 for the Gram form and H W L for the dot products, where the L1 needs the H x W x D
// features, forward and backward (172,800 x 64 x 512 products per 480 x 360 view, three times). The L1 in
// CLIP space (language_loss_from_seg on W B) stays the other choice (--sparse-distance l1).
#include <ATen/core/Tensor.h>

#include "language/language_loss.h"
#include "splat/rasterize.h"

namespace cls {

// weight_map: H x W x L rendered weights (may require grad); codebook: L x D (may require grad); the seg maps'
// tables hold D-d targets (the baseline's CityGML map is not read). cos = F . t / max(|F| |t|, 1e-8), as
// torch's cosine_similarity. float32 or float64 on any device (the codebook, tables and coverage are moved to
// the weight map's); the ids are read on the CPU for the check.
// cls::Error for shapes that do not agree and for ids outside their tables (check_seg_ids).
//
// On the CPU one pass over the pixels takes the three terms and the gradients (as language_loss_from_seg): `total`
// is differentiable with respect to the weight map and the codebook, the three terms are plain scalars. Elsewhere
// sparse_cosine_loss_reference, whose LibTorch operations make a dozen H W x L tensors and their backward.
LanguageLoss sparse_cosine_loss(const at::Tensor& weight_map, const at::Tensor& codebook, const SegMapTarget& sam,
                                const SegMapTarget& gml, const at::Tensor& coverage, const LanguageLossWeights& weights);

// sparse_cosine_loss of the weight map rasterize_sparse_features(means, scales, quats, opacities, weights, indices,
// L, {}, settings) renders (L: the codebook's rows), taken from the blend weights settings.blend_cache recorded
// (recorded_blend_weights) in one pass over the tiles with the rendering and its backward
// (rasterize_recorded_loss_cpu): the H x W x L map and its gradient are never made. `total` is differentiable with
// respect to `weights` (N x K) and the codebook; the same loss and gradients as rendering, then
// sparse_cosine_loss, within rounding. CPU tensors, geometry as the cache recorded it (contiguous), no
// background; cls::Error when the cache holds no weights yet (record them with a call of
// rasterize_sparse_features), when they are not of these Gaussians or this view, and as sparse_cosine_loss.
LanguageLoss sparse_cosine_loss_recorded(const at::Tensor& means, const at::Tensor& scales, const at::Tensor& quats,
                                         const at::Tensor& opacities, const at::Tensor& weights,
                                         const at::Tensor& indices, const RasterizeSettings& settings,
                                         const at::Tensor& codebook, const SegMapTarget& sam, const SegMapTarget& gml,
                                         const at::Tensor& coverage, const LanguageLossWeights& loss_weights);

// The same loss as LibTorch operations, every term differentiable: the GPU's path and the CPU pass's reference.
LanguageLoss sparse_cosine_loss_reference(const at::Tensor& weight_map, const at::Tensor& codebook,
                                          const SegMapTarget& sam, const SegMapTarget& gml, const at::Tensor& coverage,
                                          const LanguageLossWeights& weights);

}  // namespace cls
