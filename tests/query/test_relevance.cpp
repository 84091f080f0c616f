// Query scores and relevance maps against hand-computed values and a double-precision per-pixel reference.
#include <gtest/gtest.h>
#include <torch/torch.h>

#include <cmath>

#include "core/error.h"
#include "query/relevance.h"
#include "splat/reference_render.h"
#include "latent_scene.h"
#include "splat/splat_scene.h"

namespace cls {
namespace {

at::Tensor rows(std::vector<std::vector<float>> v) {
  std::vector<at::Tensor> r;
  for (auto& x : v) r.push_back(torch::tensor(x));
  return torch::stack(r);
}

TEST(GaussianScores, HandValues) {
  const at::Tensor latents = rows({{1, 0}, {0, 2}, {1, 1}, {0, 0}, {-3, 0}});
  const at::Tensor s = gaussian_scores(latents, torch::tensor({2.0f, 0.0f}));
  ASSERT_EQ(s.sizes(), at::IntArrayRef({5}));
  EXPECT_EQ(s.scalar_type(), torch::kFloat32);
  const float expected[] = {1.0f, 0.0f, float(1 / std::sqrt(2.0)), 0.0f, -1.0f};
  for (int i = 0; i < 5; ++i) EXPECT_NEAR(s[i].item<float>(), expected[i], 1e-6) << i;
  // A zero query scores 0 everywhere (no NaN).
  const at::Tensor z = gaussian_scores(latents, torch::zeros({2}));
  EXPECT_EQ(z.abs().sum().item<float>(), 0.0f);
}

TEST(GaussianScores, ShapeMismatchIsAnError) {
  EXPECT_THROW(gaussian_scores(torch::zeros({3, 4}), torch::zeros({3})), Error);
  EXPECT_THROW(gaussian_scores(torch::zeros({3}), torch::zeros({3})), Error);
}

TEST(CosineMaps, HandValuesIncludingZeroVectors) {
  // One row of three pixels: (3, 4), (0, 0), (-1, 0); prototypes (1, 0) and (0, 5).
  const at::Tensor f = rows({{3, 4}, {0, 0}, {-1, 0}}).reshape({1, 3, 2});
  const at::Tensor c = cosine_maps(f, rows({{1, 0}, {0, 5}}));
  ASSERT_EQ(c.sizes(), at::IntArrayRef({2, 1, 3}));
  const float expected[2][3] = {{0.6f, 0.0f, -1.0f}, {0.8f, 0.0f, 0.0f}};
  for (int k = 0; k < 2; ++k)
    for (int x = 0; x < 3; ++x) EXPECT_NEAR(c[k][0][x].item<float>(), expected[k][x], 1e-6) << k << "," << x;
  // A zero prototype gives 0 too.
  EXPECT_EQ(cosine_maps(f, torch::zeros({1, 2})).abs().sum().item<float>(), 0.0f);
  EXPECT_THROW(cosine_maps(f, torch::zeros({1, 3})), Error);
  EXPECT_THROW(cosine_maps(torch::zeros({3, 2}), torch::zeros({1, 2})), Error);
}

TEST(LangsplatRelevancy, OnePixelTwoCanonicalPhrases) {
  // f = (2, 0, 0) (length does not matter), q = (0.6, 0.8, 0): cos 0.6.
  // c1 = (0, 1, 0): cos 0    -> softmax(10 * [0.6, 0.0])[0] = 1 / (1 + e^-6) = 0.997527
  // c2 = (0.8, 0, 0.6): 0.8  -> softmax(10 * [0.6, 0.8])[0] = 1 / (1 + e^2)  = 0.119203
  // min over the phrases = 0.119203.
  const at::Tensor f = torch::tensor({2.0f, 0.0f, 0.0f}).reshape({1, 1, 3});
  const at::Tensor q = torch::tensor({0.6f, 0.8f, 0.0f});
  const at::Tensor canonical = rows({{0, 1, 0}, {0.8f, 0, 0.6f}});
  const at::Tensor r = langsplat_relevancy(f, q, canonical);
  ASSERT_EQ(r.sizes(), at::IntArrayRef({1, 1}));
  EXPECT_NEAR(r[0][0].item<float>(), 0.1192029, 1e-6);
  // The phrase order does not matter; with only the weak phrase, the strong value remains.
  EXPECT_NEAR(langsplat_relevancy(f, q, canonical.flip(0))[0][0].item<float>(), 0.1192029, 1e-6);
  EXPECT_NEAR(langsplat_relevancy(f, q, canonical.slice(0, 0, 1))[0][0].item<float>(), 0.9975274, 1e-6);
  // A zero feature has cosine 0 with everything: 0.5.
  EXPECT_NEAR(langsplat_relevancy(torch::zeros({1, 1, 3}), q, canonical)[0][0].item<float>(), 0.5, 1e-6);
}

TEST(LangsplatRelevancy, EqualsTheSoftmaxFormOnRandomCosines) {
  // OpenCLIPNetwork.get_relevancy as written: softmax(10 [a, b_c]) per phrase, the smallest positive probability.
  torch::manual_seed(3);
  const at::Tensor a = torch::rand({50}, torch::kFloat64) * 2 - 1;
  const at::Tensor b = torch::rand({50, 4}, torch::kFloat64) * 2 - 1;
  const at::Tensor pairs = torch::stack({a.unsqueeze(1).expand_as(b), b}, -1);  // 50 x 4 x 2
  const at::Tensor expected = std::get<0>(torch::softmax(10 * pairs, -1).select(-1, 0).min(1));
  EXPECT_LT((relevancy_from_cosines(a, b) - expected).abs().max().item<double>(), 1e-12);
  // float32, as the maps are made: within 1e-6 (about 17 float ulps near 1)
  EXPECT_LT((relevancy_from_cosines(a.to(torch::kFloat32), b.to(torch::kFloat32)).to(torch::kFloat64) - expected)
                .abs().max().item<double>(), 1e-6);
  EXPECT_THROW(relevancy_from_cosines(a, torch::zeros({50, 0}, torch::kFloat64)), Error);
  EXPECT_THROW(relevancy_from_cosines(a, torch::zeros({49, 4}, torch::kFloat64)), Error);
}

TEST(CanonicalPhrases, AreLangSplats) {
  EXPECT_EQ(canonical_phrases(), (std::vector<std::string>{"object", "things", "stuff", "texture"}));
}

TEST(RenderDecoded, MatchesPerPixelReference) {
  // The view is 24 columns wider than the scene's frustum, so that some pixels stay uncovered.
  const int W0 = 37, W = W0 + 24, H = 29, L = 8, D = 12;
  test::LatentScene t = test::latent_scene(80, W0, H, L, 7);
  t.camera.width = t.s.cam.width = W;
  // The decoder: a fixed affine map followed by tanh (stands in for the autoencoder's MLP).
  torch::manual_seed(5);
  const at::Tensor A = torch::randn({L, D}, torch::kFloat64), bias = torch::randn({D}, torch::kFloat64);
  int calls = 0;
  const LatentDecoder decode = [&](const at::Tensor& z) {
    ++calls;
    return torch::tanh(z.to(torch::kFloat64).matmul(A) + bias).to(torch::kFloat32);
  };
  const DecodedView v = render_decoded(t.g, t.latents, decode, t.camera, t.pose, /*chunk_pixels=*/100);
  ASSERT_EQ(v.features.sizes(), at::IntArrayRef({H, W, D}));
  ASSERT_EQ(v.alpha.sizes(), at::IntArrayRef({H, W}));
  // chunked over the covered pixels, last chunk partial; one more call decodes the uncovered pixels' zero latent
  const int64_t covered_pixels = (v.alpha > 0).sum().item<int64_t>();
  EXPECT_EQ(calls, (covered_pixels + 99) / 100 + 1);
  // Chunk 0: the device's (8192 pixels on the CPU: one call for this view's covered pixels), same features.
  calls = 0;
  const DecodedView v0 = render_decoded(t.g, t.latents, decode, t.camera, t.pose);
  EXPECT_EQ(calls, 2);
  EXPECT_LT((v0.features - v.features).abs().max().item<double>(), 1e-6);
  EXPECT_EQ(decode_chunk_pixels(torch::kCPU), kDecodeChunkPixels);
  EXPECT_EQ(decode_chunk_pixels(torch::Device(torch::kCUDA, 0)), kDecodeChunkPixelsGpu);
  EXPECT_THROW(render_decoded(t.g, t.latents, decode, t.camera, t.pose, -1), Error);

  // Reference: double-precision renderer for the latents (zero background), then the decoder per pixel.
  const auto ad = test::scene_arrays<double>(t.s);
  const ReferenceImage ref = reference_render(t.s.cam, ad.inputs(t.s, /*with_background=*/false));
  double max_diff = 0, max_alpha_diff = 0, covered = 0;
  auto Aa = A.accessor<double, 2>();
  auto ba = bias.accessor<double, 1>();
  auto fa = v.features.accessor<float, 3>();
  auto aa = v.alpha.accessor<float, 2>();
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const size_t p = size_t(y) * W + x;
      for (int d = 0; d < D; ++d) {
        double acc = ba[d];
        for (int l = 0; l < L; ++l) acc += ref.image[p * L + l] * Aa[l][d];
        max_diff = std::max(max_diff, std::abs(std::tanh(acc) - fa[y][x][d]));
      }
      max_alpha_diff = std::max(max_alpha_diff, std::abs(ref.alpha[p] - aa[y][x]));
      covered += ref.alpha[p] > 0.05;
    }
  EXPECT_LT(max_diff, 1e-4);
  EXPECT_LT(max_alpha_diff, 1e-5);
  EXPECT_GT(covered / (W0 * H), 0.5);  // the scene is not empty
  EXPECT_LT(covered_pixels, W * H);   // and has uncovered pixels: they too match the reference above
}

TEST(RenderDecoded, LanguageModelLevelMatchesReferenceThenAutoencoderPerPixel) {
  // The LanguageModel form: the level's latents, the model's autoencoder, the view's camera and pose.
  const int W = 29, H = 23, L = 8, D = 16;
  test::LatentScene t = test::latent_scene(70, W, H, L, 13);
  LanguageModel m{t.g, {}, Autoencoder(AutoencoderConfig{D, {12, L}, {12, D}}, 3), {}};
  torch::manual_seed(2);
  m.latents = {torch::randn({70, L}), t.latents, torch::randn({70, L})};
  SceneView view;
  view.camera = t.camera;
  view.pose = t.pose;
  const DecodedView v = render_decoded(m, 2, view);
  ASSERT_EQ(v.features.sizes(), at::IntArrayRef({H, W, D}));

  const auto ad = test::scene_arrays<double>(t.s);
  const ReferenceImage ref = reference_render(t.s.cam, ad.inputs(t.s, /*with_background=*/false));
  double max_diff = 0;
  for (int y = 0; y < H; y += 3)
    for (int x = 0; x < W; x += 2) {
      const size_t p = size_t(y) * W + x;
      std::vector<float> z(ref.image.begin() + p * L, ref.image.begin() + (p + 1) * L);
      const at::Tensor f = m.autoencoder->decode(torch::tensor(z).reshape({1, L}))[0];  // one pixel at a time
      max_diff = std::max(max_diff, (f - v.features[y][x]).abs().max().item<double>());
    }
  EXPECT_LT(max_diff, 1e-4);
  EXPECT_THROW(render_decoded(m, 4, view), Error);
  // relevance_maps of the same level and view agrees with the maps of the decoded field.
  const at::Tensor queries = torch::randn({2, D}), canonical = torch::randn({4, D});
  const RelevanceMaps rm = relevance_maps(m, 2, view, queries, canonical);
  EXPECT_LT((rm.cosine - cosine_maps(v.features, queries)).abs().max().item<float>(), 1e-5);
  EXPECT_LT((rm.relevancy[1] - langsplat_relevancy(v.features, queries[1], canonical)).abs().max().item<float>(), 1e-5);
  // Another level renders other latents.
  EXPECT_GT((render_decoded(m, 1, view).features - v.features).abs().max().item<float>(), 1e-3);
}

// decode(z) = tanh(z A) W^T + b in double: the reference for DecodedCosines.
at::Tensor decode_in_double(const at::Tensor& z, const at::Tensor& A, const at::Tensor& W, const at::Tensor& b) {
  return torch::tanh(z.to(torch::kFloat64).matmul(A.to(torch::kFloat64))).matmul(W.to(torch::kFloat64).t()) +
         b.to(torch::kFloat64);
}

TEST(DecodedCosines, EqualCosinesOfTheDecodedFeaturesInDouble) {
  // Last layers narrower (7 -> 10: Q is 10 x 7 and the bias has a part outside its columns), as wide
  // (10 -> 10) and wider (13 -> 10: R is 10 x 13) than the features.
  const int L = 5, D = 10, B = 300;
  for (const int Hd : {7, 10, 13}) {
    torch::manual_seed(Hd);
    const at::Tensor A = torch::randn({L, Hd}), W = torch::randn({D, Hd}), b = torch::randn({D});
    at::Tensor directions = torch::randn({6, D}) * torch::rand({6, 1}) * 5;
    directions[4].zero_();  // a zero direction: cosine 0
    at::Tensor z = torch::randn({B, L});
    const LinearHeadDecoder decoder{[&](const at::Tensor& x) { return torch::tanh(x.matmul(A)); },
                                    factor_linear_head(W, b)};
    const at::Tensor got = DecodedCosines(decoder, directions)(z);
    ASSERT_EQ(got.sizes(), at::IntArrayRef({B, 6}));
    EXPECT_EQ(got.scalar_type(), torch::kFloat32);
    const at::Tensor f = decode_in_double(z, A, W, b);
    const at::Tensor p = directions.to(torch::kFloat64);
    const at::Tensor expected = f.matmul(p.t()) / (f.norm(2, {1}, true) * p.norm(2, {1}).clamp_min(1e-300));
    expected.select(1, 4).zero_();
    EXPECT_LT((got.to(torch::kFloat64) - expected).abs().max().item<double>(), 1e-5) << "hidden size " << Hd;
    EXPECT_EQ(got.select(1, 4).abs().max().item<float>(), 0.0f);
    // The factors the decoder holds are the ones used: another layer's change the cosines, and one
    // factorisation serves every DecodedCosines made from it.
    LinearHeadDecoder other = decoder;
    other.last = factor_linear_head(W, b + 1);
    EXPECT_GT((DecodedCosines(other, directions)(z) - got).abs().max().item<float>(), 1e-3);
    EXPECT_TRUE(torch::equal(DecodedCosines(decoder, directions)(z), got)) << "hidden size " << Hd;
  }
}

TEST(DecodedCosines, ZeroFeatureGivesZeroAndShapesAreChecked) {
  // Without a bias, decode(0) = 0: its cosines are 0 (as cosine_maps' for a zero feature), not NaN.
  const int L = 3, Hd = 4, D = 6;
  torch::manual_seed(1);
  const at::Tensor A = torch::randn({L, Hd}), W = torch::randn({D, Hd});
  const LinearHeadDecoder decoder{[&](const at::Tensor& x) { return torch::tanh(x.matmul(A)); },
                                  factor_linear_head(W, at::Tensor())};
  const at::Tensor got = DecodedCosines(decoder, torch::randn({2, D}))(torch::zeros({3, L}));
  EXPECT_EQ(got.abs().max().item<float>(), 0.0f);
  EXPECT_THROW(DecodedCosines(decoder, torch::randn({2, D + 1})), Error);
  EXPECT_THROW(factor_linear_head(W, torch::zeros({D + 1})), Error);
  EXPECT_THROW(factor_linear_head(torch::randn({D}), at::Tensor()), Error);
  EXPECT_THROW(DecodedCosines({decoder.hidden, LinearHeadFactors{}}, torch::randn({2, D})), Error);
  const LinearHeadDecoder wrong_hidden{[&](const at::Tensor& x) { return x; }, decoder.last};  // L != Hd values
  EXPECT_THROW(DecodedCosines(wrong_hidden, torch::randn({2, D}))(torch::zeros({3, L})), Error);
}

TEST(DecodedCosinesCuda, EqualTheCpuPathForAnAutoencoderOnTheDevice) {
  if (!torch::cuda::is_available()) GTEST_SKIP() << "no CUDA device: DecodedCosines on CUDA is not compared";
  // The same initial weights on both devices (one seed); the factorisation is made on the CPU in both.
  for (const AutoencoderConfig& c : {AutoencoderConfig{}, langsplat_autoencoder_config()}) {
    const Autoencoder cpu(c, 2);
    Autoencoder cuda(c, 2);
    cuda.to(torch::kCUDA);
    torch::manual_seed(3);
    const at::Tensor z = torch::randn({5000, c.latent_dim()}), directions = torch::randn({5, c.input_dim});
    const at::Tensor expected = DecodedCosines(linear_head_decoder(cpu), directions)(z);
    const at::Tensor got = DecodedCosines(linear_head_decoder(cuda), directions)(z.to(torch::kCUDA));
    ASSERT_TRUE(got.is_cuda());
    EXPECT_LT((got.cpu() - expected).abs().max().item<float>(), 1e-4);
  }
}

TEST(RelevanceMaps, LangSplatAutoencoderLayoutEqualsItsDecodedField) {
  // LangSplat's layout: six hidden layers, the last one wider than the features, latent and output normalised.
  const AutoencoderConfig c = langsplat_autoencoder_config(16);
  const int W = 29, H = 23, L = c.latent_dim(), D = c.input_dim;
  test::LatentScene t = test::latent_scene(70, W, H, L, 17);
  LanguageModel m{t.g, {}, Autoencoder(c, 5), {}};
  m.latents = {t.latents, t.latents, t.latents};
  SceneView view;
  view.camera = t.camera;
  view.pose = t.pose;
  torch::manual_seed(4);
  const at::Tensor queries = torch::randn({2, D}), canonical = torch::randn({4, D});
  const RelevanceMaps rm = relevance_maps(m, 1, view, queries, canonical);
  const DecodedView v = render_decoded(m, 1, view);
  EXPECT_LT((rm.cosine - cosine_maps(v.features, queries)).abs().max().item<float>(), 1e-5);
  EXPECT_LT((rm.relevancy[0] - langsplat_relevancy(v.features, queries[0], canonical)).abs().max().item<float>(), 1e-5);
  EXPECT_THROW(relevance_maps(m, 1, view, torch::randn({1, D + 1}), torch::randn({4, D + 1})), Error);
}

TEST(RelevanceMaps, EqualMapsOfTheWholeDecodedField) {
  const int W = 31 + 20, H = 23, L = 6, Hd = 7, D = 10;
  test::LatentScene t = test::latent_scene(60, 31, H, L, 11);
  t.camera.width = W;  // wider than the scene: uncovered pixels too
  torch::manual_seed(9);
  const at::Tensor A = torch::randn({L, Hd}), Wd = torch::randn({D, Hd}), b = torch::randn({D});
  const LinearHeadDecoder decoder{[&](const at::Tensor& z) { return torch::tanh(z.matmul(A)); },
                                  factor_linear_head(Wd, b)};
  const LatentDecoder decode = [&](const at::Tensor& z) { return decode_in_double(z, A, Wd, b).to(torch::kFloat32); };
  const at::Tensor queries = torch::randn({3, D}), canonical = torch::randn({4, D});
  const RelevanceMaps m = relevance_maps(t.g, t.latents, decoder, t.camera, t.pose, queries, canonical, 77);
  const DecodedView v = render_decoded(t.g, t.latents, decode, t.camera, t.pose);
  ASSERT_EQ(m.cosine.sizes(), at::IntArrayRef({3, H, W}));
  ASSERT_EQ(m.relevancy.sizes(), at::IntArrayRef({3, H, W}));
  EXPECT_LT((m.cosine - cosine_maps(v.features, queries)).abs().max().item<float>(), 1e-5);
  for (int k = 0; k < 3; ++k)
    EXPECT_LT((m.relevancy[k] - langsplat_relevancy(v.features, queries[k], canonical)).abs().max().item<float>(), 1e-5);
  EXPECT_TRUE(torch::equal(m.alpha, v.alpha));
  EXPECT_GT((m.alpha == 0).sum().item<int64_t>(), 0);
  EXPECT_THROW(relevance_maps(t.g, t.latents, decoder, t.camera, t.pose, queries, torch::zeros({0, D})), Error);
  EXPECT_THROW(relevance_maps(t.g, t.latents, decoder, t.camera, t.pose, torch::zeros({1, D + 1}), canonical), Error);
  EXPECT_THROW(render_latents(t.g, t.latents.slice(0, 1), t.camera, t.pose), Error);
}

// The sparse field against its reference, the dense decode (weights scattered, times the codebook): the
// per-Gaussian cosines, and the relevance maps of the sparse splatting through the codebook's factors.
SparseLevel random_sparse_level(int64_t n, int K, int L, int D, unsigned seed) {
  torch::manual_seed(seed);
  SparseLevel s;
  s.indices = torch::randint(0, L, {n, K}, torch::kInt32);
  s.weights = torch::rand({n, K});
  s.weights[0].zero_();  // a Gaussian with no feature: cosine 0
  s.codebook = torch::randn({L, D});
  return s;
}

TEST(SparseField, CosinesEqualThoseOfTheDecodedFeatures) {
  const SparseLevel s = random_sparse_level(50, 3, 7, 9, 4);
  const at::Tensor dirs = torch::randn({4, 9});
  dirs[3].zero_();
  const at::Tensor f = sparse_features(s).to(torch::kFloat64), d = dirs.to(torch::kFloat64);
  // the reference in double: <f, d> / (|f| |d|), 0 where either is zero
  const at::Tensor fn = f.norm(2, {1}, true), dn = d.norm(2, {1}, true);
  const at::Tensor expected = torch::where(fn * dn.t() > 0, f.matmul(d.t()) / (fn * dn.t()), torch::zeros({50, 4}, torch::kFloat64));
  const at::Tensor got = sparse_cosines(s, dirs);
  ASSERT_EQ(got.sizes(), at::IntArrayRef({50, 4}));
  EXPECT_LT((got.to(torch::kFloat64) - expected).abs().max().item<double>(), 1e-5);
  EXPECT_GT(expected.abs().max().item<double>(), 0.5);
  EXPECT_THROW(sparse_cosines(s, torch::randn({2, 8})), Error);
}

TEST(SparseField, RelevanceMapsEqualMapsOfTheDecodedField) {
  const int W = 31 + 20, H = 23, L = 6, K = 2, D = 10;
  test::LatentScene t = test::latent_scene(60, 31, H, L, 12);
  t.camera.width = W;  // wider than the scene: uncovered pixels too
  const SparseLevel s = random_sparse_level(60, K, L, D, 5);
  const at::Tensor queries = torch::randn({3, D}), canonical = torch::randn({4, D});
  const RelevanceMaps m = relevance_maps(t.g, s, t.camera, t.pose, queries, canonical, 77);
  const at::Tensor dense = torch::zeros({60, L}).scatter_add(1, s.indices.to(torch::kLong), s.weights);
  const DecodedView v = render_decoded(t.g, dense, [&](const at::Tensor& w) { return w.matmul(s.codebook); }, t.camera, t.pose);
  ASSERT_EQ(m.cosine.sizes(), at::IntArrayRef({3, H, W}));
  EXPECT_LT((m.cosine - cosine_maps(v.features, queries)).abs().max().item<float>(), 1e-5);
  for (int k = 0; k < 3; ++k)
    EXPECT_LT((m.relevancy[k] - langsplat_relevancy(v.features, queries[k], canonical)).abs().max().item<float>(), 1e-5);
  EXPECT_TRUE(torch::allclose(m.alpha, v.alpha));
  EXPECT_GT((m.alpha == 0).sum().item<int64_t>(), 0);
  // Through a LanguageModel: the same maps, and gaussian_cosines as sparse_cosines.
  LanguageModel model{t.g, {}, std::nullopt, {}, {}, {s, s, s}};
  SceneView view;
  view.camera = t.camera;
  view.pose = t.pose;
  EXPECT_TRUE(torch::equal(relevance_maps(model, 2, view, queries, canonical).cosine, m.cosine));
  EXPECT_TRUE(torch::equal(gaussian_cosines(model, 3, queries), sparse_cosines(s, queries)));
  EXPECT_THROW(model.dense_autoencoder("export"), UsageError);
}

}  // namespace
}  // namespace cls
