// SAM building blocks against hand-computed cases and independent formulas: Pillow's bilinear
// resize, ResizeLongestSide, window partition, relative-position tables, the dense positional
// encoding, weight-loading errors and the official ViT-B/L/H state_dict layouts; the banded encoder
// attention, the decoder's folded and shared cross-attention and its channel-last upscaling against the
// reference's order, in double.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "core/atomic_file.h"
#include "core/error.h"
#include "models/sam/image_encoder.h"
#include "models/sam/mask_decoder.h"
#include "models/sam/resize_longest_side.h"
#include "models/sam/two_way_transformer.h"
#include "sam_fixture.h"

namespace cls::sam {
namespace {

using testing::sam_fixture;

TEST(SamResize, PreprocessShapeRoundsLikeTheReference) {
  EXPECT_EQ(preprocess_shape(302, 403, 1024), std::make_pair(767, 1024));  // 302 * 1024/403 = 767.37
  EXPECT_EQ(preprocess_shape(750, 1000, 1024), std::make_pair(768, 1024));
  EXPECT_EQ(preprocess_shape(1024, 10, 1024), std::make_pair(1024, 10));
  EXPECT_EQ(preprocess_shape(2, 3, 1024), std::make_pair(683, 1024));  // 682.67 + 0.5 -> 683
  // another input side and a portrait image: scale 512 / 403, so 302 columns -> int(383.7 + 0.5) = 384
  EXPECT_EQ(preprocess_shape(403, 302, 512), std::make_pair(512, 384));
}

TEST(SamResize, ApplyCoordsByHand) {
  ResizeLongestSide t;  // 1024
  double p[2] = {403.0, 151.0};
  t.apply_coords(p, 1, {302, 403});
  EXPECT_DOUBLE_EQ(p[0], 1024.0);
  EXPECT_DOUBLE_EQ(p[1], 151.0 * 767.0 / 302.0);
  t.target_length = 512;
  double q[2] = {151.0, 403.0};
  t.apply_coords(q, 1, {403, 302});
  EXPECT_DOUBLE_EQ(q[0], 151.0 * 384.0 / 302.0);
  EXPECT_DOUBLE_EQ(q[1], 512.0);
}

TEST(SamResize, PillowBilinearUpscaleByHand) {
  // 1 x 2 -> 1 x 4: centres 0.25, 0.75, 1.25, 1.75 give weights (1), (.75,.25), (.25,.75), (1).
  const uint8_t a[2] = {0, 200};
  EXPECT_EQ(resize_bilinear_pil(a, 1, 2, 1, 1, 4), (std::vector<uint8_t>{0, 50, 150, 200}));
  // Fixed-point rounding: 0.25 -> 0, 0.75 -> 1.
  const uint8_t b[2] = {0, 1};
  EXPECT_EQ(resize_bilinear_pil(b, 1, 2, 1, 1, 4), (std::vector<uint8_t>{0, 0, 1, 1}));
  // The same along the vertical axis, channels kept apart.
  const uint8_t c[4] = {0, 10, 200, 30};  // 2 x 1 x 2
  EXPECT_EQ(resize_bilinear_pil(c, 2, 1, 2, 4, 1), (std::vector<uint8_t>{0, 10, 50, 15, 150, 25, 200, 30}));
}

TEST(SamResize, PillowBilinearDownscaleAntiAliases) {
  // 4 -> 2: scale 2, support 2. Output 0: centre 1, pixels 0..2 with weights .75, .75, .25 (sum
  // 1.75); output 1: centre 3, pixels 1..3 with .25, .75, .75. So pixel 2 (70) contributes
  // 70 * .25/1.75 = 10 and 70 * .75/1.75 = 30.
  const uint8_t a[4] = {0, 0, 70, 0};
  EXPECT_EQ(resize_bilinear_pil(a, 1, 4, 1, 1, 2), (std::vector<uint8_t>{10, 30}));
}

TEST(SamResize, ApplyCoordsMatchesPromptsJson) {
  const auto prompts = nlohmann::json::parse(read_text_file(sam_fixture("prompts.json")));
  ResizeLongestSide t;
  t.target_length = testing::img_size();  // as SamPredictor sets it from the model
  const std::pair<int, int> hw{prompts.at("image_size_hw")[0].get<int>(), prompts.at("image_size_hw")[1].get<int>()};
  for (const auto& set : prompts.at("prompt_sets")) {
    if (set.contains("point_coords")) {
      for (size_t i = 0; i < set["point_coords"].size(); ++i) {
        double xy[2] = {set["point_coords"][i][0].get<double>(), set["point_coords"][i][1].get<double>()};
        t.apply_coords(xy, 1, hw);
        EXPECT_DOUBLE_EQ(xy[0], set["point_coords_transformed"][i][0].get<double>());
        EXPECT_DOUBLE_EQ(xy[1], set["point_coords_transformed"][i][1].get<double>());
      }
    }
    if (set.contains("box")) {
      auto box = set["box"].get<std::vector<double>>();
      t.apply_coords(box.data(), 2, hw);
      for (int k = 0; k < 4; ++k) EXPECT_DOUBLE_EQ(box[k], set["box_transformed"][0][k].get<double>());
    }
  }
}

TEST(SamImageEncoder, WindowPartitionPadsAndRoundTrips) {
  const auto x = torch::arange(2 * 5 * 7 * 3, torch::kFloat).view({2, 5, 7, 3});
  auto [windows, pad_hw] = window_partition(x, 4);
  EXPECT_EQ(pad_hw.first, 8);
  EXPECT_EQ(pad_hw.second, 8);
  ASSERT_EQ(windows.sizes(), (std::vector<int64_t>{2 * 2 * 2, 4, 4, 3}));
  // Window 1 of image 0 = rows 0..3, columns 4..7 (row-major windows); column 7 is padding.
  EXPECT_TRUE(torch::equal(windows[1].index({torch::indexing::Slice(), torch::indexing::Slice(0, 3)}),
                           x[0].index({torch::indexing::Slice(0, 4), torch::indexing::Slice(4, 7)})));
  EXPECT_EQ(windows[1].index({0, 3}).abs().sum().item<float>(), 0.0f);
  EXPECT_TRUE(torch::equal(window_unpartition(windows, 4, pad_hw, {5, 7}), x));
}

TEST(SamImageEncoder, RelPosTableByHand) {
  // Equal sizes, no interpolation: R[i, j] = rel_pos[i - j + k - 1].
  const auto rel = torch::arange(5, torch::kFloat).view({5, 1});
  const auto r = get_rel_pos(3, 3, rel).squeeze(-1);
  EXPECT_TRUE(torch::equal(r, torch::tensor({{2.f, 1.f, 0.f}, {3.f, 2.f, 1.f}, {4.f, 3.f, 2.f}})));
  // q = 2, k = 4: q coords scaled by 2; index = 2i - j + 3; table length 7.
  const auto rel7 = torch::arange(7, torch::kFloat).view({7, 1});
  EXPECT_TRUE(torch::equal(get_rel_pos(2, 4, rel7).squeeze(-1), torch::tensor({{3.f, 2.f, 1.f, 0.f}, {5.f, 4.f, 3.f, 2.f}})));
  // Interpolation 3 -> 5 (linear, align_corners=False): src = (i + 0.5) * 3/5 - 0.5, clamped at 0.
  const auto r3 = torch::tensor({0.f, 10.f, 40.f}).view({3, 1});
  const auto t = get_rel_pos(3, 3, r3).squeeze(-1);
  // Resized table: positions 0.0(clamped from -0.2), 0.4, 1.0, 1.6, 2.2(clamped to 2) ->
  // 0, 4, 10, 28, 40. R[i, 0] = table[i + 2].
  EXPECT_NEAR(t[0][0].item<float>(), 10.0f, 1e-5);
  EXPECT_NEAR(t[1][0].item<float>(), 28.0f, 1e-5);
  EXPECT_NEAR(t[2][0].item<float>(), 40.0f, 1e-5);
  EXPECT_NEAR(t[0][2].item<float>(), 0.0f, 1e-5);
  EXPECT_NEAR(t[0][1].item<float>(), 4.0f, 1e-5);
}

TEST(SamImageEncoder, BandedAttentionEqualsTheWholeMatrixInDouble) {
  // A 48 x 48 global grid: one attention row of 2304 keys is 442 KB, so the bands (16 MB, divided
  // among the threads that take bands side by side) hold 37 of the 48 query rows or fewer, and each
  // head takes two bands or more.
  torch::manual_seed(3);
  const int64_t dim = 16, heads = 2, side = 48;
  ViTAttention attn(dim, heads, /*qkv_bias=*/true, /*use_rel_pos=*/true, std::make_pair(side, side));
  attn->to(torch::kDouble);
  {
    torch::NoGradGuard no_grad;
    attn->rel_pos_h.normal_(0, 0.3), attn->rel_pos_w.normal_(0, 0.3);
  }
  const auto x = torch::randn({1, side, side, dim}, torch::kDouble);
  torch::NoGradGuard no_grad;
  // The reference's order: the whole [heads, N, N] matrix at once.
  const int64_t n = side * side;
  const auto qkv = attn->qkv(x).reshape({1, n, 3, heads, -1}).permute({2, 0, 3, 1, 4}).reshape({3, heads, n, -1});
  const auto q = qkv[0], k = qkv[1], v = qkv[2];
  const auto Rh = get_rel_pos(side, side, attn->rel_pos_h), Rw = get_rel_pos(side, side, attn->rel_pos_w);
  auto a = add_decomposed_rel_pos(torch::matmul(q * attn->scale, k.transpose(-2, -1)), q, Rh, Rw, {side, side}, {side, side});
  const auto out = torch::matmul(a.softmax(-1), v).view({1, heads, side, side, -1}).permute({0, 2, 3, 1, 4}).reshape({1, side, side, -1});
  const auto expected = attn->proj(out);
  // Bands one after another (one thread) and side by side, with the linear layers split by rows.
  const int threads = at::get_num_threads();
  for (const int n : {1, 2}) {
    at::set_num_threads(n);
    EXPECT_LT((attn(x) - expected).abs().max().item<double>(), 1e-12) << n << " threads";
  }
  at::set_num_threads(threads);
}

TEST(SamMaskDecoder, FoldedCrossAttentionEqualsTheReferenceOrderInDouble) {
  // The decoder's own sizes (config.json); 3 prompts of 7 tokens against a 9 x 11 image.
  const auto& t = testing::sam_config_json().at("mask_decoder").at("transformer");
  const int64_t dim = t.at("embedding_dim"), heads = t.at("num_heads"), down = t.at("attention_downsample_rate");
  torch::manual_seed(4);
  DecoderAttention attn(dim, heads, down);
  attn->to(torch::kDouble);
  const int64_t B = 3, T = 7, N = 99;
  const auto tokens = torch::randn({B, T, dim}, torch::kDouble), tokens_pe = torch::randn({B, T, dim}, torch::kDouble);
  const auto image = torch::randn({B, N, dim}, torch::kDouble), image_pe = torch::randn({B, N, dim}, torch::kDouble);
  torch::NoGradGuard no_grad;
  const auto max_diff = [](const torch::Tensor& a, const torch::Tensor& b) { return (a - b).abs().max().item<double>(); };
  // One image per prompt.
  EXPECT_LT(max_diff(attn->tokens_to_image(tokens, image_pe, image), attn(tokens, image_pe, image)), 1e-12);
  EXPECT_LT(max_diff(attn->image_to_tokens(image_pe, tokens_pe, tokens), attn(image_pe, tokens_pe, tokens)), 1e-12);
  // One image shared by every prompt: the reference repeats it.
  const auto one = image.narrow(0, 0, 1), one_pe = image_pe.narrow(0, 0, 1);
  const auto rep = one.expand({B, N, dim}), rep_pe = one_pe.expand({B, N, dim});
  EXPECT_LT(max_diff(attn->tokens_to_image(tokens, one_pe, one), attn(tokens, rep_pe, rep)), 1e-12);
  EXPECT_LT(max_diff(attn->image_to_tokens(one_pe, tokens_pe, tokens), attn(rep_pe, tokens_pe, tokens)), 1e-12);
  // The same with the shared image's projections made once (SharedImageSide).
  EXPECT_LT(max_diff(attn->tokens_to_projected_image(tokens, attn->k_proj(one_pe[0]), attn->v_proj(one[0])),
                     attn(tokens, rep_pe, rep)),
            1e-12);
  EXPECT_LT(max_diff(attn->projected_image_to_tokens(attn->q_proj(one_pe[0]), tokens_pe, tokens),
                     attn(rep_pe, tokens_pe, tokens)),
            1e-12);
  // Added in place to a residual the caller owns: residual + attention, in the residual's storage.
  const auto residual = torch::randn({B, N, dim}, torch::kDouble);
  for (const bool projected : {false, true}) {
    auto into = residual.clone();
    const auto sum = projected ? attn->projected_image_to_tokens(attn->q_proj(one_pe[0]), tokens_pe, tokens, into)
                               : attn->image_to_tokens(one_pe, tokens_pe, tokens, into);
    EXPECT_EQ(sum.data_ptr(), into.data_ptr());
    EXPECT_LT(max_diff(sum, residual + attn(rep_pe, tokens_pe, tokens)), 1e-12);
  }
}

TEST(SamMaskDecoder, ChannelLastUpscalingEqualsTheReferenceModulesInDouble) {
  // The fixture's decoder sizes; random weights (LayerNorm2d's affine too), 2 prompts on a 5 x 7 grid.
  const auto cfg = sam_config_from_json_file(sam_fixture("config.json"));
  torch::manual_seed(5);
  MaskDecoder dec(cfg);
  dec->to(torch::kDouble);
  torch::NoGradGuard no_grad;
  for (auto& p : dec->output_upscaling->parameters()) p.normal_(0, 0.5);
  const int64_t b = 2, h = 5, w = 7, c = cfg.prompt_embed_dim, m = dec->num_mask_tokens;
  const auto keys = torch::randn({b, h * w, c}, torch::kDouble);
  const auto hyper = torch::randn({b, m, c / 8}, torch::kDouble);
  // mask_decoder.py: upscale the [b, C, h, w] embedding with the modules, then hyper_in @ upscaled.
  const auto upscaled = dec->output_upscaling->forward(keys.transpose(1, 2).reshape({b, c, h, w}));
  const auto expected = torch::matmul(hyper, upscaled.view({b, c / 8, 16 * h * w})).view({b, m, 4 * h, 4 * w});
  const auto got = dec->masks_from_keys(keys, hyper, h, w);
  ASSERT_EQ(got.sizes(), expected.sizes());
  EXPECT_LT((got - expected).abs().max().item<double>(), 1e-12);
}

TEST(SamPromptEncoder, DensePeMatchesTheFormulaInDouble) {
  Sam model = testing::load_tiny_sam();
  const auto pe = model->prompt_encoder->get_dense_pe();  // [1, C, H, W]: the embedding grid
  const auto G = model->prompt_encoder->pe_layer->positional_encoding_gaussian_matrix.to(torch::kDouble);
  const auto& pc = testing::sam_config_json().at("prompt_encoder");
  const int64_t C = pc.at("embed_dim"), H = pc.at("image_embedding_size")[0], W = pc.at("image_embedding_size")[1];
  ASSERT_EQ(pe.sizes(), (std::vector<int64_t>{1, C, H, W}));
  const int F = int(G.size(1));
  ASSERT_EQ(2 * F, C);
  double worst = 0;
  for (int i = 0; i < H; i += 7)
    for (int j = 0; j < W; j += 5) {
      const double cx = 2 * ((j + 0.5) / W) - 1, cy = 2 * ((i + 0.5) / H) - 1;
      for (int f = 0; f < F; ++f) {
        const double a = 2 * M_PI * (cx * G[0][f].item<double>() + cy * G[1][f].item<double>());
        worst = std::max(worst, std::abs(pe[0][f][i][j].item<double>() - std::sin(a)));
        worst = std::max(worst, std::abs(pe[0][F + f][i][j].item<double>() - std::cos(a)));
      }
    }
  EXPECT_LT(worst, 1e-5);  // reference fp32 vs fp64: 2.9e-6
}

WeightFile tiny_weights_copy(Sam& model) {
  WeightFile w("synthetic.safetensors");
  for (const auto& [name, t] : sam_state_names(*model)) w.add(name, t.detach().clone());
  return w;
}

std::string load_error(Sam& model, const WeightFile& w) {
  try {
    load_sam_weights(*model, w);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(SamWeights, LoadErrorsNameTheFileAndTensor) {
  Sam model(sam_config_from_json_file(sam_fixture("config.json")));
  // Shapes of this fixture's tensors, from its weight file.
  const WeightFile ref = read_safetensors(sam_fixture("weights.safetensors"));
  {
    auto w = tiny_weights_copy(model);
    w.remove("mask_decoder.iou_token.weight");
    const auto msg = load_error(model, w);
    EXPECT_NE(msg.find("synthetic.safetensors"), std::string::npos) << msg;
    EXPECT_NE(msg.find("missing tensor mask_decoder.iou_token.weight"), std::string::npos) << msg;
  }
  {
    // A rel_pos table one row longer than the model's (the first global block's, else block 0's).
    const auto& cfg = testing::sam_config_json();
    ASSERT_TRUE(cfg.at("use_rel_pos").get<bool>()) << "this case needs rel_pos tables";
    const auto& global = cfg.at("global_attn_indexes");
    const std::string rel = "image_encoder.blocks." + std::to_string(global.empty() ? 0 : global.at(0).get<int>()) +
                            ".attn.rel_pos_h";
    const auto want = ref.info(rel).shape;
    const std::vector<int64_t> wrong{want.at(0) + 1, want.at(1)};
    auto dims = [](const std::vector<int64_t>& v) {  // "[rows, cols]", spelled out here, not by the loader's formatter
      return "[" + std::to_string(v.at(0)) + ", " + std::to_string(v.at(1)) + "]";
    };
    auto w = tiny_weights_copy(model);
    w.remove(rel);
    w.add(rel, torch::zeros(wrong));
    w.add("image_encoder.extra", torch::zeros({1}));
    w.remove("prompt_encoder.no_mask_embed.weight");
    w.add("prompt_encoder.no_mask_embed.weight",
          torch::zeros(ref.info("prompt_encoder.no_mask_embed.weight").shape, torch::kInt));
    const auto before = model->image_encoder->pos_embed.clone();
    const auto msg = load_error(model, w);
    EXPECT_NE(msg.find(rel + " has shape " + dims(wrong) + ", expected " + dims(want)), std::string::npos) << msg;
    EXPECT_NE(msg.find("unexpected tensor image_encoder.extra"), std::string::npos) << msg;
    EXPECT_NE(msg.find("prompt_encoder.no_mask_embed.weight is not floating point"), std::string::npos) << msg;
    EXPECT_TRUE(torch::equal(before, model->image_encoder->pos_embed));  // nothing copied
  }
  {
    // f16 weights are converted.
    auto w = tiny_weights_copy(model);
    w.remove("mask_decoder.iou_token.weight");
    w.add("mask_decoder.iou_token.weight",
          torch::full(ref.info("mask_decoder.iou_token.weight").shape, 0.5, torch::kHalf));
    load_sam_weights(*model, w);
    EXPECT_TRUE(model->mask_decoder->iou_token->weight.eq(0.5f).all().item<bool>());
  }
}

// The model's state_dict names and shapes equal the official architecture's (the real key lists).
// The models are built with their first blocks only (up to and including the first global block of
// the file's "encoder") to keep the test light; the remaining blocks repeat those.
void expect_real_layout(const std::string& file, SamConfig cfg) {
  const auto j = nlohmann::json::parse(read_text_file(sam_fixture(file)));
  const int blocks_built = j.at("encoder").at("global_attn_indexes").at(0).get<int>() + 1;
  const int depth = cfg.encoder_depth;
  cfg.encoder_depth = blocks_built;
  Sam model(cfg);
  auto names = sam_state_names(*model);
  size_t checked = 0;
  for (const auto& t : j.at("tensors")) {
    const auto name = t.at("name").get<std::string>();
    if (name.rfind("image_encoder.blocks.", 0) == 0 && std::stoi(name.substr(21)) >= blocks_built) continue;
    const auto it = names.find(name);
    ASSERT_NE(it, names.end()) << file << ": model lacks " << name;
    EXPECT_EQ(it->second.sizes().vec(), t.at("shape").get<std::vector<int64_t>>()) << name;
    ++checked;
  }
  EXPECT_EQ(checked, names.size()) << file << ": the model has tensors the official one does not";
  EXPECT_EQ(j.at("encoder").at("depth").get<int>(), depth);
}

// load_sam goes through the layout mapping: the fixture file (official names) and the same tensors
// under Hugging Face SamModel names give the same model.
TEST(SamWeights, LoadSamReadsOfficialAndHuggingFaceNames) {
  const auto cfg = sam_config_from_json_file(sam_fixture("config.json"));
  Sam official = load_sam(sam_fixture("weights.safetensors"), cfg);
  const auto ref = read_safetensors(sam_fixture("weights.safetensors"));
  std::vector<SafetensorsEntry> hf;
  for (const auto& name : ref.names()) {
    const auto t = ref.get(name);
    hf.push_back({sam_official_to_hf(name), t.scalar_type(), t.sizes().vec(), t});
  }
  const auto path = (std::filesystem::temp_directory_path() / "cls_test_sam_hf.safetensors").string();
  write_safetensors(path, hf);
  Sam from_hf = load_sam(path, cfg);
  std::filesystem::remove(path);
  const auto a = sam_state_names(*official), b = sam_state_names(*from_hf);
  ASSERT_EQ(a.size(), ref.size());
  for (const auto& [name, t] : a) {
    EXPECT_TRUE(torch::equal(t, ref.get(name))) << name;
    EXPECT_TRUE(torch::equal(t, b.at(name))) << name;
  }
}

TEST(SamWeights, OfficialLayouts) {
  expect_real_layout("real_vit_b_keys.json", sam_config_by_name("vit_b"));
  expect_real_layout("real_vit_l_keys.json", sam_config_by_name("vit_l"));
  expect_real_layout("real_vit_h_keys.json", sam_config_by_name("vit_h"));
}

}  // namespace
}  // namespace cls::sam
