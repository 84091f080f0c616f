#pragma once
// The sparse field's first logits of a level, lifted from its targets (issue 36). From random logits a
// Gaussian that few pixels train keeps the mean of K arbitrary bases, and its own feature (what per-Gaussian
// scores and 3D labels read) says little; the first logits here are what the targets say of it: for every
// basis, its cosine with the targets of the pixels the Gaussian is blended into, averaged with the blend's
// weights alpha T and, per pixel, the loss's weights of its SAM and CityGML targets (paper 3.3; the
// baseline's objective: SAM alone), over the training views. Training then goes on from there as from
// random logits (docs/language.md).
#include <ATen/core/Tensor.h>

#include <cstdint>
#include <functional>

#include "language/language_loss.h"
#include "splat/rasterize.h"

namespace cls {

// One training view at the level being lifted.
struct LiftingView {
  RasterizeSettings settings;  // camera and pose
  SegMapTarget sam, gml;       // the level's seg maps and their features (rows in the codebook's space)
  at::Tensor coverage;         // H x W, 0/1
};

// Logits N x L: sum_p a_ip sum_t w_t(p) cos(t(p), b_j) / (sum_p a_ip sum_t w_t(p) + 1) / temperature over
// the views, a_ip = alpha_ip T_ip, t(p) the pixel's targets, w_t(p) their loss weights (seg_loss_pixel.h), b_j
// the bases (`codebook` L x D). The weights are the loss's per pixel, without its per-view 1 / (H W L): every
// pixel is the same evidence whatever its view's size. The + 1 is a prior of one fully blended pixel at
// cosine 0: a Gaussian few pixels see stays near zero. `view(i)` gives view i of `views`, one at a time (a
// view's maps are made on demand, as training makes them). cls::Error if an id lies outside its table.
at::Tensor lifted_logits(const at::Tensor& means, const at::Tensor& scales, const at::Tensor& quats,
                         const at::Tensor& opacities, int64_t views, const std::function<LiftingView(int64_t)>& view,
                         const at::Tensor& codebook, const LanguageLossWeights& weights, double temperature);

}  // namespace cls
