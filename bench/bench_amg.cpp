// LangSplat mask NMS (bit-packed fast vs LibTorch matrix form vs the literal reference) for
// M masks at 1000x750, and the whole LangSplat AMG on a 1000x750 image with a randomly initialised
// SAM (ViT-B by default), or the SAM fixture's tiny model on its own image (--fixture: the workload
// of the slowest test). Usage: bench_amg [--threads N] [--masks 200,400,...] [--model vit_b|none] [--fixture DIR]
// [--device cpu|cuda].
// Figures go to docs/benchmarks.md.
#include <omp.h>
#include <torch/torch.h>

#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <sstream>
#include <string>
#include <nlohmann/json.hpp>
#include <vector>

#include "bench_timer.h"
#include "core/args.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/heap_reuse.h"
#include "core/npy.h"
#include "models/sam/sam_config.h"
#include "models/sam/sam_model.h"
#include "models/sam/sam_predictor.h"
#include "models/sam_amg/automatic_mask_generator.h"
#include "models/sam_amg/langsplat_post.h"
#include "models/sam_amg/mask_nms.h"
#include "models/sam_amg/records_json.h"
#include "models/sam_amg/sam_amg_model.h"
#include "models/weights/safetensors.h"
#include "splat/compute_device.h"

namespace cls::amg {
namespace {

using bench::Clock;
using bench::seconds_since;

// SAM-like masks: ellipses of many sizes, a third of them nested in or near-copies of earlier
// ones, so that containment and IoU suppression both happen.
std::vector<BinaryMask> synthetic_masks(int n, int h, int w, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<BinaryMask> masks;
  std::vector<std::array<double, 4>> ellipses;  // cx, cy, rx, ry
  for (int k = 0; k < n; ++k) {
    BinaryMask m(h, w);
    double cx = u(rng) * w, cy = u(rng) * h, rx = 5 + std::pow(u(rng), 2) * w / 3, ry = 5 + std::pow(u(rng), 2) * h / 3;
    if (k > 0 && u(rng) < 0.33) {  // related to an earlier mask: same centre, scaled down a little or a lot
      const auto& e = ellipses[std::uniform_int_distribution<int>(0, k - 1)(rng)];
      const double f = 0.4 + 0.55 * u(rng);
      cx = e[0], cy = e[1], rx = e[2] * f, ry = e[3] * f;
    }
    ellipses.push_back({cx, cy, rx, ry});
    const int y0 = std::max(0, int(cy - ry)), y1 = std::min(h, int(cy + ry) + 1);
    const int x0 = std::max(0, int(cx - rx)), x1 = std::min(w, int(cx + rx) + 1);
    for (int y = y0; y < y1; ++y)
      for (int x = x0; x < x1; ++x)
        m.pixels[size_t(y) * w + x] = ((x - cx) * (x - cx) / (rx * rx) + (y - cy) * (y - cy) / (ry * ry)) <= 1.0;
    masks.push_back(std::move(m));
  }
  return masks;
}

void bench_mask_nms(const std::vector<int>& sizes, int threads, int reference_max) {
  const int h = 750, w = 1000;
  std::printf("LangSplat mask_nms at %dx%d, %d threads (fast = bit-packed + popcount; torch = matmul form on CPU)\n\n",
              w, h, threads);
  std::printf("| masks | kept | fast | fast, 1 thread | torch CPU | reference | fast vs reference |\n");
  std::printf("|---|---|---|---|---|---|---|\n");
  std::mt19937 rng(1);
  for (int n : sizes) {
    const auto masks = synthetic_masks(n, h, w, rng);
    std::vector<double> scores(n);
    std::uniform_real_distribution<double> u(0.5, 1.0);
    for (auto& s : scores) s = u(rng);
    auto t0 = Clock::now();
    std::vector<PackedMask> packed(n);
#pragma omp parallel for num_threads(threads)
    for (int i = 0; i < n; ++i) packed[i] = pack_mask(masks[i]);
    const double t_pack = seconds_since(t0);
    t0 = Clock::now();
    const auto fast = mask_nms_fast(packed, scores, {}, threads);
    const double t_fast = seconds_since(t0) + t_pack;
    t0 = Clock::now();
    const auto fast1 = mask_nms_fast(packed, scores, {}, 1);
    const double t_fast1 = seconds_since(t0) + t_pack;
    t0 = Clock::now();
    const auto tor = mask_nms_torch(masks, scores, {});
    const double t_torch = seconds_since(t0);
    std::string ref_cell = "-", ratio = "-";
    bool same = fast == fast1 && fast == tor;
    if (n <= reference_max) {
      t0 = Clock::now();
      const auto ref = mask_nms_reference(masks, scores, {});
      const double t_ref = seconds_since(t0);
      same = same && ref == fast;
      char buf[64];
      std::snprintf(buf, sizeof buf, "%.2f s", t_ref);
      ref_cell = buf;
      std::snprintf(buf, sizeof buf, "%.0fx", t_ref / t_fast);
      ratio = buf;
    }
    std::printf("| %d | %zu | %.3f s | %.3f s | %.2f s | %s | %s |%s\n", n, fast.size(), t_fast, t_fast1, t_torch,
                ref_cell.c_str(), ratio.c_str(), same ? "" : " **RESULTS DIFFER**");
    std::fflush(stdout);
  }
}

// Times the two model calls the generator makes.
class TimedModel : public AmgModel {
 public:
  explicit TimedModel(AmgModel& inner) : inner_(inner) {}
  void set_image(const uint8_t* rgb, int h, int w) override {
    const auto t0 = Clock::now();
    inner_.set_image(rgb, h, w);
    encode_s += seconds_since(t0), ++crops;
  }
  int input_size() const override { return inner_.input_size(); }
  void predict_points(const std::vector<Point2d>& pts, std::vector<float>& ious) override {
    const auto t0 = Clock::now();
    inner_.predict_points(pts, ious);
    decode_s += seconds_since(t0), prompts += pts.size();
  }
  void upsample_masks(const std::vector<int64_t>& indices, std::vector<float>& logits) override {
    const auto t0 = Clock::now();
    inner_.upsample_masks(indices, logits);
    upsample_s += seconds_since(t0), upsampled += indices.size();
  }
  double encode_s = 0, decode_s = 0, upsample_s = 0;
  int crops = 0;
  size_t prompts = 0, upsampled = 0;

