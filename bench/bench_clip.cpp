// CLIP throughput at real dimensions with random weights: LangSplat region crops per second
// (crop + pad + resize + normalise + ViT image encoder, batched) and text encodes per second
// (tokenizer + text transformer). Usage: bench_clip [--model ViT-B-16] [--threads 2] [--batch 32]
// [--batches 3] [--device cpu|cuda] [--dtype float32|float16|bfloat16]. Figures go to docs/benchmarks.md.
#include <ATen/ATen.h>
#include <ATen/Parallel.h>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <string>
#include <vector>

#include "bench_timer.h"
#include "core/args.h"
#include "core/error.h"
#include "core/heap_reuse.h"
#include "models/clip/clip_model.h"
#include "models/clip/region_crops.h"
#include "models/clip/region_encoder.h"
#include "models/clip/tokenizer.h"
#include "models/weights/clip_weights.h"

namespace cls {
namespace {

using bench::Clock;
using bench::cpu_seconds;
using bench::seconds_since;
// Random weights with the reference state_dict's names and shapes (scale 0.02, LayerNorm weight 1).
std::map<std::string, at::Tensor> random_state(const clip::ClipConfig& config) {
  std::map<std::string, at::Tensor> state;
  for (const ExpectedTensor& e : clip_expected_tensors(config.arch)) {
    const bool ln_weight = e.name.find("ln_") != std::string::npos && e.name.size() > 7 &&
                           e.name.compare(e.name.size() - 7, 7, ".weight") == 0;
    state[e.name] = ln_weight ? at::ones(e.shape) : at::randn(e.shape) * 0.02;
  }
  state["logit_scale"] = at::full({}, std::log(100.0));
  return state;
}

int run(int argc, char** argv) {
  Args args("bench_clip", "CLIP crops/s and text encodes/s at real dimensions with random weights", "");
  std::string model_name = "ViT-B-16", device = "cpu", dt = "float32";
  int threads = 2, batch = 32, batches = 3, n_texts = 64;
  args.bind("model", model_name, "ViT-B-32 | ViT-B-16 | ViT-L-14")
      .bind("threads", threads, "CPU threads (at::set_num_threads)")
      .bind("batch", batch, "crops per image-encoder batch")
      .bind("batches", batches, "timed batches (after one warm-up batch)")
      .bind("texts", n_texts, "texts per timed text run (batches of --batch)")
      .bind("device", device, "cpu | cuda")
      .bind("dtype", dt, "float32 | float16 | bfloat16 (half types on CUDA only)");
  if (!args.parse(argc, argv)) return 0;
  at::set_num_threads(threads);
  at::manual_seed(0);
  const clip::ClipConfig config = clip::clip_preset(model_name, clip::Activation::Gelu);
  clip::ClipOptions options;
  options.device = c10::Device(device);
  options.dtype = dt == "float16" ? at::kHalf : dt == "bfloat16" ? at::kBFloat16 : at::kFloat;
  const clip::ClipModel model(config, random_state(config), options, "random " + model_name);

  // A 1000 x 750 image and `batch` elliptic masks of varied size, as SAM would give.
  cv::Mat rgb(750, 1000, CV_8UC3);
  cv::randu(rgb, 0, 256);
  std::vector<cv::Mat> masks;
  for (int i = 0; i < batch; ++i) {
    cv::Mat m = cv::Mat::zeros(750, 1000, CV_8U);
    cv::ellipse(m, cv::Point(100 + (i * 97) % 800, 80 + (i * 61) % 600), cv::Size(20 + (i * 13) % 200, 15 + (i * 7) % 150),
                i * 11.0, 0, 360, cv::Scalar(1), -1);
    masks.push_back(m);
  }
  clip::encode_regions(model, rgb, masks, batch);  // warm-up
  double crop_s = 0;
  {
    const auto t0 = Clock::now();
    for (int i = 0; i < batch; ++i) clip::langsplat_region_crop(rgb, masks[i], config.arch.image_resolution);
    crop_s = seconds_since(t0);
  }
  const double c0 = cpu_seconds();
  const auto t0 = Clock::now();
  for (int b = 0; b < batches; ++b) clip::encode_regions(model, rgb, masks, batch);
  if (options.device.is_cuda()) at::zeros({1}, at::TensorOptions().device(options.device)).cpu();  // sync
  const double wall = seconds_since(t0), cpu = cpu_seconds() - c0;
  const double crops = double(batch) * batches;

  // Text: tokenise + encode, `texts` prompts in batches of `batch`.
  const clip::Tokenizer tokenizer;
  std::vector<std::string> texts;
  for (int i = 0; i < n_texts; ++i) texts.push_back("a photo of building part number " + std::to_string(i));
  auto encode_texts = [&] {
    for (int b = 0; b < n_texts; b += batch) {
      const std::vector<std::string> chunk(texts.begin() + b, texts.begin() + std::min(n_texts, b + batch));
      const std::vector<int64_t> ids = tokenizer.tokenize(chunk);
      const at::Tensor tok = at::from_blob(const_cast<int64_t*>(ids.data()),
                                           {int64_t(chunk.size()), config.arch.context_length}, at::kLong).clone();
      model.encode_text(tok.to(options.device));
    }
  };
  encode_texts();  // warm-up (fills the BPE cache, like repeated prompts do)
  const double tc0 = cpu_seconds();
  const auto tt0 = Clock::now();
  encode_texts();
  const double twall = seconds_since(tt0), tcpu = cpu_seconds() - tc0;

  std::printf("model %s, device %s, dtype %s, threads %d, batch %d\n", model_name.c_str(), device.c_str(), dt.c_str(),
              threads, batch);
  std::printf("crop preparation only: %.1f crops/s (%d crops of a 1000x750 image, 1 call each)\n", batch / crop_s, batch);
  std::printf("region crops (prepare + encode): %.1f crops/s wall, %.1f per CPU-second x threads (%d crops, %.2f s)\n",
              crops / wall, crops / cpu * threads, int(crops), wall);
  std::printf("text encodes (tokenise + encode): %.1f texts/s wall, %.1f per CPU-second x threads (%d texts, %.2f s)\n",
              n_texts / twall, n_texts / tcpu * threads, n_texts, twall);
  return 0;
}

}  // namespace
}  // namespace cls

int main(int argc, char** argv) {
  cls::reuse_freed_memory();  // as the CLI does
  try {
    return cls::run(argc, argv);
  } catch (const cls::UsageError& e) {
    std::fprintf(stderr, "bench_clip: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_clip: %s\n", e.what());
    return 1;
  }
}
