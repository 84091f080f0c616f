// The image-segment provider (robustness benchmark): segments from the image alone, features from the
// ground truth under them, checked against mixtures computed here from the class directions.
#include <ATen/ATen.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <map>
#include <opencv2/imgcodecs.hpp>

#include "core/error.h"
#include "features/feature_provider.h"
#include "features/image_segment_provider.h"

namespace cls {
namespace {
namespace fs = std::filesystem;

constexpr int kW = 64, kH = 48;

// A view whose image is red left of x = 32 and blue right of it, and no label maps or coverage at all
// (the provider must not need them). Ground truth: window for x < 16, wall for 16 <= x < 48, nothing
// right of it: the colour edge and the class edges do not coincide.
struct Fixture {
  fs::path gt = fs::temp_directory_path() / ("cls_image_segments_" + std::to_string(::getpid()));
  Taxonomy taxonomy = Taxonomy::builtin();
  int window = taxonomy.find("window"), wall = taxonomy.find("wall"), building = taxonomy.find("building");
  FeatureView view;
  Fixture() {
    fs::create_directories(gt);
    view.name = "0007.jpg";  // the ground truth is looked up as 0007.png
    view.rgb = cv::Mat(kH, kW, CV_8UC3, cv::Scalar(200, 30, 30));
    view.rgb(cv::Rect(32, 0, 32, kH)).setTo(cv::Scalar(30, 30, 200));
    cv::Mat labels(kH, kW, CV_16UC1, cv::Scalar(0));
    labels(cv::Rect(0, 0, 16, kH)).setTo(window + 1);
    labels(cv::Rect(16, 0, 32, kH)).setTo(wall + 1);
    cv::imwrite((gt / "0007.png").string(), labels);
  }
  ~Fixture() { fs::remove_all(gt); }
  ImageSegmentParams params(double noise) const {
    ImageSegmentParams p;
    p.gt_labels = gt.string();
    p.base.sam_noise = p.base.gml_noise = noise;
    return p;
  }
};

// normalise(sum_c w_c u_c), computed here from the synthetic provider's class directions.
at::Tensor mix(const SyntheticFeatureProvider& classes, const std::vector<std::pair<int, double>>& weights) {
  at::Tensor v = at::zeros({classes.params().dim}, at::kDouble);
  for (const auto& [c, w] : weights) v += w * at::tensor(classes.class_vector(c)).to(at::kDouble);
  return (v / v.norm()).to(at::kFloat);
}

TEST(ImageSegmentProvider, SegmentsFollowTheImageAndFeaturesTheTruthUnderThem) {
  Fixture f;
  ImageSegmentProvider provider(f.params(0.0), f.taxonomy);
  const SyntheticFeatureProvider classes(f.params(0.0).base, f.taxonomy);
  const SamSegments s = provider.sam_segments(f.view);
  const size_t hw = size_t(kW) * kH;
  ASSERT_EQ(s.seg.size(), 4 * hw);
  // The truth at each level as this test reads the taxonomy: openings are wall at level 2, all is building
  // at level 3, -1 = background.
  auto truth = [&](int x, int level) {
    const int c = x < 16 ? f.window : x < 48 ? f.wall : -1;
    if (c < 0 || level == 1) return c;
    return level == 2 ? f.wall : f.building;
  };
  for (int level = 1; level <= 3; ++level) {
    const int32_t* seg = s.seg.data() + level * hw;
    // Away from the colour edge (smoothing blurs 2-3 px around it), one segment per colour half.
    for (int y = 0; y < kH; ++y)
      for (int x = 0; x < kW; ++x)
        if (x <= 28 || x >= 36) ASSERT_EQ(seg[y * kW + x], seg[x < 32 ? 0 : kW - 1]) << level << " " << x << " " << y;
    ASSERT_NE(seg[0], seg[kW - 1]);
    // Every segment's feature: the mix of the truth under it, counted here pixel by pixel.
    std::map<int32_t, std::map<int, double>> counts;
    for (int y = 0; y < kH; ++y)
      for (int x = 0; x < kW; ++x) counts[seg[y * kW + x]][truth(x, level)] += 1;
    for (const auto& [id, by_class] : counts) {
      const std::vector<std::pair<int, double>> weights(by_class.begin(), by_class.end());
      EXPECT_TRUE(at::allclose(s.features[id], mix(classes, weights), 1e-5, 1e-6)) << "level " << level << " segment " << id;
    }
  }
  // The default level repeats s.
  EXPECT_TRUE(at::equal(s.features[s.seg[0]], s.features[s.seg[hw]]));

  // CityGML regions: the truth under the region, whatever the region was meant to be.
  RegionMask quarter{cv::Mat::zeros(kH, kW, CV_8UC1), 1, f.wall};
  quarter.mask(cv::Rect(0, 0, 16, kH)).setTo(255);
  RegionMask at_level2 = quarter;
  at_level2.level = 2;
  const at::Tensor r = provider.region_features(f.view, {quarter, at_level2});
  EXPECT_TRUE(at::allclose(r[0], mix(classes, {{f.window, 1}}), 1e-5, 1e-6));
  EXPECT_TRUE(at::allclose(r[1], mix(classes, {{f.wall, 1}}), 1e-5, 1e-6));
  // Text as the synthetic provider with the same seed.
  EXPECT_TRUE(at::equal(provider.text_features({"window", "glass window"}),
                        SyntheticFeatureProvider(f.params(0.0).base, f.taxonomy).text_features({"window", "glass window"})));
}

TEST(ImageSegmentProvider, NoiseIsDeterministicAndOfTheGivenSize) {
  Fixture f;
  ImageSegmentProvider a(f.params(0.5), f.taxonomy), b(f.params(0.5), f.taxonomy);
  const SamSegments sa = a.sam_segments(f.view), sb = b.sam_segments(f.view);
  EXPECT_EQ(sa.seg, sb.seg);
  EXPECT_TRUE(at::equal(sa.features, sb.features));
  // Unit rows; the pure-wall left segment at level m within the noise of its class: cos = 1 / |u + 0.5 n|
  // up to n's own small projection on u (512-d: about 0.04).
  EXPECT_TRUE(at::allclose(sa.features.norm(2, 1), at::ones({sa.features.size(0)}), 1e-5, 1e-5));
  const SyntheticFeatureProvider classes(f.params(0.5).base, f.taxonomy);
  const double cos = (sa.features[sa.seg[2 * kW * kH]] * at::tensor(classes.class_vector(f.wall))).sum().item<double>();
  EXPECT_NEAR(cos, 1 / std::sqrt(1.25), 0.05);
}

TEST(ImageSegmentProvider, MissingOrMismatchedGroundTruthIsAnErrorNamingTheFile) {
  Fixture f;
  ImageSegmentProvider provider(f.params(0.5), f.taxonomy);
  FeatureView other = f.view;
  other.name = "0008.png";
  try {
    provider.sam_segments(other);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("0008.png"), std::string::npos) << e.what();
  }
  FeatureView small = f.view;
  small.rgb = cv::Mat(10, 10, CV_8UC3, cv::Scalar(0, 0, 0));
  EXPECT_THROW(provider.sam_segments(small), Error);
  ImageSegmentParams missing = f.params(0.5);
  missing.gt_labels = (f.gt / "nowhere").string();
  EXPECT_THROW(ImageSegmentProvider(missing, f.taxonomy), Error);
  // Through the spec, as the features stage makes it.
  const auto made = make_feature_provider({{"provider", "image-segments"}, {"gt", f.gt.string()}, {"seed", 3}}, f.taxonomy);
  EXPECT_EQ(made->name(), "image-segments");
  EXPECT_EQ(made->spec()["seed"], 3);
  EXPECT_THROW(make_feature_provider({{"provider", "image-segments"}, {"gt", f.gt.string()}, {"bogus", 1}}, f.taxonomy),
               Error);
}

}  // namespace
}  // namespace cls
