// SAM image-encoder time per 1000x750 image (resized to 1024x768, normalised, padded, encoded:
// SamPredictor::set_image) for the official ViT-B / ViT-L / ViT-H architectures with random weights
// (the time does not depend on the values). Figures go to docs/benchmarks.md.
// Usage: bench_sam [--models vit_b,vit_h] [--threads 2] [--repeats 3] [--repeats-h 1]
#include <torch/torch.h>

#include <chrono>
#include <cstdio>
#include <ctime>
#include <sstream>
#include <string>
#include <vector>

#include "bench_timer.h"
#include "core/args.h"
#include "core/error.h"
#include "core/heap_reuse.h"
#include "models/sam/sam_predictor.h"

namespace cls {
namespace {

using bench::Clock;
using bench::cpu_seconds;
using bench::seconds_since;
// A deterministic textured RGB image (the encoder's cost does not depend on the content).
std::vector<uint8_t> synthetic_image(int h, int w) {
  std::vector<uint8_t> img(size_t(h) * w * 3);
  uint32_t s = 12345;
  for (size_t i = 0; i < img.size(); ++i) {
    s = s * 1664525u + 1013904223u;
    img[i] = uint8_t(((i / 3) % 97) + (s >> 26));
  }
  return img;
}

int run(int argc, char** argv) {
  Args args("bench_sam", "SAM image encoder time per 1000x750 image (random weights)", "");
  std::string model_names = "vit_b,vit_h";
  int threads = 2, repeats_default = 3, repeats_h = 1, w = 1000, h = 750;
  args.bind("models", model_names, "comma-separated architectures (vit_b, vit_l, vit_h)")
      .bind("threads", threads, "LibTorch intra-op threads")
      .bind("repeats", repeats_default, "timed runs per model (after one warm-up run)")
      .bind("repeats-h", repeats_h, "timed runs for vit_h (slow on few cores)")
      .bind("width", w, "image width")
      .bind("height", h, "image height");
  if (!args.parse(argc, argv)) return 0;
  torch::set_num_threads(threads);
  const auto image = synthetic_image(h, w);
  std::printf("image %dx%d -> 1024 longest side, %d threads\n", w, h, threads);
  std::printf("%-6s %10s %8s %12s %12s %14s\n", "model", "params(M)", "runs", "build (s)", "s/image", "CPU-norm s/img");
  std::stringstream models(model_names);
  std::string name;
  while (std::getline(models, name, ',')) {
    const auto cfg = sam::sam_config_by_name(name);
    const int repeats = name == "vit_h" ? repeats_h : repeats_default;
    auto t0 = Clock::now();
    sam::SamPredictor predictor{sam::Sam(cfg)};
    const double build = seconds_since(t0);
    int64_t params = 0;
    for (const auto& p : predictor.model()->image_encoder->parameters()) params += p.numel();
    predictor.set_image(image.data(), h, w);  // warm-up
    const double c0 = cpu_seconds();
    t0 = Clock::now();
    for (int r = 0; r < repeats; ++r) predictor.set_image(image.data(), h, w);
    const double wall = seconds_since(t0) / repeats;
    const double cpu = (cpu_seconds() - c0) / repeats;
    // CPU-normalised: CPU seconds of the process spread over `threads` cores (an estimate for idle
    // cores when the machine is shared).
    std::printf("%-6s %10.1f %8d %12.2f %12.2f %14.2f\n", name.c_str(), params / 1e6, repeats, build, wall, cpu / threads);
    std::fflush(stdout);
  }
  return 0;
}

}  // namespace
}  // namespace cls

int main(int argc, char** argv) {
  cls::reuse_freed_memory();  // as the CLI does
  try {
    return cls::run(argc, argv);
  } catch (const cls::Error& e) {
    std::fprintf(stderr, "bench_sam: %s\n", e.what());
    return 1;
  }
}
