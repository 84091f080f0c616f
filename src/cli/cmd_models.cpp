// citylangsplat models list [--models-dir DIR] [--json]
// citylangsplat models download NAME... [--models-dir DIR] [--mirror URL]
// citylangsplat models check FILE --model NAME
#include <cstdio>
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "core/args.h"
#include "cli/commands.h"
#include "core/error.h"
#include "core/log.h"
#include "models/model_registry.h"
#include "models/weights/clip_weights.h"
#include "models/weights/download.h"
#include "models/weights/sam_weights.h"

namespace cls {
namespace fs = std::filesystem;
namespace {

std::string size_text(uint64_t bytes) {
  if (bytes == 0) return "?";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f MB", static_cast<double>(bytes) / 1e6);
  return buf;
}

std::string names_text() {
  std::string s;
  for (const auto& m : known_models()) s += (s.empty() ? "" : ", ") + m.name;
  return s;
}

int models_list(int argc, char** argv) {
  Args args("models list", "Show the known model files, their sources and checksums, and which are present.");
  std::string models_dir;
  bool json = false;
  args.bind("models-dir", models_dir, "directory searched first (then $CITYLANGSPLAT_MODELS, then the XDG cache)")
      .flag("json", json, "print one JSON object instead of text");
  if (!args.parse(argc, argv)) return 0;
  const auto dirs = model_search_dirs(models_dir);
  nlohmann::json out = {{"search_dirs", nlohmann::json::array()}, {"models", nlohmann::json::array()}};
  for (const auto& d : dirs) out["search_dirs"].push_back(d.string());
  for (const KnownModel& m : known_models()) {
    const auto found = find_model_file(m, dirs);
    out["models"].push_back({{"name", m.name},
                             {"family", m.family},
                             {"arch", m.arch},
                             {"file", m.file_name},
                             {"url", m.url},
                             {"size", m.size},
                             {"sha256", m.sha256},
                             {"present", found.has_value()},
                             {"path", found ? found->string() : ""},
                             {"description", m.description}});
  }
  if (json) {
    std::printf("%s\n", out.dump().c_str());
    return 0;
  }
  std::printf("search directories (in order):\n");
  for (const auto& d : dirs) std::printf("  %s\n", d.string().c_str());
  std::printf("\n");
  for (const auto& m : out["models"]) {
    std::printf("%-26s %-8s %s\n", m["name"].get<std::string>().c_str(),
                m["present"].get<bool>() ? "present" : "missing", m["description"].get<std::string>().c_str());
    std::printf("    file %s, %s, sha256 %s\n", m["file"].get<std::string>().c_str(),
                size_text(m["size"].get<uint64_t>()).c_str(),
                m["sha256"].get<std::string>().empty() ? "(not published)" : m["sha256"].get<std::string>().c_str());
    if (m["present"].get<bool>()) std::printf("    at %s\n", m["path"].get<std::string>().c_str());
    std::printf("    from %s\n", m["url"].get<std::string>().c_str());
  }
  return 0;
}

int models_download(int argc, char** argv) {
  Args args("models download", "Download known model files into the model cache, resuming and verifying checksums.");
  std::vector<std::string> names;
  std::string models_dir, mirror;
  bool progress = true;
  args.bind("models-dir", models_dir, "download into this directory (default: $CITYLANGSPLAT_MODELS, else the XDG cache)")
      .bind("mirror", mirror, "fetch <mirror>/<file name> instead of the official URL (e.g. file:///media/usb/models)")
      .flag("no-progress", progress, "do not show progress", false)
      .rest("NAME", names, "model names (see 'citylangsplat models list')");
  if (!args.parse(argc, argv)) return 0;
  const fs::path dir = model_download_dir(models_dir);
  const auto dirs = model_search_dirs(models_dir);
  std::vector<const KnownModel*> models;
  for (const auto& name : names) {
    const KnownModel* m = find_known_model(name);
    if (!m) throw UsageError("models download: unknown model '" + name + "' (known: " + names_text() + ")");
    models.push_back(m);
  }
  for (const KnownModel* m : models) {
    if (const auto found = find_model_file(*m, dirs); found && *found != dir / m->file_name) {
      log_info(cat(m->name, ": present at ", found->string()));
      continue;
    }
    DownloadRequest req;
    req.url = mirror.empty() ? m->url : mirror + "/" + m->file_name;
    req.dest = dir / m->file_name;
    req.expected_size = m->size;
    req.sha256 = m->sha256;
    req.label = m->name;
    req.progress = progress;
    DownloadResult r;
    try {
      r = download_file(req);
    } catch (const DownloadError& e) {
      throw Error(std::string(e.what()) + "\nIf this machine is offline, download " + m->url +
                  " on another machine and put it at " + req.dest.string() +
                  " (or into the directory given by --models-dir or $CITYLANGSPLAT_MODELS)" +
                  (m->sha256.empty() ? "." : "; its sha256 must be " + m->sha256 + "."));
    }
    if (r.already_present) {
      log_info(cat(m->name, ": present at ", r.path.string(), " (sha256 ", m->sha256.empty() ? "not published" : "verified", ")"));
    } else {
      log_info(cat(m->name, ": ", r.bytes, " bytes at ", r.path.string(),
                   r.resumed_from ? cat(" (resumed at ", r.resumed_from, ")") : std::string(),
                   m->sha256.empty() ? ", sha256 " + r.sha256 + " (no published checksum to verify)" : ", sha256 verified"));
    }
  }
  return 0;
}

int models_check(int argc, char** argv) {
  Args args("models check", "Check a weight file's tensor names and shapes against a model, without loading it.");
  std::string file, arch;
  args.positional("FILE", file, "safetensors, torch.save zip or TorchScript archive")
      .bind("model", arch, "known model name (see 'models list') or architecture: ViT-B-32, ViT-B-16, ViT-L-14, vit_b, vit_l, vit_h")
      .required();
  if (!args.parse(argc, argv)) return 0;
  if (const KnownModel* m = find_known_model(arch)) arch = m->arch;
  WeightFile w;
  std::string what;
  if (arch.rfind("ViT-", 0) == 0) {
    w = load_clip_checkpoint(file, clip_arch(arch));
    what = "CLIP " + arch;
  } else {
    w = load_sam_checkpoint(file, sam_arch(arch));
    what = "SAM " + arch;
  }
  std::printf("%s: %zu tensors match %s\n", file.c_str(), w.size(), what.c_str());
  return 0;
}

}  // namespace

int cmd_models(int argc, char** argv) {
  const std::string usage =
      "usage: citylangsplat models list [--models-dir DIR] [--json]\n"
      "       citylangsplat models download NAME... [--models-dir DIR] [--mirror URL]\n"
      "       citylangsplat models check FILE --model NAME\n"
      "'citylangsplat models <list|download|check> --help' shows the options.\n";
  if (argc < 2) throw UsageError("models: missing subcommand\n" + usage);
  const std::string sub = argv[1];
  if (sub == "-h" || sub == "--help") {
    std::printf("%s", usage.c_str());
    return 0;
  }
  if (sub == "list") return models_list(argc - 1, argv + 1);
  if (sub == "download") return models_download(argc - 1, argv + 1);
  if (sub == "check") return models_check(argc - 1, argv + 1);
  throw UsageError("models: unknown subcommand '" + sub + "'\n" + usage);
}

}  // namespace cls
