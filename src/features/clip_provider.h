#pragma once
// The CLIP/SAM feature provider (paper 3.1-3.2, LangSplat's preprocess.py):
//   SAM branch: LangSplat's automatic mask generator (points_per_side 32, pred_iou_thresh 0.7,
//     stability_score_thresh 0.85, crop_n_layers 1, min_mask_region_area 100), masks_update
//     (mask NMS: iou 0.8, score 0.7, inner 0.5), the seg maps of mask2segmap/create, and one CLIP
//     image feature per mask from LangSplat's crop (masked, boxed, padded square, 224 px);
//   regions: the same crop of I ⊙ R (the paper's V(I ⊙ R^{l,c})) -> CLIP;
//   text: CLIP's tokenizer + text tower; every output row L2-normalised.
// Two flavours:
//   "clip": real weights (LangSplat: OpenCLIP ViT-B-16 laion2b_s34b_b88k, SAM ViT-H), given as
//     paths in the spec or found through the model registry (models/model_registry.h);
//   "clip-tiny": tiny random CLIP (512-d output, like ViT-B) and SAM built in code from a seed, with AMG thresholds relaxed
//     and a 4 x 4 point grid, so that the real code path runs in seconds on a CPU. A smoke test:
//     its features are meaningless.
#include <memory>

#include "features/feature_provider.h"

namespace cls {

// Builds "clip" or "clip-tiny" from its spec (see make_feature_provider). Keys:
//   clip: {"provider": "clip", "clip": PATH?, "sam": PATH?, "clip_model": known name
//          (default "openclip-vit-b-16-laion2b"), "sam_model": known name (default "sam-vit-h"),
//          "clip_activation": "gelu" | "quick_gelu" (default from the model: OpenAI's QuickGELU,
//          OpenCLIP's GELU), "models_dir": DIR?, "points_per_side": 32, "batch_size": 32,
//          "device": "auto" | "cpu" | "cuda"}
//   clip-tiny: {"provider": "clip-tiny", "seed": 1, "device": ...}
// "auto" picks CUDA where LibTorch has it (clip-tiny ran on an H100 in `run --models tiny`, now `clip-tiny`, and the
// CLIP/SAM parity tests pass there; docs/benchmarks.md, "GPU").
std::unique_ptr<FeatureProvider> make_clip_provider(const nlohmann::json& spec, const Taxonomy& taxonomy);

}  // namespace cls
