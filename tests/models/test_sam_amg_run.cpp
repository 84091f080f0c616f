// The whole LangSplat AMG with the tiny fixture SAM on the fixture image, against the reference
// records (per level: count, order, mask IoU, boxes, scores), then masks_update and the seg map.
#include <gtest/gtest.h>

#include <torch/torch.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <nlohmann/json.hpp>

#include "core/atomic_file.h"
#include "core/blas_threads.h"
#include "core/error.h"
#include "core/npy.h"
#include "models/sam/resize_longest_side.h"
#include "models/sam/sam_predictor.h"
#include "models/sam_amg/langsplat_post.h"
#include "models/sam_amg/records_json.h"
#include "models/sam_amg/sam_amg_model.h"
#include "sam_amg_test_util.h"
#include "sam_fixture.h"

using namespace cls::amg;
using amg_test::amg_fixture;

namespace {

using cls::sam::testing::sam_fixture;

cls::sam::SamPredictor& tiny_predictor() {
  static cls::sam::SamPredictor* predictor = new cls::sam::SamPredictor(cls::sam::testing::load_tiny_sam());
  return *predictor;
}

struct TestImage {
  int height = 0, width = 0;
  std::vector<uint8_t> rgb;
};
const TestImage& test_image() {
  static const TestImage image = [] {
    const cls::NpyArray a = cls::read_npy(sam_fixture("test_image.npy"));
    TestImage im;
    im.height = static_cast<int>(a.shape.at(0)), im.width = static_cast<int>(a.shape.at(1));
    im.rgb.assign(a.as<uint8_t>(), a.as<uint8_t>() + a.numel());
    return im;
  }();
  return image;
}

void check_run(const std::string& run) {
  const auto records_json = nlohmann::json::parse(cls::read_text_file(amg_fixture(run + "_records.json")));
  const MaskLevels expected = levels_from_json(records_json["levels"], run);
  const AmgParams params = params_from_json(records_json["params"], run + "_records.json");
  const TestImage& im = test_image();
  SamPredictorAmgModel model(tiny_predictor());
  const MaskLevels got = generate_masks(model, im.rgb.data(), im.height, im.width, params);

  for (int l = 0; l < kNumLevels; ++l) {
    SCOPED_TRACE(run + " level " + level_name(l));
    ASSERT_EQ(got[l].size(), expected[l].size());
    int exact = 0;
    for (size_t i = 0; i < got[l].size(); ++i) {
      const MaskRecord &g = got[l][i], &e = expected[l][i];
      const double iou = amg_test::mask_iou(rle_to_mask(g.segmentation), rle_to_mask(e.segmentation));
      EXPECT_GE(iou, 0.99) << i;
      exact += g.segmentation.counts == e.segmentation.counts;
      for (int k = 0; k < 4; ++k) {
        EXPECT_LE(std::abs(g.bbox[k] - e.bbox[k]), 1) << i;
        EXPECT_EQ(g.crop_box[k], e.crop_box[k]) << i;
      }
      EXPECT_NEAR(g.predicted_iou, e.predicted_iou, 1e-5) << i;
      EXPECT_NEAR(g.stability_score, e.stability_score, 2e-3) << i;
      EXPECT_NEAR(g.point[0], e.point[0], 1e-9) << i;
      EXPECT_NEAR(g.point[1], e.point[1], 1e-9) << i;
    }
    std::cout << "[ AMG ] " << run << " " << level_name(l) << ": " << got[l].size() << " masks, " << exact
              << " bit-identical\n";
  }

  // LangSplat post-processing of *our* records and the seg map vs the reference files.
  const auto post = nlohmann::json::parse(cls::read_text_file(amg_fixture(run + "_post.json")));
  const MasksUpdateResult updated = masks_update(got, amg_test::post_params(post));
  for (int l = 0; l < kNumLevels; ++l)
    EXPECT_EQ(updated.kept[l], post["kept_input_indices"][level_name(l)].get<std::vector<int>>()) << level_name(l);
  const cls::NpyArray ref = cls::read_npy(amg_fixture(run + "_seg_map.npy"));
  const SegMap map = build_seg_map(updated.levels, im.height, im.width);
  ASSERT_EQ(static_cast<int64_t>(map.values.size()), ref.numel());
  const float* r = ref.as<float>();
  size_t differing = 0;
  for (size_t i = 0; i < map.values.size(); ++i) differing += static_cast<float>(map.values[i]) != r[i];
  std::cout << "[ AMG ] " << run << " seg map: " << differing << " differing pixels\n";
  EXPECT_EQ(differing, 0u);
}

}  // namespace

