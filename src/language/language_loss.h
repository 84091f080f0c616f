#pragma once
// The dual-feature objective of paper 3.3 for one rendered view at one level l:
//   L_SAM     = sum_v (1 - M(v)) |Z^(v) - Z_SAM(v)|_1        (SAM term outside CityGML coverage)
//   L_SAM-GML = sum_v      M(v)  |Z^(v) - Z_SAM(v)|_1        (SAM term inside coverage)
//   L_CityGML = sum_v      M(v)  |Z^(v) - Z_GML(v)|_1        (CityGML term inside coverage)
//   L_feat    = L_SAM + lambda_sam L_SAM-GML + lambda_citygml L_CityGML
// The SAM terms count only pixels where a SAM segment exists (S^l has an id), the CityGML term only
// pixels where C^l is valid. The baseline (LangSplat's objective) is |Z^ - Z_SAM|_1 on every
// SAM-valid pixel with weight 1, whatever M and lambda_sam are; CityGML targets are ignored.
//
// Normalisation: every term is divided by the same constant H * W * L (pixels x channels of the
// view), i.e. each term is a masked mean L1 as LangSplat's l1_loss(Z^ * mask, Z * mask) computes it.
// A common denominator keeps the paper's sums (and so the lambda ratios) up to one scale per view;
// it also keeps the gradient per latent independent of the image size and latent width, which
// LangSplat's lr of 0.0025 assumes.
#include <ATen/core/Tensor.h>

#include <cstdint>

namespace cls {

// A dense supervision field Z_t^l (paper: sum_c z_c S^{l,c}(v)) gathered from a seg map.
struct LatentTarget {
  at::Tensor latents;  // H x W x L, zeros where invalid
  at::Tensor valid;    // H x W float 0/1: the pixel belongs to a segment / region
};

// `ids`: H x W segment ids (row-major), -1 = no segment; `table`: K x L latents of the segments.
// cls::Error (naming `what`) if an id is outside [-1, K).
LatentTarget gather_latent_target(const int32_t* ids, int height, int width, const at::Tensor& table,
                                  const char* what = "seg map");

struct LanguageLossInputs {
  at::Tensor rendered;  // Z^: H x W x L (may require grad)
  LatentTarget sam;     // Z_SAM and where a SAM segment exists
  LatentTarget gml;     // Z_GML and where C^l is valid (undefined tensors allowed for the baseline)
  at::Tensor coverage;  // M: H x W float 0/1
};

struct LanguageLossWeights {
  double lambda_sam = 1.0;
  double lambda_citygml = 0.5;
  bool baseline = false;  // LangSplat's objective
};

struct LanguageLoss {
  at::Tensor total;    // scalar, differentiable
  at::Tensor sam;      // L_SAM (unweighted); in the baseline: the L1 outside coverage
  at::Tensor sam_gml;  // L_SAM-GML (unweighted); in the baseline: the L1 inside coverage
  at::Tensor citygml;  // L_CityGML (unweighted); zero in the baseline
};

LanguageLoss language_loss(const LanguageLossInputs& inputs, const LanguageLossWeights& weights);

// The same loss computed straight from the seg maps, without dense targets: one pass over the
// pixels computes the three terms and dL/dZ^ (saved for the backward), so a 480 x 360 x 128 view
// costs one H x W x L buffer instead of a dozen. `rendered`: float32 on the CPU or, in a CUDA build, a
// GPU (seg_loss_cuda.h); the ids and tables are moved to its device. Equal to language_loss() up to
// float rounding (tested), which stays the reference. `total` lies on `rendered`'s device; the three
// terms are CPU scalars (the pass sums them on the host's side).
struct SegMapTarget {
  at::Tensor ids;    // H x W int32, -1 = none; undefined = no pixel valid
  at::Tensor table;  // K x L latents (floating point; the one-pass loss reads them as float32)
};
LanguageLoss language_loss_from_seg(const at::Tensor& rendered, const SegMapTarget& sam, const SegMapTarget& gml,
                                    const at::Tensor& coverage, const LanguageLossWeights& weights);

// cls::Error from `what` (the caller) unless the seg map's ids are int32 of the rendered `map`'s H x W and its
// table K x `columns` floating point; nothing when the ids are undefined.
void check_seg_target(const SegMapTarget& t, const at::Tensor& map, int64_t columns, const char* what,
                      const char* name);

// cls::Error naming the map (`name`: "SAM", "CityGML"), the id and the first pixel whose id lies outside
// [-1, rows of the table); nothing when the ids are undefined. Reads the ids on the CPU.
void check_seg_ids(const SegMapTarget& t, const char* name);

}  // namespace cls
