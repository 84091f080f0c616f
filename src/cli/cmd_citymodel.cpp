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
struct ModelOptions {
  std::string file;
  CityModelOptions model;

  Args& bind(Args& args) {
    return args.positional("FILE", file, "CityGML (.gml/.xml), CityJSON (.json) or CityJSONSeq (.jsonl) file")
        .bind("lod", model.lod, "level of detail: 1, 2, 3 or highest", lod_codec())
        .bind("taxonomy", model.taxonomy_path, "taxonomy JSON (source types -> classes); the built-in one if not given");
  }
};

int run_stats(int argc, char** argv) {
  Args args("citymodel stats", "Print the semantic classes of a city model with triangle counts, areas "
                               "(square source units) and object counts.");
  ModelOptions options;
  bool json = false;
  options.bind(args).flag("json", json, "print exactly one JSON object on stdout instead of a table");
  if (!args.parse(argc, argv)) return 0;
  const Taxonomy taxonomy = load_taxonomy(options.model);
  const SemanticMesh mesh = load_city_model(options.file, taxonomy, options.model.lod);
  const MeshStats stats = compute_mesh_stats(mesh, taxonomy);
  const std::string text = json ? mesh_stats_json(stats) + "\n" : mesh_stats_table(stats);
  std::fwrite(text.data(), 1, text.size(), stdout);
  return 0;
}

int run_export(int argc, char** argv) {
  Args args("citymodel export", "Write the semantic mesh as a binary little-endian PLY: float vertices, "
                                "faces with RGB of their level-1 class, class ids per level and building index.");
  ModelOptions options;
  std::string out, transform_path;
  options.bind(args)
      .bind("out", out, "output PLY file")
      .required()
      .bind("city-transform", transform_path, "JSON similarity from the model's CRS into the scene frame; "
                                              "without it vertices are local (source minus the origin in the header)");
  if (!args.parse(argc, argv)) return 0;
  const Taxonomy taxonomy = load_taxonomy(options.model);
  // Everything is read and validated before anything is written.
  CityTransform transform;
  if (!transform_path.empty()) transform = read_city_transform(transform_path);
  const SemanticMesh mesh = load_city_model(options.file, taxonomy, options.model.lod);
  write_mesh_ply(out, mesh, taxonomy, transform_path.empty() ? nullptr : &transform);
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
