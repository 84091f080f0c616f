// citylangsplat export: a trained model as glTF with its city objects (src/export, docs/export.md).
#include "cli/commands.h"
#include "core/args.h"
#include "core/log.h"
#include "export/export_job.h"

namespace cls {

int cmd_export(int argc, char** argv) {
  Args args("export",
            "Write a model as glTF 2.0 for the field's tools (CesiumJS, three.js, PlayCanvas, Babylon.js): its\n"
            "Gaussians with KHR_gaussian_splatting, per splat the city object it belongs to on each level\n"
            "(EXT_mesh_features into an EXT_structural_metadata table of gml:ids, classes, buildings and parts)\n"
            "and the scores of the TEXT queries given; placed in the city model's CRS (minus an origin the\n"
            "asset's extras keep, y up) when the run recorded the city transform. See docs/export.md.");
  ExportOptions o;
  args.positional("MODEL", o.input, "a `run` output, a language model directory (model.json) or a 3DGS .ply")
      .rest("TEXT", o.queries, "text queries whose per-splat scores go out as property attributes")
      .optional()
      .bind("format", o.format, "glb (one file), gltf (JSON + .bin), or 3dtiles (a directory: tileset.json on the globe\n"
                                "through the city model's CRS, and tiles/*.glb)")
      .bind("compress", o.compress, "none, or spz: the Gaussians as one SPZ payload (KHR_gaussian_splatting_compression_spz_2;\n"
                                    "lossy, about a tenth of the size; what CesiumJS needs to render splats in 3D Tiles)")
      .default_text("spz for 3dtiles, else none")
      .bind("spz-axes", o.spz_axes, "with spz: luf packs from glTF's axes as the extension's text says; cesium stores them\n"
                                    "unchanged, as CesiumJS 1.145 reads SPZ (a luf payload shows there turned half about\n"
                                    "the vertical: docs/export.md)")
      .default_text("cesium for 3dtiles, else luf")
      .bind("out", o.out, "the file (the directory for 3dtiles) to write (empty: gaussians.<format>, gaussians_3dtiles/ in\n"
                          "the model's directory)")
      .bind("tile-splats", o.tile_splats, "3dtiles: the most Gaussians in one tile; a model with more is cut into a quadtree\n"
                                          "with levels of detail (a coarse tile keeps the most opaque, largest Gaussians of its\n"
                                          "area, its four quadrants add the rest)")
      .bind("method", o.method, "which language model of a run output: citylangsplat or langsplat")
      .bind("level", o.level, "the queries' level: 1, 2, 3, or best (per text the level with the highest score)")
      .flag("scene-frame", o.georeference, "keep the frame the model was trained in, not the city model's CRS", false);
  if (!args.parse(argc, argv)) return 0;
  const nlohmann::json done = run_export(o);
  log_info(cat("export: wrote ", done["file"].get<std::string>(), " (", done["gaussians"].get<int64_t>(), " Gaussians, ",
               done["semantics"].is_null() ? std::string("no city objects")
                                           : cat(done["semantics"].get<size_t>(), " city objects"),
               ", ", done["queries"].size(), " queries, ",
               done["tiles"].is_null() ? std::string() : cat(done["tiles"].get<size_t>(), " tiles, "), "frame: ", done["frame"]["frame"].get<std::string>(), ")"));
  return 0;
}

}  // namespace cls
