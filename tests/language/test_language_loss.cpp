// The dual-feature loss of paper 3.3 against hand-computed values (see the comments for the sums).
#include <gtest/gtest.h>
#include <torch/cuda.h>
#include <torch/torch.h>

#include <vector>

#include "core/error.h"
#include "language/language_loss.h"

namespace cls {
namespace {

torch::Tensor t2(std::vector<float> v, int64_t h, int64_t w) { return torch::tensor(v).view({h, w}); }
torch::Tensor t3(std::vector<float> v, int64_t h, int64_t w, int64_t l) { return torch::tensor(v).view({h, w, l}); }

// 2 x 2 view, 2 channels. Rendered: p00 (1, 2), p01 (0, 0), p10 (3, -1), p11 (0.5, 0.5).
// SAM ids [0, -1, 1, 0] with table (1, 0), (2, 2); CityGML ids [0, 0, -1, -1] with table (0, 1);
// M = [1, 1, 0, 0].
//   p00: |(1,2)-(1,0)| = 2 (SAM, M=1), |(1,2)-(0,1)| = 2 (GML)
//   p01: no SAM segment; |(0,0)-(0,1)| = 1 (GML)
//   p10: |(3,-1)-(2,2)| = 4 (SAM, M=0)
//   p11: |(0.5,0.5)-(1,0)| = 1 (SAM, M=0)
// Divided by H W L = 8: L_SAM = 5/8, L_SAM-GML = 2/8, L_CityGML = 3/8.
struct Case2x2 {
  std::vector<int32_t> sam_ids{0, -1, 1, 0}, gml_ids{0, 0, -1, -1};
  torch::Tensor sam_table = torch::tensor({1.f, 0.f, 2.f, 2.f}).view({2, 2});
  torch::Tensor gml_table = torch::tensor({0.f, 1.f}).view({1, 2});
  torch::Tensor rendered = t3({1, 2, 0, 0, 3, -1, 0.5, 0.5}, 2, 2, 2);
  torch::Tensor coverage = t2({1, 1, 0, 0}, 2, 2);

