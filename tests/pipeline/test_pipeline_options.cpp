// The options of `run` are declared once (pipeline_options()): every binding has its own name and JSON
// key, the CLI's help of `run` and `run-tiles` shows each exactly once with the default the struct gives,
// and run.json's settings go back into the same configuration. Every command's help declares each
// option once (Args refuses a second declaration).
#include <gtest/gtest.h>

#include <regex>
#include <set>
#include <sstream>

#include "cli_runner.h"
#include "core/error.h"
#include "models/temp_dir.h"
#include "pipeline/pipeline_config.h"
#include "tiles/tile_tasks.h"

using namespace cls;
using Binding = OptionList<PipelineConfig>::Binding;

namespace {

// The option names of a --help text ("  -r, --resolution VALUE" -> "resolution"), in order.
std::vector<std::string> option_names(const std::string& help) {
  std::vector<std::string> names;
  const std::regex line(R"(^  (?:-\w, )?--([a-z0-9-]+)(?: VALUE)?$)");
  std::istringstream in(help);
  for (std::string l; std::getline(in, l);) {
    std::smatch m;
    if (std::regex_match(l, m, line)) names.push_back(m[1]);
  }
  return names;
}

// What --help prints for a binding: its line, its help and its default.
std::string help_entry(const Binding& b, const PipelineConfig& defaults) {
  const std::string def = b.default_text.empty() ? b.text(defaults) : b.default_text;
  return (b.short_name.empty() ? "" : "-" + b.short_name + ", ") + "--" + b.name + (b.flag ? "" : " VALUE") +
         "\n      " + b.help +
         (b.flag || (def.empty() && b.help.find("default:") != std::string::npos) ? ""
          : def.empty()                                                          ? " (no default)"
                                                                                 : " (default: " + def + ")") +
         "\n";
}

size_t count(const std::string& text, const std::string& part) {
  size_t n = 0;
  for (size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++n;
  return n;
}

}  // namespace

TEST(PipelineOptions, EachOptionHasOneNameOneKeyAndAHelp) {
  std::set<std::string> names, keys, shorts;
  for (const Binding& b : pipeline_options().bindings()) {
    EXPECT_TRUE(names.insert(b.name).second) << b.name;
    EXPECT_TRUE(keys.insert(option_key(b.name)).second) << b.name;
    if (!b.short_name.empty()) {
      EXPECT_TRUE(shorts.insert(b.short_name).second) << b.short_name;
    }
    EXPECT_FALSE(b.help.empty()) << b.name;
  }
  EXPECT_GE(names.size(), 20u);
  // run.json's settings are the bindings' keys, and nothing else.
  const nlohmann::json j = pipeline_options().to_json(PipelineConfig{});
  EXPECT_EQ(j.size(), keys.size());
  for (const std::string& k : keys) EXPECT_TRUE(j.contains(k)) << k;
}

TEST(PipelineOptions, SettingsGoBackIntoTheSameConfiguration) {
  PipelineConfig c;
  c.scene_dir = "/data/scene";
  c.city_options.lod = 2;
  c.resolution = 4;
  c.align = "refine";
  c.features.models = "clip-tiny";
  c.features.clip = "/weights/clip.bin";
  c.alpha = 0.25;
  c.regions = "instance";
  c.rgb_iterations = 17;
  c.baselines = {};
  c.stop_after = "features";
  const nlohmann::json j = pipeline_options().to_json(c);
  EXPECT_EQ(j["lod"], 2);
  EXPECT_EQ(j["models"], "clip-tiny");
  EXPECT_EQ(j["baseline"], nlohmann::json::array());
  PipelineConfig back;
  pipeline_options().from_json(j, back, "run.json");
  EXPECT_EQ(pipeline_options().to_json(back), j);
  EXPECT_EQ(back.scene_dir, c.scene_dir);
  EXPECT_EQ(back.features.models, "clip-tiny");
  EXPECT_TRUE(back.baselines.empty());

  // A value the option refuses on the command line is refused from a file too, naming it.
  for (const auto& [key, value] : std::vector<std::pair<std::string, nlohmann::json>>{
           {"models", "real"}, {"align", "sometimes"}, {"baseline", {"langsplat", "other"}}, {"lod", 7},
           {"resolution", "four"}, {"resolution", 1.5}, {"no_such_option", 1}}) {
    try {
      pipeline_options().from_json({{key, value}}, back, "settings.json");
      ADD_FAILURE() << key << " accepted";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("settings.json"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
    }
  }
}

// --baseline lists each baseline once, in one order, whatever was written; none adds nothing.
TEST(PipelineOptions, BaselinesAreKeptOnceInOneOrder) {
  const auto parse = [](const std::string& text) {
    for (const Binding& b : pipeline_options().bindings())
      if (b.name == "baseline") {
        PipelineConfig c;
        b.parse(c, text);
        return c.baselines;
      }
    ADD_FAILURE() << "no --baseline";
    return std::vector<std::string>{};
  };
  EXPECT_EQ(parse("langsplat,langsplat-original,langsplat"), (std::vector<std::string>{"langsplat-original", "langsplat"}));
  EXPECT_EQ(parse("none,langsplat"), std::vector<std::string>{"langsplat"});
  EXPECT_TRUE(parse("none").empty());
  EXPECT_THROW(parse("langsplat,other"), std::invalid_argument);
}

// The sparse field has no decoder: LangSplat as published (its own autoencoder) cannot train in it, the
// LangSplat objective can; K must fit the codebook.
TEST(PipelineOptions, TheSparseFieldTakesTheBaselinesThatNeedNoAutoencoder) {
  PipelineConfig c;
  c.city = "model.gml";
  c.field = "sparse";
  try {
    c.validate();
    ADD_FAILURE() << "the default baseline langsplat-original was accepted with --field sparse";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("--baseline langsplat"), std::string::npos) << e.what();
  }
  c.baselines = {"langsplat"};
  EXPECT_NO_THROW(c.validate());
  c.top_k = c.codebook_size + 1;
  EXPECT_THROW(c.validate(), UsageError);
  c.top_k = 4;
  c.field = "other";
  EXPECT_THROW(c.validate(), UsageError);
}

// The shared autoencoder must exist from the step that reads it on; a run stopping before it (tiles
// stop after the features) does not need it yet.
TEST(PipelineOptions, TheAutoencoderMustExistOnlyWhereTheRunReadsIt) {
  PipelineConfig c;
  c.city = "model.gml";
  c.autoencoder = "/nonexistent/shared.safetensors";
  // The default baseline, the paper's, trains its own autoencoder: a given one needs the others.
  EXPECT_EQ(c.baselines, std::vector<std::string>{"langsplat-original"});
  c.stop_after = "labels";
  EXPECT_THROW(c.validate(), UsageError);
  c.baselines = {"langsplat"};
  for (const char* early : {"labels", "features"}) {
    c.stop_after = early;
    EXPECT_NO_THROW(c.validate()) << early;
  }
  for (const char* late : {"autoencoder", "train-rgb", "none"}) {
    c.stop_after = late;
    EXPECT_THROW(c.validate(), Error) << late;
  }
  c.stop_after = "merge";
  EXPECT_THROW(c.validate(), UsageError);
}

TEST(PipelineOptions, RunAndRunTilesHelpShowEveryOptionOnceWithTheDefaultOfTheStruct) {
  const auto run = test::run_cli("run --help");
  ASSERT_EQ(run.status, 0) << run.err;
  const auto tiles = test::run_cli("run-tiles --help");
  ASSERT_EQ(tiles.status, 0) << tiles.err;
  const PipelineConfig defaults;
  for (const Binding& b : pipeline_options().bindings()) {
    if (!b.positional.empty()) {
      EXPECT_EQ(count(run.out, "  " + b.positional + "\n      " + b.help + "\n"), 1u) << b.positional;
      continue;
    }
    EXPECT_EQ(count(run.out, "--" + b.name + (b.flag ? "\n" : " VALUE\n")), 1u) << b.name;
    EXPECT_EQ(count(run.out, help_entry(b, defaults)), 1u) << help_entry(b, defaults) << "\n--- in:\n" << run.out;
    // run-tiles carries every option that is not the scene's own, declared by the same binding.
    EXPECT_EQ(count(tiles.out, "--" + b.name + (b.flag ? "\n" : " VALUE\n")), b.per_scene ? 0u : 1u) << b.name;
    if (!b.per_scene) {
      EXPECT_EQ(count(tiles.out, help_entry(b, tile_pipeline_defaults())), 1u) << b.name;
    }
  }
  // The models' defaults come from one table (the provider registry), not from a help string.
  EXPECT_NE(run.out.find("0: the feature provider's (clip 30000, clip-tiny 100, synthetic 1500"), std::string::npos)
      << run.out;
}

TEST(CliOptions, EveryCommandsHelpDeclaresEachOptionOnce) {
  const auto top = test::run_cli("--help");
  ASSERT_EQ(top.status, 0) << top.err;
  std::vector<std::string> commands;
  const std::regex line(R"(^  ([a-z-]+) +\S.*$)");
  std::istringstream in(top.out);
  bool in_commands = false;
  for (std::string l; std::getline(in, l);) {
    if (l == "commands:") in_commands = true;
    else if (l.empty()) in_commands = false;
    std::smatch m;
    if (in_commands && std::regex_match(l, m, line)) commands.push_back(m[1]);
  }
  ASSERT_GE(commands.size(), 20u) << top.out;
  for (const std::string& command : commands) {
    const auto help = test::run_cli(command + " --help");
    EXPECT_EQ(help.status, 0) << command << ": " << help.err;
    const std::vector<std::string> names = option_names(help.out);
    EXPECT_EQ(std::set<std::string>(names.begin(), names.end()).size(), names.size()) << command;
  }
}
