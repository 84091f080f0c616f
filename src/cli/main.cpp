// citylangsplat: a thin CLI over the library. Global flags: -v/--verbose, -q/--quiet, --threads N,
// --version.
#include <ATen/Parallel.h>
#include <omp.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <string>
#include <vector>

#include "cli/commands.h"
#include "core/cpu_threads.h"
#include "core/heap_reuse.h"
#include "core/error.h"
#include "core/exit_codes.h"
#include "core/log.h"

namespace {

struct Command {
  const char* name;
  int (*fn)(int, char**);
  const char* summary;
};

const Command kCommands[] = {
    {"run", cls::cmd_run, "run every stage on a scene directory, reusing finished stages"},
    {"citymodel", cls::cmd_citymodel, "inspect a CityGML/CityJSON model: stats, export"},
    {"raycast", cls::cmd_raycast, "raycast the city model into per-view label maps and coverage"},
    {"align", cls::cmd_align, "refine the city model's transform into the scene from the scene's points (ICP)"},
    {"georef", cls::cmd_georef, "find the city model's transform into the scene from the photos' EXIF GPS (no transform given)"},
    {"align-check", cls::cmd_align_check, "check how well a scene's sparse points lie on the city model"},
    {"synth", cls::cmd_synth, "render a synthetic scene (images, COLMAP model, ground truth) of a city model"},
    {"scene", cls::cmd_scene, "inspect or convert a scene (COLMAP / Pix4D)"},
    {"models", cls::cmd_models, "list, download and check CLIP/SAM weight files"},
    {"features", cls::cmd_features, "per-view SAM and CityGML language features (LangSplat's layout)"},
    {"autoencoder", cls::cmd_autoencoder, "train the shared autoencoder (512 -> 128) on SAM features"},
    {"train-rgb", cls::cmd_train_rgb, "train 3D Gaussians photometrically (3DGS) on a scene"},
    {"train-language", cls::cmd_train_language, "train the language field on a frozen photometric model (paper 3.3)"},
    {"query", cls::cmd_query, "query a language model with text: Gaussian scores, selections, relevance maps"},
    {"evaluate", cls::cmd_evaluate, "evaluate language models against a labelled point cloud (2D and 3D)"},
    {"render", cls::cmd_render, "render a model: RGB vs photo (PSNR/SSIM), depth, features, relevance, labels, orbit video"},
    {"report", cls::cmd_report, "write a run directory's HTML report (report/index.html) and print its path"},
    {"view", cls::cmd_view, "serve a model in the browser: splats, cameras, live text queries answered with city objects"},
    {"export", cls::cmd_export, "write a model as glTF (KHR_gaussian_splatting) with its city objects and query scores"},
    {"enrich", cls::cmd_enrich, "write the run's city model as CityJSON 2.0 enriched with what the run learned of each object"},
    {"changes", cls::cmd_changes, "propose the windows and doors the city model lacks, flag the surfaces the photos contradict"},
    {"tile", cls::cmd_tile, "cut a district into tiles of whole buildings for run-tiles (docs/scale.md)"},
    {"run-tiles", cls::cmd_run_tiles, "run every tile (Slurm arrays or local processes) with one shared autoencoder"},
    {"tiles", cls::cmd_tiles, "progress of run-tiles (status), or one of its tasks (task)"},
    {"merge", cls::cmd_merge, "merge the tiles' language models into one model of the district"},
};

void usage(FILE* out) {
  std::fprintf(out,
               "usage: citylangsplat [-v|-q] [--threads N] <command> [options]\n\n"
               "Open-vocabulary understanding of urban 3D scenes with CityGML-guided language Gaussians.\n\n"
               "commands:\n");
  for (const auto& c : kCommands) std::fprintf(out, "  %-12s %s\n", c.name, c.summary);
  std::fprintf(out,
               "\nglobal options:\n"
               "  -v, --verbose   more output\n"
               "  -q, --quiet     only errors\n"
               "  --threads N     CPU threads of LibTorch and OpenMP (default: OMP_NUM_THREADS if set,\n"
               "                  else the CPUs this process may run on; here %d)\n"
               "  --version       print the version\n"
               "\n'citylangsplat <command> --help' shows a command's options and defaults.\n%s\n",
               cls::default_cpu_threads(), cls::kExitCodesHelp);
}

}  // namespace

int main(int argc, char** argv) {
  cls::reuse_freed_memory();
  std::vector<char*> args;
  args.push_back(argv[0]);
  int threads = cls::default_cpu_threads();
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (args.size() == 1 && a == "--threads") {
      const long n = i + 1 < argc ? std::strtol(argv[i + 1], nullptr, 10) : 0;
      if (n <= 0 || n > 4096 || std::to_string(n) != argv[i + 1]) {
        std::fprintf(stderr, "error: --threads needs a positive integer, got '%s'\n", i + 1 < argc ? argv[i + 1] : "");
        return cls::kExitUsage;
      }
      threads = static_cast<int>(n);
      ::setenv("OMP_NUM_THREADS", argv[i + 1], 1);  // the processes it starts (run-tiles' tasks) share them
      ++i;
    } else if (args.size() == 1 && (a == "-v" || a == "--verbose")) {
      cls::set_log_level(cls::LogLevel::Verbose);
    } else if (args.size() == 1 && (a == "-q" || a == "--quiet")) {
      cls::set_log_level(cls::LogLevel::Quiet);
    } else if (args.size() == 1 && a == "--version") {
      std::printf("citylangsplat %s\n", CLS_VERSION);
      return 0;
    } else if (args.size() == 1 && (a == "-h" || a == "--help")) {
      usage(stdout);
      return 0;
    } else {
      args.push_back(argv[i]);
    }
  }
  if (args.size() < 2) {
    usage(stderr);
    return cls::kExitUsage;
  }
  // Before any ATen call: LibTorch applies it to OpenMP in each thread that enters ATen later.
  at::set_num_threads(threads);
  omp_set_num_threads(threads);
  cls::log_verbose(cls::cat("CPU threads: ", threads));
  for (const auto& c : kCommands) {
    if (std::strcmp(c.name, args[1]) != 0) continue;
    try {
      return c.fn(static_cast<int>(args.size()) - 1, args.data() + 1);
    } catch (const cls::UsageError& e) {
      std::fprintf(stderr, "error: %s\n", e.what());
      return cls::kExitUsage;
    } catch (const cls::Error& e) {
      std::fprintf(stderr, "error: %s\n", e.what());
      return cls::kExitError;
    } catch (const std::exception& e) {
      std::fprintf(stderr, "internal error: %s\n", e.what());
      return cls::kExitInternal;
    }
  }
  std::fprintf(stderr, "error: unknown command '%s'\n\n", args[1]);
  usage(stderr);
  return cls::kExitUsage;
}
