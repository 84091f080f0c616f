// citylangsplat report RUN_DIR: (re)writes RUN_DIR/report/index.html from what the run directory holds
// (`run` writes it at its end; this command refreshes it, e.g. after `render` or `evaluate`).
#include <cstdio>
#include <string>

#include "cli/commands.h"
#include "core/args.h"
#include "core/exit_codes.h"
#include "report/report.h"

namespace cls {

int cmd_report(int argc, char** argv) {
  Args args("report",
            "Write RUN_DIR/report/index.html: a static page (opens from disk, no server or network) with the stages, "
            "settings, label maps, training curves, test renders, evaluation tables and relevance maps of a "
            "`citylangsplat run` output directory. Prints the page's path. See docs/report.md.");
  std::string run_dir;
  args.positional("RUN_DIR", run_dir, "a `citylangsplat run` output directory (holds run.json)");
  if (!args.parse(argc, argv)) return kExitOk;
  std::printf("%s\n", write_report(run_dir).string().c_str());
  return kExitOk;
}

}  // namespace cls
