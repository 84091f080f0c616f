// citylangsplat merge: the tiles' language fields as one model (src/tiles/tile_merge.h).
#include <cstdio>
#include <filesystem>

#include "cli/commands.h"
#include "core/args.h"
#include "core/error.h"
#include "core/exit_codes.h"
#include "core/run_layout.h"
#include "tiles/tile_merge.h"

namespace cls {
namespace fs = std::filesystem;

int cmd_merge(int argc, char** argv) {
  Args args("merge",
            "Merge the language fields of every tile into one model in the district's frame: each tile keeps the "
            "Gaussians whose centre lies in its own cell of the partition (no duplicates at the seams). Writes "
            "OUT/language/<method>/ (open it with query, evaluate, render or view) and OUT/merge.json.");
  fs::path tiles, out;
  args.positional("TILES", tiles, "tiles directory whose run-tiles finished")
      .bind("out", out, "output directory")
      .required();
  if (!args.parse(argc, argv)) return kExitOk;
  const nlohmann::json r = merge_tiles(tiles, out);
  for (const auto& [method, m] : r["methods"].items())
    std::printf("%s: %lld Gaussians from %zu tiles, %lld in another tile's cell (a plain union: %lld): %s\n",
                method.c_str(), m["gaussians"].get<long long>(), m["tiles"].size(),
                m["in_another_tiles_cell"].get<long long>(), m["naive_union_in_another_tiles_cell"].get<long long>(),
                RunLayout(out).language(method).string().c_str());
  return kExitOk;
}

}  // namespace cls
