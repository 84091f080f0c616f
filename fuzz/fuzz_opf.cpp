// libFuzzer target for OPF projects (scene/opf.h): the input is the project's files, in the order of
// kFiles, separated by kSeparator, written to a folder and read as a project (the seed,
// fuzz/corpus/opf/, is a consistent project of scripts/colmap_to_opf.py). Malformed input must end in
// a cls::Error; anything else is a finding.
#include <unistd.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

#include "core/error.h"
#include "scene/opf.h"

namespace {

constexpr std::string_view kSeparator = "\n@@next-file@@\n";
const char* const kFiles[] = {"project.opf",          "opf/camera_list.json",           "opf/input_cameras.json",
                              "opf/calibrated_cameras.json", "opf/scene_reference_frame.json", "opf/sparse.gltf",
                              "opf/positions.bin",    "opf/colors.bin"};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  namespace fs = std::filesystem;
  static const fs::path dir = fs::temp_directory_path() / ("fuzz_opf_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir / "opf");
  std::string_view rest(reinterpret_cast<const char*>(data), size);
  for (const char* name : kFiles) {
    const size_t end = rest.find(kSeparator);
    const std::string_view part = rest.substr(0, end);
    std::ofstream(dir / name, std::ios::binary).write(part.data(), static_cast<std::streamsize>(part.size()));
    if (end == std::string_view::npos) break;
    rest.remove_prefix(end + kSeparator.size());
  }
  try {
    const cls::OpfProject p = cls::read_opf_project((dir / "project.opf").string());
    for (const auto& point : p.points)
      for (double x : point.xyz)
        if (!std::isfinite(x)) std::abort();  // the reader promises finite tie points
  } catch (const cls::Error&) {
    // expected for malformed input
  }
  return 0;
}