TEST(SamAmgRun, FirstBatchMatchesDebugDump) {
  // Crop 0, first points_per_batch grid points, before any filtering: the prompts and the model's outputs.
  // The dump writes NaN stability scores as a bare NaN, which is not JSON: read them as null.
  std::string text = cls::read_text_file(amg_fixture("relaxed_debug_crop0_batch0.json"));
  for (size_t at = text.find("NaN"); at != std::string::npos; at = text.find("NaN", at)) text.replace(at, 3, "null");
  const auto dump = nlohmann::json::parse(text);
  // The relaxed run's parameters; crop 0 (the whole image) uses the layer-0 grid.
  const AmgParams params = params_from_json(
      nlohmann::json::parse(cls::read_text_file(amg_fixture("relaxed_records.json")))["params"], "relaxed_records.json");
  const TestImage& im = test_image();
  ASSERT_EQ(im.height, dump["original_size_hw"][0].get<int>());
  ASSERT_EQ(im.width, dump["original_size_hw"][1].get<int>());
  auto grid = build_point_grid(params.points_per_side);
  grid.resize(std::min(grid.size(), dump["points_per_batch"].get<size_t>()));
  std::vector<Point2d> pts;
  for (const auto& g : grid) pts.push_back({g[0] * im.width, g[1] * im.height});
  cls::sam::ResizeLongestSide transform;
  transform.target_length = cls::sam::testing::img_size();
  transform.apply_coords(pts.data()->data(), pts.size(), {im.height, im.width});
  const auto expected_pts = dump["transformed_points"];
  ASSERT_EQ(pts.size(), expected_pts.size());
  for (size_t i = 0; i < pts.size(); ++i) {
    EXPECT_EQ(pts[i][0], expected_pts[i][0].get<double>());
    EXPECT_EQ(pts[i][1], expected_pts[i][1].get<double>());
  }
  // One thread, and two: on the CPU the slices of a batch decode side by side (sam_amg_model.cpp), each
  // writing its own part of the outputs.
  struct RestoreThreads {
    int threads = at::get_num_threads();
    ~RestoreThreads() { at::set_num_threads(threads); }
  } restore;
  for (const int threads : {1, 2}) {
    SCOPED_TRACE(std::to_string(threads) + " threads");
    at::set_num_threads(threads);
    SamPredictorAmgModel model(tiny_predictor());
    model.set_image(im.rgb.data(), im.height, im.width);
    std::vector<float> logits, ious;
    model.predict_points(pts, ious);
    const size_t per_point = static_cast<size_t>(cls::sam::testing::num_multimask_outputs());
    ASSERT_EQ(dump["iou_predictions"].at(0).size(), per_point);
    std::vector<int64_t> all(pts.size() * per_point);
    for (size_t m = 0; m < all.size(); ++m) all[m] = static_cast<int64_t>(m);
    model.upsample_masks(all, logits);
    ASSERT_EQ(logits.size(), all.size() * static_cast<size_t>(im.height) * im.width);
    {  // The generator upsamples only some masks: a subset, in any order, gives the same planes.
      const int64_t n = static_cast<int64_t>(all.size());
      const std::vector<int64_t> some = {17 % n, 0, 5 % n, n - 1};
      std::vector<float> sub;
      model.upsample_masks(some, sub);
      const size_t plane = static_cast<size_t>(im.height) * im.width;
      ASSERT_EQ(sub.size(), some.size() * plane);
      for (size_t i = 0; i < some.size(); ++i)
        EXPECT_TRUE(std::equal(sub.begin() + i * plane, sub.begin() + (i + 1) * plane, logits.begin() + some[i] * plane))
            << some[i];
      EXPECT_THROW(model.upsample_masks({static_cast<int64_t>(all.size())}, sub), cls::Error);
    }
    {  // An empty batch: no predictions, and nothing of the previous batch left to upsample.
      SamPredictorAmgModel empty(tiny_predictor());
      empty.set_image(im.rgb.data(), im.height, im.width);
      std::vector<float> none = {1.0f}, sub;
      empty.predict_points(pts, none);
      empty.predict_points({}, none);
      EXPECT_TRUE(none.empty());
      EXPECT_THROW(empty.upsample_masks({0}, sub), cls::Error);
    }
    const size_t plane = static_cast<size_t>(im.height) * im.width;
    for (size_t p = 0; p < pts.size(); ++p)
      for (size_t k = 0; k < per_point; ++k) {
        const float* m = logits.data() + (p * per_point + k) * plane;
        EXPECT_NEAR(ious[p * per_point + k], dump["iou_predictions"][p][k].get<double>(), 1e-5);
        const auto& s = dump["stability_score"][p][k];
        const float stab = stability_score(m, im.height, im.width, params.mask_threshold,
                                           static_cast<float>(params.stability_score_offset));
        if (s.is_number()) EXPECT_NEAR(stab, s.get<double>(), 2e-3) << p << " " << k;
        else EXPECT_TRUE(std::isnan(stab)) << p << " " << k;  // 0/0
        int64_t area = 0;
        for (size_t i = 0; i < plane; ++i) area += m[i] > 0.0f;
        EXPECT_NEAR(area, dump["mask_area"][p][k].get<int64_t>(), 3) << p << " " << k;
      }
  }
}

TEST(SamAmgRun, RelaxedMatchesReference) { check_run("relaxed"); }
// LangSplat's own parameters: 5120 prompts, about 16x the relaxed run (2-4 minutes on 2 cores, the
// slowest test of the suite): it is the acceptance check of the AMG with LangSplat's defaults.
TEST(SamAmgRun, StrictMatchesReference) { check_run("strict"); }

TEST(BlasThreads, ScopeSetsAndRestoresOpenBlasThreads) {
  // LibTorch loads OpenBLAS here on Debian; with another BLAS the guard does nothing.
  const int before = cls::blas_threads();
  if (before == 0) GTEST_SKIP() << "OpenBLAS is not the BLAS of this LibTorch";
  const int other = before == 1 ? 2 : 1;
  {
    const cls::ScopedBlasThreads guard(other);
    EXPECT_EQ(cls::blas_threads(), other);
  }
  EXPECT_EQ(cls::blas_threads(), before);
}