 private:
  AmgModel& inner_;
};

struct AmgImage {
  int height = 0, width = 0;
  std::vector<uint8_t> rgb;
};

// A smooth synthetic photo at 1000x750: gradients plus a few flat rectangles and a disc.
AmgImage synthetic_photo() {
  AmgImage im{750, 1000, {}};
  const int h = im.height, w = im.width;
  im.rgb.resize(size_t(h) * w * 3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      uint8_t* p = &im.rgb[(size_t(y) * w + x) * 3];
      p[0] = uint8_t(x * 255 / w), p[1] = uint8_t(y * 255 / h), p[2] = uint8_t(((x / 125) + (y / 125)) % 2 ? 200 : 60);
      if ((x - 600) * (x - 600) + (y - 300) * (y - 300) < 120 * 120) p[0] = 250, p[1] = 30, p[2] = 30;
    }
  return im;
}

MaskLevels run_amg(sam::SamPredictor& predictor, const AmgImage& im, const AmgParams& params, const std::string& what,
                   int threads) {
  SamPredictorAmgModel sam_model(predictor);
  TimedModel timed(sam_model);
  torch::NoGradGuard no_grad;
  auto t0 = Clock::now();
  const MaskLevels levels = generate_masks(timed, im.rgb.data(), im.height, im.width, params, threads);
  const double t_amg = seconds_since(t0);
  t0 = Clock::now();
  const auto updated = masks_update(levels, MaskNmsParams{}, MaskNmsMethod::Fast, threads);
  const SegMap map = build_seg_map(updated.levels, im.height, im.width);
  const double t_post = seconds_since(t0);
  std::printf("\nAMG (points_per_side %d, crop_n_layers %d) on %dx%d, %s, %d threads\n\n", params.points_per_side,
              params.crop_n_layers, im.width, im.height, what.c_str(), threads);
  std::printf("| crops | prompts | encoder (all crops) | decoder | masks upsampled | postprocess_masks | AMG own work "
              "| AMG total | masks default/s/m/l | masks_update + seg map |\n|---|---|---|---|---|---|---|---|---|---|\n");
  std::printf("| %d | %zu | %.1f s | %.1f s | %zu | %.1f s | %.1f s | %.1f s | %zu/%zu/%zu/%zu | %.2f s |\n",
              timed.crops, timed.prompts, timed.encode_s, timed.decode_s, timed.upsampled, timed.upsample_s,
              t_amg - timed.encode_s - timed.decode_s - timed.upsample_s, t_amg,
              levels[0].size(), levels[1].size(), levels[2].size(), levels[3].size(), t_post);
  (void)map;
  return levels;
}

// An official architecture with random weights on the synthetic photo, LangSplat's parameters.
void bench_amg(const std::string& model_name, int points_per_side, int threads, const torch::Device& device) {
  torch::manual_seed(0);
  sam::Sam model(sam::sam_config_by_name(model_name));
  model->eval();
  model->to(device);
  sam::SamPredictor predictor(model);
  AmgParams params;  // LangSplat's
  params.points_per_side = points_per_side;
  run_amg(predictor, synthetic_photo(), params, "SAM " + model_name + " with random weights on " + device.str(), threads);
}

// The SAM fixture's tiny model on its test image with a reference run's parameters: the workload of
// the test SamAmgRun.<Run>MatchesReference; the mask counts are checked against the run's records.
void bench_fixture_amg(const std::string& dir, const std::string& run, int threads, const torch::Device& device) {
  sam::Sam model(sam::sam_config_from_json_file(dir + "/config.json"));
  sam::load_sam_weights(*model, read_safetensors(dir + "/weights.safetensors"));
  model->eval();
  model->to(device);
  sam::SamPredictor predictor(model);
  const NpyArray a = read_npy(dir + "/test_image.npy");
  if (a.shape.size() != 3 || a.shape[2] != 3) fail(dir + "/test_image.npy", "expected an H x W x 3 uint8 image");
  AmgImage im{static_cast<int>(a.shape[0]), static_cast<int>(a.shape[1]), {}};
  im.rgb.assign(a.as<uint8_t>(), a.as<uint8_t>() + a.numel());
  const std::string records_path = dir + "/amg/" + run + "_records.json";
  const auto records = nlohmann::json::parse(read_text_file(records_path));
  const MaskLevels got =
      run_amg(predictor, im, params_from_json(records.at("params"), records_path),
              "fixture SAM, run " + run + " on " + device.str(), threads);
  const MaskLevels expected = levels_from_json(records.at("levels"), records_path);
  for (int l = 0; l < kNumLevels; ++l)
    if (got[l].size() != expected[l].size())
      std::printf("**level %s: %zu masks, the reference has %zu**\n", level_name(l), got[l].size(), expected[l].size());
}

std::vector<int> parse_sizes(const std::string& s) {
  std::vector<int> v;
  std::stringstream ss(s);
  std::string tok;
  while (std::getline(ss, tok, ','))
    if (!tok.empty()) v.push_back(std::stoi(tok));
  return v;
}

}  // namespace
}  // namespace cls::amg

