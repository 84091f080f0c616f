#include "models/sam/prompt_encoder.h"

#include <cmath>

namespace cls::sam {

using torch::indexing::Slice;

PositionEmbeddingRandomImpl::PositionEmbeddingRandomImpl(int64_t num_pos_feats) {
  positional_encoding_gaussian_matrix = register_buffer("positional_encoding_gaussian_matrix", torch::randn({2, num_pos_feats}));
}

torch::Tensor PositionEmbeddingRandomImpl::pe_encoding(torch::Tensor coords) const {
  coords = 2 * coords - 1;
  coords = torch::matmul(coords, positional_encoding_gaussian_matrix);
  coords = 2 * M_PI * coords;
  return torch::cat({torch::sin(coords), torch::cos(coords)}, -1);
}

torch::Tensor PositionEmbeddingRandomImpl::forward(int64_t h, int64_t w) const {
  const auto opts = positional_encoding_gaussian_matrix.options();
  const auto grid = torch::ones({h, w}, opts);
  auto y_embed = grid.cumsum(0) - 0.5;
  auto x_embed = grid.cumsum(1) - 0.5;
  y_embed = y_embed / h;
  x_embed = x_embed / w;
  return pe_encoding(torch::stack({x_embed, y_embed}, -1)).permute({2, 0, 1});
}

torch::Tensor PositionEmbeddingRandomImpl::forward_with_coords(const torch::Tensor& coords_input,
                                                               std::pair<int64_t, int64_t> image_size_hw) const {
  auto coords = coords_input.clone();
  coords.index({"...", 0}).div_(double(image_size_hw.second));
  coords.index({"...", 1}).div_(double(image_size_hw.first));
  return pe_encoding(coords.to(positional_encoding_gaussian_matrix.dtype()));
}

PromptEncoderImpl::PromptEncoderImpl(const SamConfig& cfg)
    : embed_dim(cfg.prompt_embed_dim),
      image_embedding_size(cfg.image_embedding_size(), cfg.image_embedding_size()),
      input_image_size(cfg.image_size, cfg.image_size) {
  pe_layer = register_module("pe_layer", PositionEmbeddingRandom(embed_dim / 2));
  for (int i = 0; i < 4; ++i) point_embeddings->push_back(torch::nn::Embedding(1, embed_dim));
  register_module("point_embeddings", point_embeddings);
  not_a_point_embed = register_module("not_a_point_embed", torch::nn::Embedding(1, embed_dim));
  using torch::nn::Conv2dOptions;
  const int64_t c = cfg.mask_in_chans;
  mask_downscaling->push_back(torch::nn::Conv2d(Conv2dOptions(1, c / 4, 2).stride(2)));
  mask_downscaling->push_back(LayerNorm2d(c / 4));
  mask_downscaling->push_back(torch::nn::GELU());
  mask_downscaling->push_back(torch::nn::Conv2d(Conv2dOptions(c / 4, c, 2).stride(2)));
  mask_downscaling->push_back(LayerNorm2d(c));
  mask_downscaling->push_back(torch::nn::GELU());
  mask_downscaling->push_back(torch::nn::Conv2d(Conv2dOptions(c, embed_dim, 1)));
  register_module("mask_downscaling", mask_downscaling);
  no_mask_embed = register_module("no_mask_embed", torch::nn::Embedding(1, embed_dim));
}

torch::Tensor PromptEncoderImpl::point_embedding(size_t i) const {
  return point_embeddings->ptr(i)->as<torch::nn::EmbeddingImpl>()->weight;
}

torch::Tensor PromptEncoderImpl::embed_points(torch::Tensor points, torch::Tensor labels, bool pad) const {
  points = points + 0.5;  // shift to the pixel centre
  if (pad) {
    const auto padding_point = torch::zeros({points.size(0), 1, 2}, points.options());
    const auto padding_label = -torch::ones({labels.size(0), 1}, labels.options());
    points = torch::cat({points, padding_point}, 1);
    labels = torch::cat({labels, padding_label}, 1);
  }
  auto pe = pe_layer->forward_with_coords(points, input_image_size);
  const auto lab = labels.unsqueeze(-1);
  const auto na = not_a_point_embed->weight.view({1, 1, -1});
  const auto bg = point_embedding(0).view({1, 1, -1});
  const auto fg = point_embedding(1).view({1, 1, -1});
  // point_embedding[labels == -1] = 0 then += not_a_point; [labels == 0] += bg; [labels == 1] += fg.
  pe = torch::where(lab == -1, torch::zeros_like(pe) + na, pe);
  pe = torch::where(lab == 0, pe + bg, pe);
  pe = torch::where(lab == 1, pe + fg, pe);
  return pe;
}

torch::Tensor PromptEncoderImpl::embed_boxes(const torch::Tensor& boxes) const {
  const auto coords = (boxes + 0.5).reshape({-1, 2, 2});
  auto corners = pe_layer->forward_with_coords(coords, input_image_size);
  const auto tl = point_embedding(2);
  const auto br = point_embedding(3);
  return torch::stack({corners.index({Slice(), 0, Slice()}) + tl, corners.index({Slice(), 1, Slice()}) + br}, 1);
}

torch::Tensor PromptEncoderImpl::embed_masks(const torch::Tensor& masks) { return mask_downscaling->forward(masks); }

torch::Tensor PromptEncoderImpl::get_dense_pe() const {
  return pe_layer->forward(image_embedding_size.first, image_embedding_size.second).unsqueeze(0);
}

PromptEmbeddings PromptEncoderImpl::forward(const torch::Tensor& point_coords, const torch::Tensor& point_labels,
                                            const torch::Tensor& boxes, const torch::Tensor& masks) {
  int64_t bs = 1;
  if (point_coords.defined()) bs = point_coords.size(0);
  else if (boxes.defined()) bs = boxes.size(0);
  else if (masks.defined()) bs = masks.size(0);
  const auto opts = not_a_point_embed->weight.options();
  PromptEmbeddings out;
  out.sparse = torch::empty({bs, 0, embed_dim}, opts);
  if (point_coords.defined())
    out.sparse = torch::cat({out.sparse, embed_points(point_coords, point_labels, /*pad=*/!boxes.defined())}, 1);
  if (boxes.defined()) out.sparse = torch::cat({out.sparse, embed_boxes(boxes)}, 1);
  if (masks.defined())
    out.dense = embed_masks(masks);
  else
    out.dense = dense_without_mask(bs);
  return out;
}

torch::Tensor PromptEncoderImpl::dense_without_mask(int64_t bs) const {
  return no_mask_embed->weight.reshape({1, -1, 1, 1}).expand({bs, -1, image_embedding_size.first, image_embedding_size.second});
}

}  // namespace cls::sam
