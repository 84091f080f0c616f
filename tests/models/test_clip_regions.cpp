// LangSplat region crops (get_seg_img + pad_img + cv2.resize + CLIP normalisation) on hand-made
// masks against hand-computed crops, and batched region encoding against per-crop encoding.
#include <gtest/gtest.h>

#include <ATen/ATen.h>
#include <opencv2/imgproc.hpp>

#include "core/error.h"
#include "models/clip/clip_model.h"
#include "models/clip/region_crops.h"
#include "models/clip/region_encoder.h"
#include "test_clip_fixture.h"

namespace {

using namespace cls::clip;

// 6 x 4 RGB image whose pixel (x, y) is (10x + y, 100 + y, 200 - x).
cv::Mat test_image() {
  cv::Mat img(4, 6, CV_8UC3);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 6; ++x) img.at<cv::Vec3b>(y, x) = cv::Vec3b(10 * x + y, 100 + y, 200 - x);
  return img;
}

cv::Vec3b px(int x, int y) { return cv::Vec3b(10 * x + y, 100 + y, 200 - x); }
const cv::Vec3b kBlack(0, 0, 0);

void expect_image(const cv::Mat& got, const std::vector<std::vector<cv::Vec3b>>& want) {
  ASSERT_EQ(got.rows, static_cast<int>(want.size()));
  ASSERT_EQ(got.cols, static_cast<int>(want[0].size()));
  for (int y = 0; y < got.rows; ++y)
    for (int x = 0; x < got.cols; ++x) EXPECT_EQ(got.at<cv::Vec3b>(y, x), want[y][x]) << "at " << x << "," << y;
}

TEST(ClipRegions, SamBoxLeavesOutTheLastRowAndColumn) {
  cv::Mat mask = cv::Mat::zeros(4, 6, CV_8U);
  mask.at<uint8_t>(1, 1) = mask.at<uint8_t>(1, 4) = mask.at<uint8_t>(3, 2) = 1;
  const MaskBox b = sam_mask_box(mask);
  EXPECT_EQ(b.x, 1);
  EXPECT_EQ(b.y, 1);
  EXPECT_EQ(b.w, 3);  // max x 4 - min x 1
  EXPECT_EQ(b.h, 2);  // max y 3 - min y 1
  const MaskBox e = sam_mask_box(cv::Mat::zeros(4, 6, CV_8U));
  EXPECT_EQ(e.w + e.h + e.x + e.y, 0);
}

TEST(ClipRegions, WideCropIsMaskedAndCentredVertically) {
  // Mask: columns 1..4 of rows 1..2 except (2, 1); box x=1 y=1 w=3 h=1 -> the crop is row 1,
  // columns 1..3; square side 3, vertical offset (3 - 1) / 2 = 1.
  cv::Mat mask = cv::Mat::zeros(4, 6, CV_8U);
  mask(cv::Rect(1, 1, 4, 2)).setTo(1);
  mask.at<uint8_t>(1, 2) = 0;
  const cv::Mat crop = langsplat_region_crop(test_image(), mask, 3);
  expect_image(crop, {{kBlack, kBlack, kBlack}, {px(1, 1), kBlack, px(3, 1)}, {kBlack, kBlack, kBlack}});
}

TEST(ClipRegions, TallCropIsCentredHorizontally) {
  // Mask: column 2 rows 0..3 and column 3 rows 0..3 -> box x=2 y=0 w=1 h=3: crop columns 2..2,
  // rows 0..2; side 3, horizontal offset 1.
  cv::Mat mask = cv::Mat::zeros(4, 6, CV_8U);
  mask(cv::Rect(2, 0, 2, 4)).setTo(1);
  const cv::Mat crop = langsplat_region_crop(test_image(), mask, 3);
  expect_image(crop, {{kBlack, px(2, 0), kBlack}, {kBlack, px(2, 1), kBlack}, {kBlack, px(2, 2), kBlack}});
  // Odd margin: columns 1..3, rows 0..3 -> box x=1 w=2, y=0 h=3 -> side 3, offset (3 - 2) / 2 = 0.
  cv::Mat m2 = cv::Mat::zeros(4, 6, CV_8U);
  m2(cv::Rect(1, 0, 3, 4)).setTo(1);
  expect_image(langsplat_region_crop(test_image(), m2, 3),
               {{px(1, 0), px(2, 0), kBlack}, {px(1, 1), px(2, 1), kBlack}, {px(1, 2), px(2, 2), kBlack}});
}

