// libFuzzer target for the CityJSON and CityJSONSeq readers. Every input must either parse or
// raise cls::Error; anything else (a crash, a sanitizer report, another exception) is a bug.
#include <cstddef>
#include <cstdint>
#include <string>

#include "citymodel/cityjson_reader.h"
#include "core/error.h"
#include "core/log.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const cls::Taxonomy taxonomy = [] {
    cls::set_log_level(cls::LogLevel::Quiet);
    return cls::Taxonomy::builtin();
  }();
  const std::string text(reinterpret_cast<const char*>(data), size);
  // The size picks the LoD, so LoD selection is fuzzed as well.
  const int lod = static_cast<int>(size % 4);
  try {
    if (cls::is_cityjson_seq(text))
      cls::parse_cityjson_seq(text, "fuzz.jsonl", taxonomy, lod);
    else
      cls::parse_cityjson(text, "fuzz.json", taxonomy, lod);
  } catch (const cls::Error&) {
  }
  return 0;
}