  LanguageLossInputs inputs() const {
    LanguageLossInputs in;
    in.rendered = rendered;
    in.sam = gather_latent_target(sam_ids.data(), 2, 2, sam_table);
    in.gml = gather_latent_target(gml_ids.data(), 2, 2, gml_table);
    in.coverage = coverage;
    return in;
  }
};

TEST(LanguageLoss, GatherBuildsDenseTargetAndValidity) {
  Case2x2 c;
  const LatentTarget t = gather_latent_target(c.sam_ids.data(), 2, 2, c.sam_table);
  EXPECT_TRUE(torch::equal(t.latents, t3({1, 0, 0, 0, 2, 2, 1, 0}, 2, 2, 2)));
  EXPECT_TRUE(torch::equal(t.valid, t2({1, 0, 1, 1}, 2, 2)));
  std::vector<int32_t> bad{0, 2, -1, 0};
  EXPECT_THROW(gather_latent_target(bad.data(), 2, 2, c.sam_table), Error);
  bad[1] = -2;
  EXPECT_THROW(gather_latent_target(bad.data(), 2, 2, c.sam_table), Error);
  // No segments at all: an empty table is fine as long as every id is -1.
  std::vector<int32_t> none(4, -1);
  const LatentTarget e = gather_latent_target(none.data(), 2, 2, torch::zeros({0, 2}));
  EXPECT_EQ(e.valid.sum().item<float>(), 0.f);
  EXPECT_EQ(e.latents.sizes(), (std::vector<int64_t>{2, 2, 2}));
}

TEST(LanguageLoss, EachTermByHand) {
  Case2x2 c;
  const LanguageLoss l = language_loss(c.inputs(), {1.0, 0.5, false});
  EXPECT_NEAR(l.sam.item<double>(), 5.0 / 8, 1e-6);
  EXPECT_NEAR(l.sam_gml.item<double>(), 2.0 / 8, 1e-6);
  EXPECT_NEAR(l.citygml.item<double>(), 3.0 / 8, 1e-6);
  EXPECT_NEAR(l.total.item<double>(), 5.0 / 8 + 2.0 / 8 + 0.5 * 3.0 / 8, 1e-6);
  // Other lambdas weight only their own terms.
  const LanguageLoss l2 = language_loss(c.inputs(), {2.0, 0.25, false});
  EXPECT_NEAR(l2.total.item<double>(), 5.0 / 8 + 2.0 * 2.0 / 8 + 0.25 * 3.0 / 8, 1e-6);
}

TEST(LanguageLoss, CoverageSplitsTheSamTerm) {
  Case2x2 c;
  // M = 0 everywhere: all SAM pixels go to L_SAM, CityGML contributes nothing.
  c.coverage = torch::zeros({2, 2});
  LanguageLoss l = language_loss(c.inputs(), {1.0, 0.5, false});
  EXPECT_NEAR(l.sam.item<double>(), 7.0 / 8, 1e-6);
  EXPECT_NEAR(l.sam_gml.item<double>(), 0.0, 1e-7);
  EXPECT_NEAR(l.citygml.item<double>(), 0.0, 1e-7);
  // M = 1 everywhere: all SAM pixels go to L_SAM-GML.
  c.coverage = torch::ones({2, 2});
  l = language_loss(c.inputs(), {1.0, 0.5, false});
  EXPECT_NEAR(l.sam.item<double>(), 0.0, 1e-7);
  EXPECT_NEAR(l.sam_gml.item<double>(), 7.0 / 8, 1e-6);
  EXPECT_NEAR(l.citygml.item<double>(), 3.0 / 8, 1e-6);
}

// 3 x 1 view, 3 channels: rendered (0,0,0), (1,1,1), (0,2,0); SAM ids [1, 0, -1] with table
// (1,1,1), (1,0,-1); CityGML ids [-1, 0, 0] with table (0,0,1); M = [1, 1, 0].
//   p0: SAM |(0,0,0)-(1,0,-1)| = 2 inside coverage; no CityGML region
//   p1: SAM 0; CityGML |(1,1,1)-(0,0,1)| = 2
//   p2: no SAM segment; a CityGML id where M = 0 does not count
// / 9: L_SAM = 0, L_SAM-GML = 2/9, L_CityGML = 2/9, total = 2/9 + 0.5 * 2/9 = 1/3.
TEST(LanguageLoss, MasksOnThreeByOne) {
  std::vector<int32_t> sam_ids{1, 0, -1}, gml_ids{-1, 0, 0};
  LanguageLossInputs in;
  in.rendered = t3({0, 0, 0, 1, 1, 1, 0, 2, 0}, 3, 1, 3);
  in.sam = gather_latent_target(sam_ids.data(), 3, 1, torch::tensor({1.f, 1.f, 1.f, 1.f, 0.f, -1.f}).view({2, 3}));
  in.gml = gather_latent_target(gml_ids.data(), 3, 1, torch::tensor({0.f, 0.f, 1.f}).view({1, 3}));
  in.coverage = t2({1, 1, 0}, 3, 1);
  const LanguageLoss l = language_loss(in, {1.0, 0.5, false});
  EXPECT_NEAR(l.sam.item<double>(), 0.0, 1e-7);
  EXPECT_NEAR(l.sam_gml.item<double>(), 2.0 / 9, 1e-6);
  EXPECT_NEAR(l.citygml.item<double>(), 2.0 / 9, 1e-6);
  EXPECT_NEAR(l.total.item<double>(), 1.0 / 3, 1e-6);
}

TEST(LanguageLoss, BaselineIsPlainL1OverSamPixels) {
  Case2x2 c;
  // LangSplat: mean over H W L of |Z^ - Z_SAM| on SAM-valid pixels = (2 + 4 + 1) / 8, whatever
  // M and the lambdas; the CityGML targets are not even needed.
  LanguageLossInputs in = c.inputs();
  in.gml = LatentTarget{};
  for (double ls : {1.0, 3.0}) {
    const LanguageLoss l = language_loss(in, {ls, 0.5, true});
    EXPECT_NEAR(l.total.item<double>(), 7.0 / 8, 1e-6);
    EXPECT_NEAR(l.citygml.item<double>(), 0.0, 1e-7);
  }
  // The same as torch's l1_loss of the masked maps (LangSplat's train.py).
  const torch::Tensor mask = in.sam.valid.unsqueeze(-1);
  const double ref = torch::l1_loss(c.rendered * mask, in.sam.latents * mask).item<double>();
  EXPECT_NEAR(language_loss(in, {1.0, 0.5, true}).total.item<double>(), ref, 1e-6);
}

TEST(LanguageLoss, GradientByHand) {
  Case2x2 c;
  LanguageLossInputs in = c.inputs();
  in.rendered = c.rendered.clone().requires_grad_(true);
  language_loss(in, {1.0, 0.5, false}).total.backward();
  const torch::Tensor g = in.rendered.grad();
  // p00 channel 1: z = 2 above the SAM target 0 (lambda_sam) and the GML target 1 (lambda_citygml).
  EXPECT_NEAR(g[0][0][1].item<double>(), (1.0 + 0.5) / 8, 1e-6);
  // p01 channel 1: no SAM segment; z = 0 below the GML target 1.
  EXPECT_NEAR(g[0][1][1].item<double>(), -0.5 / 8, 1e-6);
  // p10 channel 1: z = -1 below the SAM target 2, outside coverage (weight 1).
  EXPECT_NEAR(g[1][0][1].item<double>(), -1.0 / 8, 1e-6);
}

TEST(LanguageLoss, ShapeMismatchIsAnError) {
  Case2x2 c;
  LanguageLossInputs in = c.inputs();
  in.coverage = torch::ones({2, 3});
  EXPECT_THROW(language_loss(in, {}), Error);
  in = c.inputs();
  in.gml = LatentTarget{};
  EXPECT_THROW(language_loss(in, {1.0, 0.5, false}), Error);
}

torch::Tensor ids_tensor(const std::vector<int32_t>& ids, int64_t h, int64_t w) {
  return torch::tensor(ids, torch::kInt32).view({h, w});
}

// The message of the cls::Error that `f` throws ("" if none).
template <class F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

// The one-pass loss from seg maps on `device` against the dense reference on the CPU (values and
// gradients), on random maps with partial coverage, missing segments, pixels equal to their targets
// (sgn(0) = 0) and both modes; no maps and empty tables; bad ids and shapes.
void expect_seg_equals_dense(const torch::Device& device, int64_t h, int64_t w, int64_t l, uint64_t seed) {
  torch::manual_seed(seed);
  const torch::Tensor sam_table = torch::randn({6, l}), gml_table = torch::randn({4, l});
  const torch::Tensor sam_ids_t = torch::randint(-1, 6, {h * w}, torch::kInt32);
  const torch::Tensor gml_ids_t = torch::randint(-1, 4, {h * w}, torch::kInt32);
  const std::vector<int32_t> sam_ids(sam_ids_t.data_ptr<int32_t>(), sam_ids_t.data_ptr<int32_t>() + h * w);
  const std::vector<int32_t> gml_ids(gml_ids_t.data_ptr<int32_t>(), gml_ids_t.data_ptr<int32_t>() + h * w);
  const torch::Tensor coverage = (torch::rand({h, w}) > 0.4).to(torch::kFloat);
  const torch::Tensor base = torch::randn({h, w, l});
  // Every 5th pixel equals its SAM target; else every 7th its CityGML one, inside the coverage (where
  // the CityGML term counts).
  int64_t sam_ties = 0, gml_ties = 0;
  for (int64_t p = 0; p < h * w; ++p) {
    const int32_t s = sam_ids[p], g = gml_ids[p];
    if (p % 5 == 0 && s >= 0) {
      base.view({h * w, l})[p].copy_(sam_table[s]);
      ++sam_ties;
    } else if (p % 7 == 0 && g >= 0) {
      base.view({h * w, l})[p].copy_(gml_table[g]);
      coverage.view({h * w})[p] = 1.f;
      ++gml_ties;
    }
  }
  ASSERT_GT(sam_ties, 0);
  ASSERT_GT(gml_ties, 0);
  for (bool baseline : {false, true}) {
    const LanguageLossWeights weights{1.3, 0.7, baseline};
    LanguageLossInputs in;
    in.rendered = base.clone().requires_grad_(true);
    in.sam = gather_latent_target(sam_ids.data(), h, w, sam_table);
    in.gml = gather_latent_target(gml_ids.data(), h, w, gml_table);
    in.coverage = coverage;
    const LanguageLoss ref = language_loss(in, weights);
    ref.total.backward();
    const torch::Tensor z = base.clone().to(device).requires_grad_(true);
    const LanguageLoss fused = language_loss_from_seg(z, {ids_tensor(sam_ids, h, w), sam_table},
                                                      {ids_tensor(gml_ids, h, w), gml_table}, coverage, weights);
    fused.total.backward();
    EXPECT_NEAR(fused.total.item<double>(), ref.total.item<double>(), 1e-5) << baseline;
    EXPECT_NEAR(fused.sam.item<double>(), ref.sam.item<double>(), 1e-5);
    EXPECT_NEAR(fused.sam_gml.item<double>(), ref.sam_gml.item<double>(), 1e-5);
    EXPECT_NEAR(fused.citygml.item<double>(), ref.citygml.item<double>(), 1e-5);
    ASSERT_EQ(z.grad().device().type(), device.type());
    EXPECT_TRUE(torch::allclose(z.grad().cpu(), in.rendered.grad(), 1e-5, 1e-7)) << baseline;
  }
  // No seg maps, or an empty SAM table with every id -1: zero loss and gradient.
  const std::vector<int32_t> none(h * w, -1);
  for (const SegMapTarget& sam : {SegMapTarget{}, SegMapTarget{ids_tensor(none, h, w), torch::zeros({0, l})}}) {
    const torch::Tensor z = base.clone().to(device).requires_grad_(true);
    const LanguageLoss empty = language_loss_from_seg(z, sam, {}, coverage, {1.0, 0.5, false});
    empty.total.backward();
    EXPECT_EQ(empty.total.item<double>(), 0.0);
    EXPECT_EQ(z.grad().abs().sum().item<double>(), 0.0);
  }
  // Ids outside the table are errors naming the map, the id and the pixel; shapes are checked.
  const torch::Tensor z = base.to(device);
  const int64_t at = h * w / 2;
  const std::string where = " at pixel (" + std::to_string(at % w) + ", " + std::to_string(at / w) + ")";
  std::vector<int32_t> bad = sam_ids;
  bad[at] = 6;
  EXPECT_NE(error_of([&] {
              language_loss_from_seg(z, {ids_tensor(bad, h, w), sam_table}, {}, coverage, {1.0, 0.5, true});
            }).find("SAM seg map holds id 6" + where + ", outside [-1, 6)"),
            std::string::npos);
  bad[at] = -2;
  EXPECT_THROW(language_loss_from_seg(z, {ids_tensor(bad, h, w), sam_table}, {}, coverage, {1.0, 0.5, true}), Error);
  bad = gml_ids;
  bad[at] = 4;
  const auto with_bad_gml = [&](bool baseline) {
    return language_loss_from_seg(z, {ids_tensor(sam_ids, h, w), sam_table}, {ids_tensor(bad, h, w), gml_table},
                                  coverage, {1.0, 0.5, baseline});
  };
  EXPECT_NE(error_of([&] { with_bad_gml(false); }).find("CityGML seg map holds id 4" + where), std::string::npos);
  EXPECT_NO_THROW(with_bad_gml(true));  // the baseline reads no CityGML map
  EXPECT_THROW(language_loss_from_seg(z, {ids_tensor(sam_ids, h * w, 1), sam_table}, {}, coverage, {1.0, 0.5, true}),
               Error);
  EXPECT_THROW(language_loss_from_seg(z, {ids_tensor(sam_ids, h, w), sam_table.slice(1, 1)}, {}, coverage,
                                      {1.0, 0.5, true}),
               Error);
}

TEST(LanguageLoss, FromSegMapsEqualsDenseReference) {
  expect_seg_equals_dense(torch::kCPU, 7, 9, 5, 3);
  expect_seg_equals_dense(torch::kCPU, 5, 4, 37, 4);
  // The hand-computed 2 x 2 case as well.
  Case2x2 c;
  const LanguageLoss l2 =
      language_loss_from_seg(c.rendered, {ids_tensor(c.sam_ids, 2, 2), c.sam_table}, {ids_tensor(c.gml_ids, 2, 2), c.gml_table},
                             c.coverage, {1.0, 0.5, false});
  EXPECT_NEAR(l2.total.item<double>(), 5.0 / 8 + 2.0 / 8 + 0.5 * 3.0 / 8, 1e-6);
  EXPECT_NE(error_of([] { language_loss_from_seg(torch::zeros({0, 2, 2}), {}, {}, torch::zeros({0, 2}), {}); })
                .find("the rendered map is empty"),
            std::string::npos);
}

// The CUDA kernel (seg_loss_cuda.h) against the same reference: channel counts below, at and above a
// warp's 32 lanes and LangSplat's 3; the 300 x 200 view has more pixels than the grid has warps, so
// warps take several pixels each.
TEST(LanguageLossCuda, FromSegMapsEqualsDenseReferenceOnTheDevice) {
  if (!torch::cuda::is_available()) GTEST_SKIP() << "no CUDA device: the CUDA loss is not compared with the reference";
  expect_seg_equals_dense(torch::kCUDA, 7, 9, 3, 5);
  expect_seg_equals_dense(torch::kCUDA, 37, 53, 32, 6);
  expect_seg_equals_dense(torch::kCUDA, 61, 43, 128, 7);
  expect_seg_equals_dense(torch::kCUDA, 9, 11, 200, 8);
  expect_seg_equals_dense(torch::kCUDA, 200, 300, 3, 9);
}

}  // namespace
}  // namespace cls
