// citylangsplat tiles status|task: progress of run-tiles, and one task of it (what the executors run).
#include <cstdio>
#include <filesystem>
#include <string>

#include "cli/commands.h"
#include "core/args.h"
#include "core/error.h"
#include "core/exit_codes.h"
#include "tiles/tile_status.h"
#include "tiles/tile_tasks.h"

namespace cls {
namespace fs = std::filesystem;

namespace {

int tiles_status(int argc, char** argv) {
  Args args("tiles status", "Tasks finished per phase, the tiles still missing, and the Slurm jobs of the last run-tiles.");
  fs::path dir;
  args.positional("TILES", dir, "tiles directory");
  if (!args.parse(argc, argv)) return kExitOk;
  std::printf("%s", tiles_status_text(dir).c_str());
  return tiles_finished(dir, read_tiles_dir(dir)) ? kExitOk : kExitError;
}

int tiles_task(int argc, char** argv) {
  Args args("tiles task",
            "Run one task of run-tiles in this process (what the task scripts under TILES/jobs run): "
            "PHASE features|autoencoder|train, INDEX the tile (0 for the autoencoder).");
  fs::path dir;
  std::string phase, index;
  args.positional("TILES", dir, "tiles directory")
      .positional("PHASE", phase, "features, autoencoder or train")
      .positional("INDEX", index, "task index");
  if (!args.parse(argc, argv)) return kExitOk;
  if (index.empty() || index.find_first_not_of("0123456789") != std::string::npos || index.size() > 6)
    throw UsageError("tiles task: INDEX must be a task number, got '" + index + "'");
  return run_tile_task(dir, parse_tile_phase(phase), std::stoi(index));
}

}  // namespace

int cmd_tiles(int argc, char** argv) {
  const std::string usage =
      "usage: citylangsplat tiles status TILES\n"
      "       citylangsplat tiles task TILES PHASE INDEX\n"
      "'citylangsplat tiles <status|task> --help' shows the options.\n";
  if (argc < 2) throw UsageError("tiles: missing subcommand\n" + usage);
  const std::string sub = argv[1];
  if (sub == "-h" || sub == "--help") {
    std::printf("%s", usage.c_str());
    return kExitOk;
  }
  if (sub == "status") return tiles_status(argc - 1, argv + 1);
  if (sub == "task") return tiles_task(argc - 1, argv + 1);
  throw UsageError("tiles: unknown subcommand '" + sub + "'\n" + usage);
}

}  // namespace cls
