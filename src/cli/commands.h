#pragma once
// One function per subcommand; argv[0] is the subcommand name. Each returns the exit status.
namespace cls {
int cmd_citymodel(int argc, char** argv);   // citymodel stats | export
int cmd_raycast(int argc, char** argv);     // per-view label maps and coverage
int cmd_align(int argc, char** argv);       // refine the city transform (ICP)
int cmd_align_check(int argc, char** argv); // sparse points vs city mesh
int cmd_georef(int argc, char** argv);      // the city transform from the photos' GPS
int cmd_synth(int argc, char** argv);       // synthetic scenes
int cmd_scene(int argc, char** argv);       // scene info | convert
int cmd_run(int argc, char** argv);         // the whole pipeline
int cmd_models(int argc, char** argv);      // models list | download | check
int cmd_features(int argc, char** argv);    // per-view SAM and CityGML features
int cmd_autoencoder(int argc, char** argv); // train the shared autoencoder on SAM features
int cmd_train_rgb(int argc, char** argv);   // photometric 3DGS training
int cmd_train_language(int argc, char** argv);  // language field training (paper 3.3)
int cmd_query(int argc, char** argv);       // open-vocabulary text queries on a language model
int cmd_evaluate(int argc, char** argv);    // the paper's evaluation (section 4)
int cmd_render(int argc, char** argv);      // pictures and videos of a trained model
int cmd_report(int argc, char** argv);      // the HTML report of a run directory
int cmd_view(int argc, char** argv);        // the browser viewer with live text queries
int cmd_export(int argc, char** argv);      // glTF with KHR_gaussian_splatting and the city objects
int cmd_enrich(int argc, char** argv);      // the city model as CityJSON 2.0 with what the run learned
int cmd_changes(int argc, char** argv);     // openings the city model lacks, surfaces the photos contradict
int cmd_tile(int argc, char** argv);        // cut a district into tiles
int cmd_run_tiles(int argc, char** argv);   // every tile's pipeline on Slurm or locally
int cmd_tiles(int argc, char** argv);       // tiles status | task
int cmd_merge(int argc, char** argv);       // the tiles' models as one
}  // namespace cls