int main(int argc, char** argv) {
  cls::reuse_freed_memory();  // as the CLI does
  cls::Args args("bench_amg",
                 "LangSplat mask NMS (fast vs torch vs reference) at 1000x750 and the whole LangSplat AMG on a "
                 "1000x750 image with a randomly initialised SAM. Prints Markdown rows for docs/benchmarks.md.",
                 "");
  int threads = 2, reference_max = 200, points_per_side = 32;
  std::string masks = "200,400,600,800,1000", model = "vit_b", fixture, run = "strict", device_name = "cpu";
  args.bind("threads", threads, "CPU threads (OpenMP and LibTorch)")
      .bind("masks", masks, "mask counts for the NMS benchmark (empty: skip)")
      .bind("reference-max", reference_max, "largest mask count also timed with the slow reference")
      .bind("model", model, "SAM for the AMG benchmark: vit_b, vit_l, vit_h, or none to skip")
      .bind("points-per-side", points_per_side, "AMG grid (LangSplat: 32)")
      .bind("fixture", fixture, "SAM fixture folder (config.json, weights.safetensors, test_image.npy, amg/): run its "
                                "tiny model on its image instead of --model")
      .bind("run", run, "with --fixture: the reference run whose parameters to use (strict, relaxed)")
      .bind("device", device_name,
            "where SAM runs: cpu or cuda (needs a CUDA build); the NMS benchmark stays on the CPU");
  torch::Device device(torch::kCPU);
  try {
    if (!args.parse(argc, argv)) return 0;
    if (threads < 1) throw cls::UsageError("bench_amg: --threads must be positive");
    device = cls::compute_device(device_name);
  } catch (const cls::UsageError& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  }
  omp_set_num_threads(threads);
  at::set_num_threads(threads);
  try {
    const auto sizes = cls::amg::parse_sizes(masks);
    if (!sizes.empty()) cls::amg::bench_mask_nms(sizes, threads, reference_max);
    if (!fixture.empty())
      cls::amg::bench_fixture_amg(fixture, run, threads, device);
    else if (model != "none")
      cls::amg::bench_amg(model, points_per_side, threads, device);
  } catch (const cls::Error& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
  return 0;
}
