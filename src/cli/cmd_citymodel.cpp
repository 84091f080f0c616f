// citylangsplat citymodel stats|export: inspect a CityGML / CityJSON model.
#include <cstdio>
#include <cstring>
#include <string>

#include "core/args.h"
#include "cli/commands.h"
#include "citymodel/city_model.h"
#include "citymodel/city_transform.h"
#include "citymodel/mesh_ply.h"
#include "citymodel/mesh_stats.h"
#include "core/error.h"

namespace cls {
namespace {

const char* const kUsage =
    "usage: citylangsplat citymodel <stats|export> FILE [options]\n\n"
    "  stats   counts and areas per semantic class (--json: one JSON object on stdout)\n"
    "  export  the semantic mesh as a binary PLY with per-face class colours\n\n"
    "'citylangsplat citymodel <stats|export> --help' shows the options and defaults.\n";

// Options every subcommand shares: the model, its LoD and the taxonomy.
void add_model_options(Args& args) {
  args.positional("FILE", "CityGML (.gml/.xml), CityJSON (.json) or CityJSONSeq (.jsonl) file")
      .option("lod", "highest", "level of detail: 1, 2, 3 or highest")
      .option("taxonomy", "", "taxonomy JSON (source types -> classes); the built-in one if not given");
}

CityModelOptions model_options(const Args& args) {
  CityModelOptions o;
  o.lod = parse_lod_option(args.get("lod"));
  o.taxonomy_path = args.get("taxonomy");
  return o;
}

int run_stats(int argc, char** argv) {
  Args args("citymodel stats", "Print the semantic classes of a city model with triangle counts, areas "
                               "(square source units) and object counts.");
  add_model_options(args);
  args.flag("json", "print exactly one JSON object on stdout instead of a table");
  if (!args.parse(argc, argv)) return 0;
  const CityModelOptions options = model_options(args);
  const Taxonomy taxonomy = load_taxonomy(options);
  const SemanticMesh mesh = load_city_model(args.get("FILE"), taxonomy, options.lod);
  const MeshStats stats = compute_mesh_stats(mesh, taxonomy);
  const std::string text = args.flag_set("json") ? mesh_stats_json(stats) + "\n" : mesh_stats_table(stats);
  std::fwrite(text.data(), 1, text.size(), stdout);
  return 0;
}

int run_export(int argc, char** argv) {
  Args args("citymodel export", "Write the semantic mesh as a binary little-endian PLY: float vertices, "
                                "faces with RGB of their level-1 class, class ids per level and building index.");
  add_model_options(args);
  args.option("out", "", "output PLY file (required)")
      .option("city-transform", "", "JSON similarity from the model's CRS into the scene frame; "
                                    "without it vertices are local (source minus the origin in the header)");
  if (!args.parse(argc, argv)) return 0;
  if (!args.has("out")) throw UsageError("citymodel export: --out is required (see --help)");
  const CityModelOptions options = model_options(args);
  const Taxonomy taxonomy = load_taxonomy(options);
  // Everything is read and validated before anything is written.
  CityTransform transform;
  if (args.has("city-transform")) transform = read_city_transform(args.get("city-transform"));
  const SemanticMesh mesh = load_city_model(args.get("FILE"), taxonomy, options.lod);
  write_mesh_ply(args.get("out"), mesh, taxonomy, args.has("city-transform") ? &transform : nullptr);
  return 0;
}

}  // namespace

int cmd_citymodel(int argc, char** argv) {
  if (argc < 2 || std::strcmp(argv[1], "--help") == 0 || std::strcmp(argv[1], "-h") == 0) {
    std::fputs(kUsage, argc < 2 ? stderr : stdout);
    return argc < 2 ? 2 : 0;
  }
  const std::string sub = argv[1];
  if (sub == "stats") return run_stats(argc - 1, argv + 1);
  if (sub == "export") return run_export(argc - 1, argv + 1);
  throw UsageError("citymodel: unknown subcommand '" + sub + "' (stats or export)");
}

}  // namespace cls