TEST(ClipRegions, ResizeIsBilinearOfThePaddedSquare) {
  cv::Mat mask = cv::Mat::zeros(4, 6, CV_8U);
  mask(cv::Rect(0, 0, 6, 4)).setTo(1);  // box 0,0,5,3 -> 5 x 3 crop, side 5, offset 1
  cv::Mat square = cv::Mat::zeros(5, 5, CV_8UC3);
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 5; ++x) square.at<cv::Vec3b>(1 + y, x) = px(x, y);
  cv::Mat want;
  cv::resize(square, want, cv::Size(224, 224), 0, 0, cv::INTER_LINEAR);
  const cv::Mat got = langsplat_region_crop(test_image(), mask);
  ASSERT_EQ(got.size(), cv::Size(224, 224));
  EXPECT_EQ(cv::norm(got, want, cv::NORM_INF), 0.0);
  // A uniform region stays uniform through the resize.
  cv::Mat flat(8, 8, CV_8UC3, cv::Scalar(7, 8, 9));
  const cv::Mat f = langsplat_region_crop(flat, cv::Mat::ones(8, 8, CV_8U));  // box 7x7 -> all inside
  EXPECT_EQ(f.at<cv::Vec3b>(0, 0), cv::Vec3b(7, 8, 9));
  EXPECT_EQ(f.at<cv::Vec3b>(223, 223), cv::Vec3b(7, 8, 9));
}

TEST(ClipRegions, EmptyAndDegenerateMasksGiveBlackCrops) {
  const cv::Mat img = test_image();
  EXPECT_EQ(cv::countNonZero(langsplat_region_crop(img, cv::Mat::zeros(4, 6, CV_8U)).reshape(1)), 0);
  cv::Mat line = cv::Mat::zeros(4, 6, CV_8U);
  line.row(2).setTo(1);  // h = 0
  EXPECT_EQ(cv::countNonZero(langsplat_region_crop(img, line).reshape(1)), 0);
  EXPECT_THROW(langsplat_region_crop(img, cv::Mat::zeros(3, 6, CV_8U)), cls::Error);
}

TEST(ClipRegions, NormalisationUsesClipMeanAndStd) {
  const cv::Mat c(2, 2, CV_8UC3, cv::Scalar(255, 0, 128));
  const at::Tensor t = normalize_crops({c, c});
  ASSERT_EQ(t.sizes(), (std::vector<int64_t>{2, 3, 2, 2}));
  EXPECT_NEAR(t[1][0][1][1].item<float>(), (1.0 - 0.48145466) / 0.26862954, 1e-5);
  EXPECT_NEAR(t[0][1][0][0].item<float>(), (0.0 - 0.4578275) / 0.26130258, 1e-5);
  EXPECT_NEAR(t[0][2][1][0].item<float>(), (128.0 / 255.0 - 0.40821073) / 0.27577711, 1e-5);
}

TEST(ClipRegions, BatchedEncodingMatchesOneCropAtATime) {
  const std::string dir = cls::clip::testing::fixture_dir("tiny_quickgelu");
  const ClipConfig config = read_clip_config(dir + "/config.json");
  const ClipModel model(config, cls::clip::testing::load_state(dir + "/weights_rows.safetensors", config.arch.vocab_size));
  cv::Mat rgb(40, 50, CV_8UC3);
  cv::randu(rgb, 0, 256);
  std::vector<cv::Mat> masks;
  for (int i = 0; i < 5; ++i) {
    cv::Mat m = cv::Mat::zeros(40, 50, CV_8U);
    cv::circle(m, cv::Point(8 + 8 * i, 10 + 5 * i), 4 + 2 * i, cv::Scalar(1), -1);
    masks.push_back(m);
  }
  const at::Tensor batched = encode_regions(model, rgb, masks, 2);
  ASSERT_EQ(batched.sizes(), (std::vector<int64_t>{5, config.arch.embed_dim}));
  for (size_t i = 0; i < masks.size(); ++i) {
    const at::Tensor one =
        model.encode_image(normalize_crops({langsplat_region_crop(rgb, masks[i], config.arch.image_resolution)}));
    const at::Tensor want = one / one.norm(2, -1, true);
    EXPECT_TRUE(at::allclose(batched[i], want[0], 1e-5, 1e-5)) << i;
    EXPECT_NEAR(batched[i].norm().item<double>(), 1.0, 1e-5);
  }
  EXPECT_EQ(encode_regions(model, rgb, {}, 4).size(0), 0);
  EXPECT_THROW(encode_regions(model, rgb, {cv::Mat::zeros(10, 10, CV_8U)}), cls::Error);
}

}  // namespace

namespace {

TEST(ClipRegions, NormaliseRejectsMixedCrops) {
  EXPECT_THROW(cls::clip::normalize_crops({}), cls::Error);
  EXPECT_THROW(cls::clip::normalize_crops({cv::Mat::zeros(4, 4, CV_8UC3), cv::Mat::zeros(5, 5, CV_8UC3)}), cls::Error);
  EXPECT_THROW(cls::clip::normalize_crops({cv::Mat::zeros(4, 4, CV_8U)}), cls::Error);
}

}  // namespace
