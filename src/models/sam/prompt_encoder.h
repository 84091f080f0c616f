#pragma once
// SAM's prompt encoder (segment_anything/modeling/prompt_encoder.py): random Fourier positional
// encoding of points and box corners, learned point/box/not-a-point embeddings, and the dense
// embedding of a low-res mask input (or no_mask_embed when there is none).
#include <torch/torch.h>

#include <utility>

#include "models/sam/sam_config.h"
#include "models/sam/sam_layers.h"

namespace cls::sam {

// PositionEmbeddingRandom: PE(c) = [sin(2 pi (2c-1) G), cos(2 pi (2c-1) G)], G [2, F] is the
// persistent buffer positional_encoding_gaussian_matrix.
struct PositionEmbeddingRandomImpl : torch::nn::Module {
  explicit PositionEmbeddingRandomImpl(int64_t num_pos_feats);
  torch::Tensor pe_encoding(torch::Tensor coords) const;  // [..., 2] in [0,1] -> [..., 2F]
  // Dense PE of an h x w grid at cell centres: [2F, h, w].
  torch::Tensor forward(int64_t h, int64_t w) const;
  // Points in input pixels (x, y): x / width, y / height in the points' dtype, then cast to float32.
  torch::Tensor forward_with_coords(const torch::Tensor& coords, std::pair<int64_t, int64_t> image_size_hw) const;
  torch::Tensor positional_encoding_gaussian_matrix;
};
TORCH_MODULE(PositionEmbeddingRandom);

struct PromptEmbeddings {
  torch::Tensor sparse;  // [B, N, C]
  torch::Tensor dense;   // [B, C, 64, 64]
};

struct PromptEncoderImpl : torch::nn::Module {
  explicit PromptEncoderImpl(const SamConfig& cfg);
  // points: coords [B,N,2] (model-input frame, any float dtype) + labels [B,N] (1 fg, 0 bg, -1 pad);
  // boxes [B,4] XYXY; masks [B,1,256,256] logits. Undefined tensors = prompt absent. A padding
  // point is appended to the points when there is no box (reference behaviour).
  PromptEmbeddings forward(const torch::Tensor& point_coords, const torch::Tensor& point_labels,
                           const torch::Tensor& boxes, const torch::Tensor& masks);
  torch::Tensor embed_points(torch::Tensor points, torch::Tensor labels, bool pad) const;
  torch::Tensor embed_boxes(const torch::Tensor& boxes) const;
  torch::Tensor embed_masks(const torch::Tensor& masks);
  torch::Tensor get_dense_pe() const;  // [1, C, 64, 64]
  // The dense embedding of prompts without mask input: no_mask_embed broadcast to [bs, C, 64, 64].
  torch::Tensor dense_without_mask(int64_t bs) const;
  torch::Tensor point_embedding(size_t i) const;  // point_embeddings.i.weight [1, C]

  int64_t embed_dim;
  std::pair<int64_t, int64_t> image_embedding_size, input_image_size;
  PositionEmbeddingRandom pe_layer{nullptr};
  torch::nn::ModuleList point_embeddings;  // 0 bg, 1 fg, 2 box top-left, 3 box bottom-right
  torch::nn::Embedding not_a_point_embed{nullptr}, no_mask_embed{nullptr};
  torch::nn::Sequential mask_downscaling;
};
TORCH_MODULE(PromptEncoder);

}  // namespace cls::sam
