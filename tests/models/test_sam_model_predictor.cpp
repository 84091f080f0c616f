// SamPredictor on the tiny reference model against the reference outputs of tests/fixtures/sam/:
// the preprocessed input (bit-exact), the image embedding, and for every prompt set the sparse and
// dense prompt embeddings, IoU predictions, low-res logits and full-size mask logits with
// multimask on and off. Tolerances: the fixture README's suggested checks for a float32 port
// (embedding atol 1e-4; logits atol 1e-3 + rtol 1e-4; IoU atol 1e-5).
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/hash.h"
#include "models/sam/sam_predictor.h"
#include "sam_fixture.h"

namespace cls::sam {
namespace {

using testing::compare;
using testing::load_npy_tensor;
using testing::sam_fixture;
using torch::indexing::None;
using torch::indexing::Slice;

constexpr double kLogitAtol = 1e-3, kLogitRtol = 1e-4, kIouAtol = 1e-5;

cv::Mat test_image_rgb() {
  cv::Mat bgr = cv::imread(sam_fixture("test_image.png"), cv::IMREAD_COLOR);
  EXPECT_FALSE(bgr.empty());
  cv::Mat rgb;
  cv::cvtColor(bgr, rgb, cv::COLOR_BGR2RGB);
  return rgb;
}

// The fixture's prompts.json: image and model-input sizes, the prompt sets and their transformed points.
const nlohmann::json& prompts() {
  static const nlohmann::json p = nlohmann::json::parse(read_text_file(sam_fixture("prompts.json")));
  return p;
}
std::pair<int, int> hw_of(const char* key) { return {prompts().at(key)[0].get<int>(), prompts().at(key)[1].get<int>()}; }
const nlohmann::json& prompt_set(const std::string& name) {
  for (const auto& set : prompts().at("prompt_sets"))
    if (set.at("name") == name) return set;
  throw std::runtime_error("prompts.json has no prompt set " + name);
}
// The side of the decoder's low-res masks (= of mask_input): the first mask_input's [1, S, S].
int64_t low_res_side() {
  for (const auto& set : prompts().at("prompt_sets"))
    if (set.contains("mask_input")) return load_npy_tensor(set["mask_input"].get<std::string>()).size(-1);
  throw std::runtime_error("prompts.json has no prompt set with a mask_input");
}

// The FNV-1a 64 of input_image.npy's data block that SAM_MODEL_FILES.md records where the 12.5 MB
// file itself was not copied ("... hash of its float32 data block (`<16 hex digits>`) ...").
std::string recorded_input_image_hash() {
  const std::string md = read_text_file(sam_fixture("SAM_MODEL_FILES.md"));
  const size_t at = md.find("FNV-1a 64 hash");
  const size_t open = at == std::string::npos ? at : md.find('`', at);
  if (open == std::string::npos) throw std::runtime_error("SAM_MODEL_FILES.md records no FNV-1a 64 hash");
  return md.substr(open + 1, md.find('`', open + 1) - open - 1);
}

TEST(SamPredictor, PreprocessedInputIsBitExact) {
  SamPredictor predictor(testing::load_tiny_sam());
  const cv::Mat rgb = test_image_rgb();
  const auto [h, w] = hw_of("image_size_hw");
  const auto [input_h, input_w] = hw_of("input_size_hw");
  ASSERT_EQ(rgb.rows, h);
  ASSERT_EQ(rgb.cols, w);
  const auto input = predictor.transformed_input(rgb.data, rgb.rows, rgb.cols).cpu().contiguous();
  const int64_t side = input.size(3);  // the encoder's square input
  ASSERT_EQ(input.sizes(), (std::vector<int64_t>{1, 3, side, side}));
  // The zero padding below and right of the resized image.
  EXPECT_EQ(input.index({0, Slice(), Slice(input_h, None), Slice()}).abs().sum().item<float>(), 0.0f);
  EXPECT_EQ(input.index({0, Slice(), Slice(), Slice(input_w, None)}).abs().sum().item<float>(), 0.0f);
  // Bit-exact: against input_image.npy where the fixture set has it, else against its recorded hash.
  if (std::filesystem::exists(sam_fixture("input_image.npy"))) {
    const auto ref = load_npy_tensor("input_image.npy");
    ASSERT_EQ(input.sizes(), ref.sizes());
    const auto differ = input.ne(ref);
    EXPECT_EQ(differ.sum().item<int64_t>(), 0)
        << "first differing element (flat) " << differ.flatten().nonzero()[0].item<int64_t>();
  } else {
    const std::string bytes(static_cast<const char*>(input.data_ptr()), size_t(input.numel()) * sizeof(float));
    EXPECT_EQ(fnv1a64_hex(bytes), recorded_input_image_hash());
  }
}

TEST(SamPredictor, ImageEmbeddingMatchesReference) {
  SamPredictor predictor(testing::load_tiny_sam());
  const cv::Mat rgb = test_image_rgb();
  predictor.set_image(rgb.data, rgb.rows, rgb.cols);
  EXPECT_EQ(predictor.input_size(), hw_of("input_size_hw"));
  EXPECT_EQ(predictor.original_size(), hw_of("image_size_hw"));
  const auto ref = load_npy_tensor("image_embedding.npy");
  ASSERT_EQ(predictor.features().sizes(), ref.sizes());
  const auto d = compare(predictor.features(), ref, 1e-4, 0);
  EXPECT_LE(d.worst_excess, 0) << "max |diff| " << d.max_abs;
}

SamPrompt prompt_of(const nlohmann::json& set) {
  SamPrompt p;
  if (set.contains("point_coords")) {
    for (const auto& xy : set["point_coords"]) p.points.push_back({xy[0].get<double>(), xy[1].get<double>()});
    p.labels = set["point_labels"].get<std::vector<int>>();
  }
  if (set.contains("box")) {
    const auto b = set["box"].get<std::vector<double>>();
    p.box = std::array<double, 4>{b[0], b[1], b[2], b[3]};
  }
  if (set.contains("mask_input")) p.mask_input = load_npy_tensor(set["mask_input"].get<std::string>());
  return p;
}

// The reference file if it was copied whole, else its [..., ::4, ::4] sample (<name>_stride4.npy);
// `ours` is sampled the same way.
void expect_logits(const std::string& file, const torch::Tensor& ours, const std::string& what) {
  const std::string full = sam_fixture(file);
  torch::Tensor ref, mine = ours.cpu();
  if (std::filesystem::exists(full)) {
    ref = load_npy_tensor(file);
    // Binary masks: no sign flip where the reference logit is clearly away from 0.
    const auto flips = ((mine > 0) != (ref > 0)) & (ref.abs() >= 1e-3);
    EXPECT_EQ(flips.sum().item<int64_t>(), 0) << what;
  } else {
    ref = load_npy_tensor(file.substr(0, file.size() - 4) + "_stride4.npy");
    mine = ours.index({"...", Slice(None, None, 4), Slice(None, None, 4)});
  }
  ASSERT_EQ(mine.sizes(), ref.sizes()) << what;
  const auto d = compare(mine, ref, kLogitAtol, kLogitRtol);
  EXPECT_LE(d.worst_excess, 0) << what << ": max |diff| " << d.max_abs;
}

TEST(SamPredictor, DecoderMatchesReferenceForEveryPromptSet) {
  SamPredictor predictor(testing::load_tiny_sam());
  // The decoder is checked on the reference embedding, independently of the encoder.
  predictor.set_features(load_npy_tensor("image_embedding.npy"), hw_of("image_size_hw"));
  const auto [h, w] = hw_of("image_size_hw");
  size_t sets = 0;
  for (const auto& set : prompts().at("prompt_sets")) {
    const auto name = set["name"].get<std::string>();
    SCOPED_TRACE(name);
    const SamPrompt prompt = prompt_of(set);

    // Prompt embeddings, with the tensors predict() builds (coords transformed in float64 -> float32).
    {
      torch::Tensor coords, labels, box, mask;
      if (set.contains("point_coords_transformed")) {
        std::vector<double> flat;
        for (const auto& xy : set["point_coords_transformed"]) flat.push_back(xy[0]), flat.push_back(xy[1]);
        coords = torch::tensor(flat, torch::kDouble).view({1, -1, 2}).to(torch::kFloat);
        labels = torch::tensor(set["point_labels"].get<std::vector<int>>(), torch::kInt).view({1, -1});
      }
      if (set.contains("box_transformed"))
        box = torch::tensor(set["box_transformed"][0].get<std::vector<double>>(), torch::kDouble).view({1, 4}).to(torch::kFloat);
      if (prompt.mask_input.defined()) mask = prompt.mask_input.unsqueeze(0);
      for (torch::Tensor* t : {&coords, &labels, &box, &mask})
        if (t->defined()) *t = t->to(predictor.device());
      torch::NoGradGuard no_grad;
      const auto emb = predictor.model()->prompt_encoder->forward(coords, labels, box, mask);
      const auto ref_sparse = load_npy_tensor(set["sparse_embeddings"].get<std::string>());
      ASSERT_EQ(emb.sparse.sizes(), ref_sparse.sizes());
      EXPECT_LE(compare(emb.sparse, ref_sparse, 1e-5, 0).worst_excess, 0) << "sparse embeddings";
      if (set.contains("dense_embeddings")) {
        const auto ref_dense = load_npy_tensor(set["dense_embeddings"].get<std::string>());
        ASSERT_EQ(emb.dense.sizes(), ref_dense.sizes());
        EXPECT_LE(compare(emb.dense, ref_dense, 1e-4, 0).worst_excess, 0) << "dense embeddings";
      }
    }

    for (const bool multimask : {false, true}) {
      const auto& files = set["files"][multimask ? "mm1" : "mm0"];
      const std::string what = name + (multimask ? " mm1" : " mm0");
      const auto out = predictor.predict(prompt, multimask, /*return_logits=*/true);
      const auto ref_iou = load_npy_tensor(files["iou_predictions"].get<std::string>());
      ASSERT_EQ(out.iou_predictions.sizes(), ref_iou.sizes()) << what;
      const auto di = compare(out.iou_predictions, ref_iou, kIouAtol, 0);
      EXPECT_LE(di.worst_excess, 0) << what << " iou: max |diff| " << di.max_abs;
      expect_logits(files["low_res_logits"].get<std::string>(), out.low_res_logits, what + " low-res logits");
      if (files.contains("masks_logits")) {
        ASSERT_EQ(out.masks.sizes(), (std::vector<int64_t>{1, multimask ? testing::num_multimask_outputs() : 1, h, w}))
            << what;
        expect_logits(files["masks_logits"].get<std::string>(), out.masks, what + " mask logits");
      }
    }
    ++sets;
  }
  EXPECT_GT(sets, 0u);
  EXPECT_EQ(sets, prompts().at("prompt_sets").size());
}

TEST(SamPredictor, BatchedFloat64PointsAsTheAmgPassesThem) {
  SamPredictor predictor(testing::load_tiny_sam());
  predictor.set_features(load_npy_tensor("image_embedding.npy"), hw_of("image_size_hw"));
  // Two single-point prompts in one batch, float64 coordinates in the model-input frame: the first is
  // p0_point's point, so its row must reproduce p0_point's multimask outputs; the second is the
  // background point of p1_points_fg_bg.
  const auto& p0 = prompt_set("p0_point").at("point_coords_transformed")[0];
  const auto& p1 = prompt_set("p1_points_fg_bg").at("point_coords_transformed")[1];
  const auto coords = torch::tensor({p0[0].get<double>(), p0[1].get<double>(), p1[0].get<double>(), p1[1].get<double>()},
                                    torch::kDouble)
                          .view({2, 1, 2});
  const auto [h, w] = hw_of("image_size_hw");
  const int64_t k = testing::num_multimask_outputs(), low_res = low_res_side();
  const auto& p0_files = prompt_set("p0_point").at("files").at("mm1");
  const auto labels = torch::ones({2, 1}, torch::kInt);
  const auto out = predictor.predict_batch(coords, labels, {}, {}, /*multimask_output=*/true, /*return_logits=*/true);
  ASSERT_EQ(out.masks.sizes(), (std::vector<int64_t>{2, k, h, w}));
  ASSERT_EQ(out.low_res_logits.sizes(), (std::vector<int64_t>{2, k, low_res, low_res}));
  ASSERT_EQ(out.iou_predictions.sizes(), (std::vector<int64_t>{2, k}));
  const auto p0_iou = load_npy_tensor(p0_files.at("iou_predictions").get<std::string>());
  EXPECT_LE(compare(out.iou_predictions.slice(0, 0, 1), p0_iou, kIouAtol, 0).worst_excess, 0);
  expect_logits(p0_files.at("low_res_logits").get<std::string>(), out.low_res_logits.slice(0, 0, 1), "batched low-res");
  expect_logits(p0_files.at("masks_logits").get<std::string>(), out.masks.slice(0, 0, 1), "batched masks");
  // The second prompt is not the first one again.
  EXPECT_GT((out.low_res_logits[1] - out.low_res_logits[0]).abs().max().item<float>(), 1.0f);
  // Binary output = logits > mask_threshold.
  const auto bin = predictor.predict_batch(coords, labels, {}, {}, true, /*return_logits=*/false);
  EXPECT_EQ(bin.masks.scalar_type(), torch::kBool);
  EXPECT_TRUE(torch::equal(bin.masks.cpu(), (out.masks > 0.0).cpu()));
}

TEST(SamPredictor, BadCallsAreErrors) {
  SamPredictor predictor(testing::load_tiny_sam());
  SamPrompt p;
  p.points = {{1.0, 2.0}};
  p.labels = {1};
  EXPECT_THROW(predictor.predict(p), Error);
  const auto emb = load_npy_tensor("image_embedding.npy").sizes().vec();  // [1, C, H, W] of this model
  predictor.set_features(torch::zeros(emb), {10, 10});
  p.labels.clear();
  EXPECT_THROW(predictor.predict(p), Error);
  EXPECT_THROW(predictor.set_features(torch::zeros({1, emb[1] / 2, emb[2], emb[3]}), {10, 10}), Error);
  p.points.clear();
  const int64_t low_res = low_res_side();
  p.mask_input = torch::zeros({1, low_res / 2, low_res / 2});  // must be 1 x low_res x low_res
  EXPECT_THROW(predictor.predict(p), Error);
}

}  // namespace
}  // namespace cls::sam
